#pragma once
// The files, plots and summary block of `compare` (analysis/model_comparison.h computes them).
#include "fiberbridge/analysis/model_comparison.h"
#include "fiberbridge/app/scene/item_outcome.h"

#include <string>
#include <vector>

namespace fiberbridge::app {

/// compare.csv (every pair's differences), compare_R_a.png, compare_load.png and
/// compare_delta_root.png on shared axes (from each model's rcurve_<model>.csv), and, with the
/// closed loop, closed_loop.csv, closed_loop_laws_<model>.csv and closed_loop_<model>.png; the
/// summary's `compare` block. A model whose loop could not run is named with why, and warned of.
void write_comparison(const analysis::ModelComparison& c,
                      const std::vector<const result::SimulationResult*>& models,
                      const law::TractionLaw& law, double j_tip, const std::string& out_dir,
                      ItemReport& report);

} // namespace fiberbridge::app
