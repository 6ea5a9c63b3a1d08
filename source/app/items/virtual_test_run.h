#pragma once
// One FEM virtual test (FEM/Virtual DIC) made from a study's own scene file, for `chain study`
// and `programme study`: the scene with its --set settings, the case's settings, `Run = fem` and
// the output directory, through the scene runner as `fiberbridge run --set ...` would run it.
#include "fiberbridge/app/scene/scene_context.h"

#include <string>
#include <vector>

namespace fiberbridge::app {

/// Runs the virtual test into `dir` (its frames, machine.csv, virtual_test_truth.csv and
/// dic_scene.prm in `dir`/virtual_test) unless `reuse` and an earlier run left one there made
/// from the same scene text and settings (dir/virtual_test_stamp.txt): the FEM is the slow part
/// of a study and does not change when the measuring chain does. Returns true when the FEM ran.
/// Throws what the scene runner throws.
bool run_virtual_test(const SceneContext& ctx, const std::vector<std::string>& case_sets,
                      const std::string& dir, bool reuse);

} // namespace fiberbridge::app
