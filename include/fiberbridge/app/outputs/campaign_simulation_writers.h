#pragma once
// The campaign's laws back in the specimen, written (the paper's Fig. 10): the simulated R(delta)
// of each group beside its measured curve, and each group's simulation block in the summary.
#include "fiberbridge/analysis/campaign_run.h"
#include "fiberbridge/app/scene/item_outcome.h"
#include "fiberbridge/app/scene/step_outcomes.h"

#include <string>
#include <vector>

namespace fiberbridge::app {

/// Writes campaign_fig10_<material>_c<cycles>.csv per simulated group and a PNG per material
/// (every cycle count: measured with +-2 std, simulated); returns the PNGs made.
std::vector<std::string> write_campaign_simulation_files(const analysis::CampaignResult& r,
                                                         const std::vector<GroupSimulation>& sims,
                                                         const std::string& out_dir);
/// campaign.groups[i].simulation in the summary (after write_campaign_outputs made the block).
void add_campaign_simulation_summary(const analysis::CampaignResult& r,
                                     const std::vector<GroupSimulation>& sims, ItemReport& report);

} // namespace fiberbridge::app
