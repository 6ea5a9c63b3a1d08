// A study's FEM virtual test (virtual_test_run.h).
#include "items/virtual_test_run.h"

#include "fiberbridge/app/run/scene_runner.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fiberbridge::app {

namespace {

std::string read_text(const std::string& path) {
  std::ifstream f(path);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

} // namespace

bool run_virtual_test(const SceneContext& ctx, const std::vector<std::string>& case_sets,
                      const std::string& dir, bool reuse) {
  std::vector<std::string> sets = ctx.parameters().overrides;
  sets.insert(sets.end(), case_sets.begin(), case_sets.end());
  sets.push_back("Run=fem");
  sets.push_back("Output directory=" + dir);
  sets.push_back("FEM/Virtual DIC/Enabled=true");
  // The stamp: everything the FEM read (the scene's text and the settings on top of it).
  std::string stamp = read_text(ctx.scene_file) + "\n";
  for (const auto& s : sets)
    stamp += s + "\n";
  const std::string stamp_file = dir + "/virtual_test_stamp.txt";
  if (reuse && std::filesystem::exists(dir + "/virtual_test/dic_scene.prm") &&
      read_text(stamp_file) == stamp)
    return false;
  std::filesystem::remove(stamp_file);
  run_scene(ctx.scene_file, sets, false, ctx.progress_sink);
  std::ofstream(stamp_file) << stamp;
  return true;
}

} // namespace fiberbridge::app
