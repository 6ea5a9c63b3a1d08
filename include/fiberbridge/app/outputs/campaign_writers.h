#pragma once
// The campaign's outputs (issue 33 item 4), written from a finished analysis::CampaignResult:
// campaign_table1.csv (seed_table1.csv's format with interval columns), campaign_table1_values.csv
// (the same without them: `fiberbridge rank` reads it), per-group and per-specimen tables, the
// degradation and ranking tables, each group's law with its band and as LS-DYNA / Abaqus input,
// gnuplot PNGs, campaign_report.html and the summary block `campaign`. Nothing is computed here.
#include "fiberbridge/analysis/campaign_run.h"
#include "fiberbridge/app/scene/item_outcome.h"
#include "fiberbridge/app/scene/step_outcomes.h"

#include <string>

namespace fiberbridge::app {

struct CampaignWriteOptions {
  bool fe_export = true; ///< LS-DYNA and Abaqus cards per group with a law
  double seconds = 0;    ///< wall time of the analysis (for the report)
  /// The laws back in the specimen (empty when not simulated) and their PNGs, for the tables,
  /// the report and the summary.
  std::vector<GroupSimulation> simulations;
  std::vector<std::string> simulation_pngs;
};

/// summary.json's `campaign` block of `r` (the groups with their intervals, degradation, ranking
/// and its confidence).
Json campaign_summary_block(const analysis::CampaignResult& r, const CampaignWriteOptions& w);

void write_campaign_outputs(const analysis::CampaignResult& r, const CampaignWriteOptions& w,
                            const std::string& out_dir, ItemReport& report);

} // namespace fiberbridge::app
