// The whole campaign from its manifest (campaign_run.h).
#include "fiberbridge/analysis/campaign_run.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"

#include <algorithm>
#include <set>

namespace fiberbridge::analysis {

CampaignResult analyse_campaign(const CampaignManifest& manifest, const RawRecordOptions& raw,
                                const CampaignOptions& options,
                                const std::vector<std::string>& reference_materials,
                                const CampaignProgress& progress, const GroupRunner& runner) {
  if (options.bootstrap_samples < 0)
    throw InputError("Campaign/Bootstrap samples: must be >= 0");
  if (!(options.confidence > 0 && options.confidence < 1))
    throw InputError("Campaign/Confidence level: must lie in (0, 1)");
  CampaignResult r;
  r.estimator = raw.estimator;
  r.manifest = manifest;
  r.options = options;
  r.reference_materials = reference_materials;
  for (const auto& row : manifest.rows) {
    r.specimens.push_back(load_campaign_specimen(row, raw));
    assess_campaign_specimen(r.specimens.back(), options);
  }
  r.groups = make_campaign_groups(r.specimens);
  if (runner)
    runner(r.groups, r.specimens, options, progress);
  else
    for (std::size_t i = 0; i < r.groups.size(); ++i) {
      analyse_campaign_group(r.groups[i], r.specimens, options);
      if (progress)
        progress(i + 1, r.groups.size(), r.groups[i]);
    }
  // A campaign with no estimate at all has no Table 1, laws or ranking: that is a failed run,
  // not a result (issue 42: delta_c_mm written in micrometres exited 0 with an empty table).
  if (!r.groups.empty() &&
      std::none_of(r.groups.begin(), r.groups.end(), [](const auto& g) { return g.estimate.ok; })) {
    std::string why;
    for (std::size_t i = 0; i < r.groups.size() && i < 3; ++i)
      why += (i ? "; " : "") + r.groups[i].material + " at " + fmt(r.groups[i].cycles) +
             " cycles: " + r.groups[i].estimate.failure;
    throw ComputationError(manifest.source + ": no group of the campaign could be estimated (" +
                           why + (r.groups.size() > 3 ? "; ..." : "") +
                           "); check the manifest's per-specimen columns (delta_c_mm in mm, "
                           "j_tip_J_m2 in J/m^2) and the specimens' files");
  }
  std::set<std::string> materials;
  for (const auto& g : r.groups)
    materials.insert(g.material);
  for (const auto& m : reference_materials)
    if (!materials.count(m))
      r.notes.push_back("reference material '" + m + "' is not in the manifest");
  r.degradation = campaign_degradation(r.groups, options.confidence);
  r.ranking = campaign_ranking(r.groups, reference_materials);
  return r;
}

} // namespace fiberbridge::analysis
