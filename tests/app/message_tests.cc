// Messages and numeric checks of the command line and the scene reader (issues 40 item 7 and 42
// item 6): each input the fuzzer found passing, or failing with a misleading or garbled message,
// is refused with one line naming the option or key, the value and what was expected.
#include "fiberbridge/app/cli/commands.h"
#include "fiberbridge/app/scene/scene_reader.h"
#include "fiberbridge/core/error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace fiberbridge;

namespace {

std::string work_dir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("fb_messages_" + name);
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d.string();
}

std::string scene_file(const std::string& name, const std::string& body,
                       const std::string& run = "beam") {
  const std::string d = work_dir(name);
  const std::string path = d + "/scene.prm";
  std::ofstream(path) << "set Output directory = " << d << "/out\nset Run = " << run << "\n"
                      << body;
  return path;
}

/// The command's exit code and what it wrote on stderr.
std::pair<int, std::string> run(const std::vector<std::string>& args) {
  testing::internal::CaptureStderr();
  const int rc = app::run_command_line(args, 0);
  return {rc, testing::internal::GetCapturedStderr()};
}

std::string scene_error(const std::string& prm, const std::vector<std::string>& set = {}) {
  try {
    app::read_scene_parameters(prm, set);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

} // namespace

// dic --initial-crack nan, inf, -5 and 0 exited 0 with that value in every a_mm.
TEST(CommandMessages, DicInitialCrackMustBeAFinitePositiveLength) {
  const std::string d = work_dir("dic_a0");
  for (const char* a0 : {"nan", "inf", "-5", "0"}) {
    const auto [rc, err] = run({"dic", d + "/f_1.csv", "--record", d + "/machine.csv",
                                "--initial-crack", a0, "--out", d + "/out"});
    EXPECT_EQ(rc, 1) << a0;
    EXPECT_NE(err.find("--initial-crack"), std::string::npos) << a0 << ": " << err;
  }
}

// reduce --initial-crack nan wrote nan; --smoothing-window nan or -1 meant automatic and inf moved
// the plateau; --width 1e-300 gave R of 1e304.
TEST(CommandMessages, ReduceOptionsAreFiniteAndInTheirRange) {
  const std::string d = work_dir("reduce_options");
  const std::vector<std::vector<std::string>> bad = {
      {"--initial-crack", "nan"},    {"--smoothing-window", "nan"}, {"--smoothing-window", "-1"},
      {"--smoothing-window", "inf"}, {"--width", "1e-300"},         {"--arm-thickness", "inf"}};
  for (const auto& o : bad) {
    std::vector<std::string> args = {"reduce",          d + "/r.csv", "--width", "20",
                                     "--arm-thickness", "5",          "--out",   d + "/out"};
    args.insert(args.end(), o.begin(), o.end());
    const auto [rc, err] = run(args);
    EXPECT_EQ(rc, 1) << o[0] << " " << o[1];
    EXPECT_NE(err.find(o[0]), std::string::npos) << err;
  }
}

// "fiberbridge reduce: input error: fiberbridge reduce: ..." named the command twice.
TEST(CommandMessages, TheCommandIsNamedOnce) {
  const std::string d = work_dir("prefix");
  const auto [rc, err] = run({"reduce", d + "/r.csv", "--arm-thickness", "5", "--out", d});
  EXPECT_EQ(rc, 1);
  EXPECT_EQ(err.find("fiberbridge reduce"), err.rfind("fiberbridge reduce")) << err;
}

// An empty Output directory: "input error: : cannot create output directory".
TEST(SceneMessages, AnEmptyOutputDirectoryIsNamed) {
  const std::string d = work_dir("empty_out");
  const std::string prm = d + "/scene.prm";
  std::ofstream(prm) << "set Output directory =\nset Run = beam\n";
  const auto [rc, err] = run({"run", prm});
  EXPECT_NE(rc, 0);
  EXPECT_NE(err.find("Output directory is empty"), std::string::npos) << err;
}

// --set passes on deal.II's reason instead of "unknown key or value not allowed for it".
TEST(SceneMessages, SetSaysWhyAValueIsRefused) {
  const std::string e = scene_error(scene_file("set_reason", ""), {"Specimen/Width=wide"});
  EXPECT_NE(e.find("Specimen/Width=wide"), std::string::npos) << e;
  EXPECT_NE(e.find("wide"), e.rfind("Specimen/Width=wide")) << e; // the reason quotes it again
  EXPECT_EQ(e.find("unknown key or value not allowed"), std::string::npos) << e;
}

// A substring of the item list ("ank" of "rank") was "not available in this build".
TEST(SceneMessages, AnUnknownItemIsCalledUnknown) {
  const std::string e = scene_error(scene_file("unknown_item", "", "ank"));
  EXPECT_NE(e.find("unknown Run item 'ank'"), std::string::npos) << e;
}

// A subnormal Double printed deal.II's internal error with a stack trace. (An overflowing 1e400 is
// refused by deal.II's own Double pattern before it reaches us, with its own message.)
TEST(SceneMessages, ASubnormalNumberNamesKeyAndValue) {
  for (const std::string v : {"1e-320", "4.9e-324"}) {
    const std::string e =
        scene_error(scene_file("subnormal", "subsection DIC\n  set Frame rate = " + v + "\nend\n"));
    EXPECT_NE(e.find("DIC/Frame rate = " + v), std::string::npos) << e;
    EXPECT_NE(e.find("expected"), std::string::npos) << e;
    EXPECT_EQ(e.find("An error occurred"), std::string::npos) << e;
  }
}
