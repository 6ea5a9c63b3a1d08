#pragma once
// The files, plots and summary keys of extract and fit (analysis/law_extraction.h computes them).
#include "fiberbridge/analysis/law_extraction.h"
#include "fiberbridge/app/scene/item_outcome.h"
#include "fiberbridge/law/piecewise_linear_law.h"

#include <string>

namespace fiberbridge::app {

/// rdelta_averaged.csv, cohesive_law_eq5.csv, cohesive_law_dRdd.csv; the top-level keys of
/// docs/design.md section 5 (J_tip_J_m2, G_ss_J_m2, delta_c_mm, peak_sigma_eq5_kPa,
/// peak_sigma_dRdd_kPa) and the `extract` block.
void write_extraction(const analysis::ExtractionOutcome& e, const analysis::ExtractionOptions& o,
                      const std::string& out_dir, ItemReport& report);

/// A trilinear law's summary keys, in the tables' units: delta1_mm, sigma1_kPa, delta2_mm,
/// sigma2_kPa, delta_c_mm, J1_J_m2, J2_J_m2 (the `trilinear` block's and the correction's).
Json trilinear_json(const law::TrilinearParameters& t);

/// trilinear_fit.csv and the summary's `trilinear` block.
void write_trilinear_fit(const analysis::TrilinearFit& fit, const std::string& out_dir,
                         ItemReport& report);

/// rdelta.png (the averaged R(delta), with the fitted law's Eq. 2 forward curve in
/// rdelta_fit_forward.csv when `fit`) and cohesive_law.png (the Eq. 6 and R' laws, the fit, and
/// when `corrected` the law corrected by simulation, trilinear_fit_corrected.csv).
void plot_extraction(const analysis::ExtractionOutcome& e, const analysis::TrilinearFit* fit,
                     const std::string& out_dir, ItemReport& report, bool corrected = false);

} // namespace fiberbridge::app
