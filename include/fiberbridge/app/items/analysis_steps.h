#pragma once
// The analysis chain as steps shared by the command line (extract, rank) and the scene items
// (extract, fit, rank, bridging): one implementation, two front ends.
#include "fiberbridge/analysis/law_extraction.h"
#include "fiberbridge/app/scene/item_outcome.h"

#include <memory>
#include <string>

namespace fiberbridge::app {

// The computations and their options live in analysis (analysis/law_extraction.h); the writers in
// outputs/ (extraction_writers.h, ranking_writers.h). These steps join the two for the command
// line and the scene items.
using analysis::ExtractionOptions;
using analysis::ExtractionOutcome;
using analysis::FitOptions;
using analysis::RankOptions;

/// Reads (or takes o.data), averages, finds the steady state, extracts Eq. 6 and R' laws; writes
/// rdelta_averaged.csv, cohesive_law_eq5.csv, cohesive_law_dRdd.csv; adds the top-level keys of
/// docs/design.md section 5 to `summary` (J_tip_J_m2, G_ss_J_m2, delta_c_mm, peak_sigma_eq5_kPa,
/// peak_sigma_dRdd_kPa, extract{}).
ExtractionOutcome run_extraction(const ExtractionOptions& o, const std::string& out_dir,
                                 ItemReport& report);

/// Trilinear fit of the Eq. 6 law with area G_ss - J_tip; writes trilinear_fit.csv and the
/// summary's `trilinear` block (the plots: plot_extraction, outputs/extraction_writers.h).
analysis::TrilinearFit run_trilinear_fit(const ExtractionOutcome& e, const FitOptions& o,
                                         const std::string& out_dir, ItemReport& report);

/// Degradation statistics, ranking and consistency check; writes degradation.csv, ranking.csv,
/// PNGs per material; adds `ranking`, `degradation`, `consistency` to summary.
void run_ranking(const RankOptions& o, const std::string& out_dir, ItemReport& report);

} // namespace fiberbridge::app
