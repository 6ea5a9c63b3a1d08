// The campaign's outputs (campaign_writers.h): tables, law files, plots, the HTML report and the
// summary block, all from a finished CampaignResult. Every file goes through the atomic core
// writers (a killed run leaves no half-written table; rank > 0 writes nothing).
#include "fiberbridge/app/outputs/campaign_writers.h"

#include "fiberbridge/app/outputs/campaign_simulation_writers.h"
#include "outputs/campaign_out.h"

namespace fiberbridge::app {

using analysis::CampaignResult;

Json campaign_summary_block(const CampaignResult& r, const CampaignWriteOptions& w) {
  return campaign_out::summary_block(r, w);
}

void write_campaign_outputs(const CampaignResult& r, const CampaignWriteOptions& w,
                            const std::string& out_dir, ItemReport& report) {
  campaign_out::write_table1(r, out_dir);
  campaign_out::write_groups_table(r, out_dir);
  campaign_out::write_specimens_table(r, out_dir);
  campaign_out::write_statistics_tables(r, out_dir);
  std::vector<std::string> files{"campaign_table1.csv",
                                 "campaign_table1_values.csv",
                                 "campaign_groups.csv",
                                 "campaign_specimens.csv",
                                 "campaign_degradation.csv",
                                 "campaign_ranking.csv",
                                 "campaign_ranking_confidence.csv"};
  for (const auto& f : campaign_out::write_group_laws(r, w.fe_export, out_dir))
    files.push_back(f);
  campaign_out::write_degradation_by_material(r, out_dir);
  auto pngs = campaign_out::write_plots(r, out_dir);
  for (const auto& p : w.simulation_pngs)
    pngs.push_back(p);
  campaign_out::write_html(r, w, pngs, files, out_dir);
  report["campaign"] = campaign_summary_block(r, w);
  add_campaign_simulation_summary(r, w.simulations, report);
  for (const auto& p : pngs)
    report.plots.push_back(p);
}

} // namespace fiberbridge::app
