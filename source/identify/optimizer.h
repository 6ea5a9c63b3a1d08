#pragma once
// identify's optimizer (docs/design.md section 6, "identify"): NLopt's bounded derivative-free
// BOBYQA (or SBPLX) on the misfit, from several starts (one job each), then polished from the
// best point.
#include "jobs.h"

#include <functional>
#include <string>
#include <vector>

namespace fiberbridge::identify::detail {

/// The parameters of the smallest chi^2 the starts and polish rounds reach. Each optimizer run
/// appends a note (its NLopt stop, its chi^2) to `notes` and its forward-run counts to `counts`,
/// in the serial order.
Parameters optimize(const std::vector<PreparedRecord>& prepared, const IdentifySettings& settings,
                    const ForwardModel& forward,
                    const std::function<void(const std::string&)>& progress,
                    const IdentifyJobRunner& run_jobs, RunCounts& counts,
                    std::vector<std::string>& notes);

} // namespace fiberbridge::identify::detail
