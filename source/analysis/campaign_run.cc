// The whole campaign from its manifest (campaign_run.h).
#include "fiberbridge/analysis/campaign_run.h"

#include "fiberbridge/core/error.h"

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
