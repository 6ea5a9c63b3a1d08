// The campaign's PNGs.
#include "outputs/campaign_out.h"

#include "fiberbridge/core/format.h"
#include "fiberbridge/core/plot.h"
#include "fiberbridge/core/units.h"

#include <cmath>

namespace fiberbridge::app::campaign_out {

using units::kPa;
using units::mm;

std::vector<std::string> write_plots(const CampaignResult& r, const std::string& dir) {
  std::vector<std::string> pngs;
  const std::string level = fmt(100 * r.options.confidence) + " %";
  auto law_plot = [&](const std::string& png, const std::string& title,
                      const std::vector<const CampaignGroup*>& groups, bool label_material) {
    std::string s = gnuplot_png_preamble(png, 1000, 620);
    s += "set title '" + title +
         "'\nset xlabel 'opening delta (mm)'\nset ylabel 'sigma (kPa)'\n"
         "set key top right\nset style fill transparent solid 0.2 noborder\nplot ";
    int k = 0;
    for (const auto* g : groups) {
      const std::string csv = "campaign_law_" + group_stem(*g) + ".csv";
      const std::string name = label_material ? g->material : fmt(g->cycles) + " cycles";
      const std::string lc = " lc " + std::to_string(k + 1);
      if (k)
        s += ", ";
      if (g->has_interval())
        s += "'" + csv + "' using 1:5:6 with filledcurves" + lc + " notitle, ";
      s += "'" + csv + "' using 1:2 with lines lw 2" + lc + " title '" + name + "'";
      ++k;
    }
    s += "\n";
    if (k && run_gnuplot(dir, s))
      pngs.push_back(png);
  };
  for (const auto& mat : materials_of(r)) {
    std::vector<const CampaignGroup*> gs;
    for (const auto& g : r.groups)
      if (g.material == mat && g.estimate.ok && g.estimate.has_law)
        gs.push_back(&g);
    law_plot("campaign_laws_" + file_name_part(mat) + ".png",
             mat + ": laws by Eq. 6 after each cycle count, " + level + " bootstrap bands", gs,
             false);
  }
  {
    std::vector<const CampaignGroup*> gs;
    for (const auto& mat : materials_of(r)) {
      const CampaignGroup* first = nullptr;
      for (const auto& g : r.groups)
        if (g.material == mat && g.estimate.ok && g.estimate.has_law &&
            (!first || g.cycles < first->cycles))
          first = &g;
      if (first)
        gs.push_back(first);
    }
    law_plot("campaign_control_laws.png",
             "Laws of every material at its fewest cycles (controls), " + level + " bands", gs,
             true);
  }
  // Degradation: per material the four law properties against cycles with their intervals and
  // the least-squares line, its slope interval and p in the key.
  for (const auto& mat : materials_of(r)) {
    const std::string csv = "campaign_degradation_" + file_name_part(mat) + ".csv";
    const auto& props = degradation_rows();
    // Plotted when some group of the material has a finite value of one of them.
    bool any = false;
    for (const auto& g : r.groups)
      if (g.material == mat)
        for (const auto& d : props)
          any = any || std::isfinite(q(g, d.quantity));
    if (!any)
      continue;
    const std::string png = "campaign_degradation_" + file_name_part(mat) + ".png";
    std::string s = gnuplot_png_preamble(png, 1100, 800);
    s += "set multiplot layout 2,2 title '" + mat + ": degradation with moisture cycles (" + level +
         " intervals)'\nset xlabel 'cycles'\nset key below font ',9'\nset offsets 2,2,0,0\n";
    for (std::size_t p = 0; p < props.size(); ++p) {
      const auto* d = find_degradation(r, mat, props[p].property);
      const int c = 2 + 3 * static_cast<int>(p);
      s +=
          "set ylabel '" + std::string(props[p].property) + (p < 2 ? " (kPa)" : " (J/m^2)") + "'\n";
      s += "plot '" + csv + "' using 1:" + std::to_string(c) + ":" + std::to_string(c + 1) + ":" +
           std::to_string(c + 2) + " with yerrorbars pt 7 title 'groups'";
      if (d && d->has_slope) {
        s += ", " + fmt(d->paper.fit.intercept, 8) + " + " + fmt(d->paper.fit.slope, 8) +
             "*x with lines lw 2 title 'slope " + fmt(d->paper.fit.slope, 3) + " [" +
             cell(d->slope_ci.lo, 3) + ", " + cell(d->slope_ci.hi, 3) + "] p " +
             cell(d->p_value, 2) + ", R^2 " + fmt(d->paper.fit.r2, 2) + "'";
      }
      s += "\n";
    }
    s += "unset multiplot\n";
    if (run_gnuplot(dir, s))
      pngs.push_back(png);
  }
  return pngs;
}

} // namespace fiberbridge::app::campaign_out
