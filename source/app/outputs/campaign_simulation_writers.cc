#include "fiberbridge/app/outputs/campaign_simulation_writers.h"

#include "fiberbridge/analysis/campaign.h"
#include "fiberbridge/analysis/line_fit.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/plot.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <cmath>

namespace fiberbridge::app {

using units::mm;

void add_campaign_simulation_summary(const analysis::CampaignResult& r,
                                     const std::vector<GroupSimulation>& sims, ItemReport& report) {
  auto& groups = report["campaign"]["groups"];
  for (const auto& s : sims)
    for (std::size_t i = 0; i < r.groups.size(); ++i)
      if (r.groups[i].material == s.material && r.groups[i].cycles == s.cycles)
        groups[i]["simulation"] = {
            {"model", s.model},
            {"ran", s.ran},
            {"failure", s.failure},
            {"G_ss_J_m2", json_number(s.G_ss)},
            {"misfit_rel_to_G_B", json_number(s.misfit_rel)},
            {"fraction_within_2_std", json_number(s.within_scatter)},
            {"wall_time_s", json_number(s.wall_time_s)},
            {"specimen",
             {{"width_mm", json_number(s.specimen.width / mm)},
              {"arm_thickness_mm", json_number(s.specimen.arm_thickness() / mm)},
              {"a0_mm", json_number(s.specimen.initial_crack / mm)},
              {"length_mm", json_number(s.specimen.length / mm)}}},
            {"a_start_mm", json_number(s.a_start / mm)},
            {"geometry_note", s.geometry_note}};
}

std::vector<std::string> write_campaign_simulation_files(const analysis::CampaignResult& r,
                                                         const std::vector<GroupSimulation>& sims,
                                                         const std::string& out_dir) {
  std::vector<std::string> pngs;
  for (const auto& s : sims) {
    const analysis::CampaignGroup* g = nullptr;
    for (const auto& gg : r.groups)
      if (gg.material == s.material && gg.cycles == s.cycles)
        g = &gg;
    if (!g || !s.ran)
      continue;
    const auto& c = g->estimate.curve;
    CsvWriter w(
        out_dir + "/campaign_fig10_" + analysis::group_file_stem(s.material, s.cycles) + ".csv",
        {"delta_mm", "R_measured_J_m2", "R_std_J_m2", "R_simulated_J_m2"},
        {s.material + " after " + fmt(s.cycles) +
             " cycles: the group's averaged R(delta) "
             "and its scatter (standard deviation over the specimens) against the " +
             s.model + " simulation of the group's trilinear law (R_energy)",
         "simulated specimen: width " + fmt(s.specimen.width / mm) + " mm, arm thickness " +
             fmt(s.specimen.arm_thickness() / mm) + " mm, a0 " +
             fmt(s.specimen.initial_crack / mm) + " mm, length " + fmt(s.specimen.length / mm) +
             " mm" + (s.geometry_note.empty() ? "" : " (" + s.geometry_note + ")")});
    for (std::size_t i = 0; i < c.delta.size(); ++i)
      w.row({c.delta[i] / mm, c.R[i], c.R_std[i],
             analysis::interpolate_within(s.delta_root, s.R, c.delta[i])});
    w.close();
  }
  // One PNG per material: measured (band of 2 std) and simulated for every cycle count.
  std::vector<std::string> materials;
  for (const auto& s : sims)
    if (s.ran && std::find(materials.begin(), materials.end(), s.material) == materials.end())
      materials.push_back(s.material);
  for (const auto& m : materials) {
    const std::string s0 = analysis::group_file_stem(m, 0);
    const std::string png = "campaign_fig10_" + s0.substr(0, s0.size() - 3) + ".png";
    std::string p = gnuplot_png_preamble(png, 1000, 620);
    p += "set title '" + m + ": measured R(delta) (+-2 std over specimens) and the " +
         sims.front().model +
         " simulation of each group law'\nset xlabel 'notch-root opening delta (mm)'\n"
         "set ylabel 'R (J/m^2)'\nset key bottom right\nset style fill transparent solid 0.2 "
         "noborder\nplot ";
    int k = 0;
    for (const auto& s : sims) {
      if (s.material != m || !s.ran)
        continue;
      const std::string csv =
          "campaign_fig10_" + analysis::group_file_stem(s.material, s.cycles) + ".csv";
      const std::string lc = " lc " + std::to_string(k + 1);
      p += std::string(k ? ", " : "") + "'" + csv + "' using 1:($2-2*$3):($2+2*$3) with " +
           "filledcurves" + lc + " notitle, '" + csv + "' using 1:2 with lines lw 1" + lc +
           " title '" + fmt(s.cycles) + " cycles measured', '" + csv +
           "' using 1:4 with lines lw 2 dt 2" + lc + " title 'simulated'";
      ++k;
    }
    p += "\n";
    if (run_gnuplot(out_dir, p))
      pngs.push_back(png);
  }
  return pngs;
}

} // namespace fiberbridge::app
