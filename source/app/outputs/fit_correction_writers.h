#pragma once
// The files and summary blocks of the fit's correction by simulation (items/fit_correction_step.h,
// identify/chain_correction.h), apart from its computing.
#include "fiberbridge/app/scene/item_outcome.h"
#include "fiberbridge/identify/chain_correction.h"

#include <string>

namespace fiberbridge::app {

/// fit_correction.csv (each simulation: the law simulated and what the chain gave on it), and when
/// the correction converged trilinear_fit_corrected.csv; summary blocks `fit_correction` (always)
/// and `trilinear_corrected` (when converged, the `trilinear` keys and J_tip_J_m2).
void write_fit_correction(const identify::ChainCorrection& c, const std::string& out_dir,
                          ItemReport& report);

} // namespace fiberbridge::app
