#pragma once
// The tables, plot and summary block of `study` (item_study.cc), apart from its runs and their
// analysis (docs/design.md section 4, "Parse once and writers apart"): run_study_item runs the
// levels and cases, analyses the ladders, then hands the outcomes to these.
#include "fiberbridge/app/scene/scene_context.h"
#include "fiberbridge/result/rcurve.h"

#include <string>
#include <vector>

namespace fiberbridge::app {

/// One level of a refinement ladder, run and analysed.
struct LadderLevel {
  std::string setting;  ///< "Key = value; ..." of the level
  double key_value = 0; ///< the first varied key's value (its ratio is the refinement factor)
  result::SimulationResult r;
  double g_err = 0; ///< |G_ss - (J_tip + law area)| / (J_tip + law area)
  double peak = 0;  ///< [N] the largest finite load of the R curve
  int rank = 0;     ///< the rank that ran it, and its CPU seconds there
  double cpu_s = 0;
  /// Observed orders from this level and the next (the next two for the peak load);
  /// result::not_available where there are not enough levels or the errors do not shrink.
  double order_rdelta = result::not_available, order_G_ss = result::not_available,
         order_peak = result::not_available;
};

/// A model's ladder: its levels coarse to fine and the cheapest one within the target error.
struct LadderOutcome {
  std::string model;
  std::vector<LadderLevel> levels;
  double target = 0; ///< the Study's target error for the model
  int cheapest = -1; ///< -1: no level reached the target
};

/// study_error_vs_time.csv, study_<model>.csv, study_error_vs_time.png, and in `block` the law's
/// and specimen's sources, cheapest (per model) and error_vs_time.
void write_study_ladders(const SceneContext& ctx, const std::vector<LadderOutcome>& ladders,
                         Json& block, ItemReport& report);

/// stability.csv and block["stability"] from the cases' rows (case, description, model,
/// outcome, diagnosis, wall_time_s, steady_state_status, rank, cpu_s).
void write_study_stability(const SceneContext& ctx, const std::vector<Json>& rows, Json& block);

} // namespace fiberbridge::app
