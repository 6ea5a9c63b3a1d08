#pragma once
// Running a .prm scene (docs/design.md section 5): read it (scene/scene_reader.h), check every
// listed item's sections, then run only the items listed in `Run`, in the registry's order.
#include <string>
#include <vector>

namespace fiberbridge::app {

/// Runs the scene; returns the output directory. Throws InputError/ComputationError. With
/// `resume`, work an earlier run into the same output directory finished is restored and
/// checkpoints are continued (resume_store.h); without, that state is removed first.
std::string run_scene(const std::string& prm_file, const std::vector<std::string>& overrides,
                      bool resume = false);

} // namespace fiberbridge::app
