#pragma once
// What every simulation item writes of its result (outputs/report_simulation.cc).
#include "fiberbridge/app/scene/scene_context.h"
#include "fiberbridge/result/rcurve.h"

#include <string>

namespace fiberbridge::app {

/// Common writer for a simulation item: rcurve_<model>.csv, the summary block (docs/design.md
/// section 5: G_ss_J_m2, wall_time_s, n_dofs or n_particles, rdelta_rel_error_vs_eq2, notes) and an
/// R(a) PNG. Every simulation item calls this once with its result, and returns the outcome it
/// makes: the result and this report.
ItemOutcome
report_simulation(const SceneContext& ctx, result::SimulationResult result,
                  const std::string& size_key /* "n_dofs" or "n_particles" or "n_elements" */);

} // namespace fiberbridge::app
