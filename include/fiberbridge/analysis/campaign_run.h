#pragma once
// The whole campaign from its manifest (campaign.h, campaign_statistics.h): every specimen
// loaded and assessed, the groups with their bootstraps, the degradation and the ranking. No
// file is written here (the app's campaign writers write from the result).
#include "fiberbridge/analysis/campaign.h"
#include "fiberbridge/analysis/campaign_statistics.h"

#include <functional>
#include <string>
#include <vector>

namespace fiberbridge::analysis {

struct CampaignResult {
  CampaignManifest manifest;
  CampaignOptions options;
  std::vector<std::string> reference_materials;
  std::vector<CampaignSpecimen> specimens;
  RaMethod estimator = RaMethod::energy; ///< of R(a)-only specimens (RawRecordOptions)
  std::vector<CampaignGroup> groups;
  std::vector<CampaignDegradation> degradation;
  CampaignRanking ranking;
  std::vector<std::string> notes; ///< the campaign's own (the groups' are in each group)
};

/// Called after each group: (groups done, groups in all, the group just finished).
using CampaignProgress = std::function<void(std::size_t, std::size_t, const CampaignGroup&)>;

/// Runs one group's analysis: `analyse_group(i)` must fill groups[i] (analyse_campaign_group);
/// the default runs them in order on this process. A distributed caller passes its own (every
/// group's result depends only on its specimens, the options and its own seed, so any order or
/// placement gives the same numbers).
using GroupRunner =
    std::function<void(std::vector<CampaignGroup>&, const std::vector<CampaignSpecimen>&,
                       const CampaignOptions&, const CampaignProgress&)>;

CampaignResult analyse_campaign(const CampaignManifest& manifest, const RawRecordOptions& raw,
                                const CampaignOptions& options,
                                const std::vector<std::string>& reference_materials,
                                const CampaignProgress& progress = {},
                                const GroupRunner& runner = {});

} // namespace fiberbridge::analysis
