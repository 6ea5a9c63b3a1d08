#pragma once
// identify's uncertainties (docs/design.md section 6, "identify"): the Jacobian of the weighted
// residuals at the optimum by central differences (its columns are independent jobs), the
// parameter covariance, the correlations that the records cannot separate, J_c's standard error
// and the law's one-standard-error band.
#include "jobs.h"

namespace fiberbridge::identify::detail {

/// Runs the Jacobian's jobs at `best` and fills `out`: the records' fits at the optimum, chi2,
/// n_residuals, law, j_tip, g_ss, parameters with their standard errors, correlation, j_c's
/// standard error, the band, and notes on unidentifiable combinations. Adds the jobs' forward-run
/// counts to `counts`.
void estimate_uncertainty(const std::vector<PreparedRecord>& prepared,
                          const IdentifySettings& settings, const ForwardModel& forward,
                          const Parameters& best, const IdentifyJobRunner& run_jobs,
                          RunCounts& counts, Identification& out);

} // namespace fiberbridge::identify::detail
