// libFuzzer target: the scene reader (app/scene/scene_reader.cc read_scene_parameters: deal.II
// ParameterHandler with every section declared, unknown keys rejected, every section parsed once)
// with `--set` overrides, then the sections every simulation reads (Cohesive law, Specimen,
// Material). Input: a scene file; each line that starts
// with "#--set " (a comment to deal.II, so bundled scenes are valid inputs as they are) adds the
// rest of the line as one --set override.
#include "fiberbridge/app/scene/scene_context.h"
#include "fiberbridge/app/scene/scene_reader.h"
#include "fuzz_input.h"

#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fiberbridge;
  const std::string text = fuzz::as_text(data, size);
  std::vector<std::string> overrides;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("#--set ", 0) == 0)
      overrides.push_back(line.substr(7));
  fuzz::expect_success_or_input_error([&] {
    app::SceneContext ctx;
    ctx.params = app::read_scene_parameters(fuzz::as_file(text, ".prm"), overrides);
    ctx.scene_file = "fuzz.prm";
    fuzz::expect_success_or_input_error([&] { (void)ctx.law(); });
    fuzz::expect_success_or_input_error([&] { (void)ctx.specimen(); });
    fuzz::expect_success_or_input_error([&] { (void)ctx.material(); });
  });
  return 0;
}
