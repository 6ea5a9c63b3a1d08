#pragma once
// A campaign's degradation with cycles and its durability ranking (seed section 3.3), each with
// what the replicates say about it: the paper's rule (R^2 >= 0.8 on the group means,
// degradation.h) beside the bootstrap over whole specimens (campaign.h).
#include "fiberbridge/analysis/campaign.h"
#include "fiberbridge/analysis/degradation.h"

#include <string>
#include <vector>

namespace fiberbridge::analysis {

/// The q-quantile of the finite values of v (linear between order statistics, "type 7"); NaN
/// when none is finite. The campaign's bootstrap intervals and degradation slopes use it.
double sample_quantile(std::vector<double> v, double q);

/// The Table 1 properties a campaign regresses, as named in data/reference/seed_table1.csv:
/// sigma1 [kPa], J1 [J/m^2], sigma2 [kPa], J2 [J/m^2], lb [mm].
const std::vector<std::string>& campaign_table_properties();

/// The groups' values as a property table (the format degradation.h reads): one row per
/// (material, property) with at least one finite value, cycles = every cycle count of the groups.
/// `sample` < 0: the point estimates; else the bootstrap sample of that index in every group (a
/// group without samples gives its point estimate). Materials not in `materials` (when
/// non-empty) are left out.
PropertyTable campaign_property_table(const std::vector<CampaignGroup>& groups, int sample,
                                      const std::vector<std::string>& materials = {});

/// One property of one material against cycles.
struct CampaignDegradation {
  std::string material, property;
  std::vector<double> cycles, values; ///< the group point estimates (table units)
  bool has_slope = false;             ///< at least 3 cycle counts with a value
  std::string note;                   ///< why there is no slope / no interval
  DegradationRow paper;               ///< the paper's rule on the group means (has_slope)
  Interval slope_ci;                  ///< bootstrap percentile interval of the slope [1/cycle]
  double p_value = NAN; ///< bootstrap two-sided p of "slope = 0" (floored at 1/(samples+1))
  int samples_used = 0; ///< bootstrap samples with a slope
};

/// Degradation of every property of every material with at least 3 cycle counts; materials with
/// fewer are reported with has_slope = false and the note saying so.
std::vector<CampaignDegradation> campaign_degradation(const std::vector<CampaignGroup>& groups,
                                                      double confidence);

/// How often one material ranks ahead of another over the bootstrap.
struct PairConfidence {
  std::string first, second; ///< `first` ranks ahead in the point estimate's ranking
  double p_first_ahead = NAN, p_tie = NAN, p_second_ahead = NAN;
};

struct CampaignRanking {
  std::vector<MaterialRank> ranks;     ///< the paper's rule on the group means
  std::vector<std::string> reference;  ///< reported beside, not ranked (solid wood)
  std::vector<std::string> not_ranked; ///< materials without 3 cycle counts
  std::vector<PairConfidence> pairs;   ///< every pair of ranked materials
  int samples = 0;                     ///< bootstrap samples used
  std::vector<std::string> notes;
};

/// The paper's ranking (degradation.h rank_materials) of the non-reference materials with at
/// least 3 cycle counts, and over every bootstrap sample the same rule on that sample's values.
CampaignRanking campaign_ranking(const std::vector<CampaignGroup>& groups,
                                 const std::vector<std::string>& reference_materials);

} // namespace fiberbridge::analysis
