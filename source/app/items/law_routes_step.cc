// The three routes to the bridging law in a scene (items.h, report_law_routes): after `extract`
// ran on R(delta_root) of records that `identify` also fitted, the Eq. 5/6 law, the old
// dR/d delta law and the identified law on one grid, in a table, a summary block and a plot.
#include "fiberbridge/analysis/law_routes.h"
#include "fiberbridge/app/items/analysis_steps.h"
#include "fiberbridge/app/items/item_identify.h"
#include "fiberbridge/app/items/items.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/plot.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/identify/identify.h"

namespace fiberbridge::app {

using units::kPa;
using units::mm;

void report_law_routes(const ExtractionOutcome& e, const identify::Identification& id,
                       const std::string& out_dir, ItemReport& report) {
  const auto routes =
      analysis::compare_law_routes(e.laws, law::make_trilinear(id.law), nullptr, 1001);
  {
    CsvWriter w(out_dir + "/law_routes.csv",
                {"delta_mm", "sigma_eq5_kPa", "sigma_dRdd_kPa", "sigma_identified_kPa"},
                {"the three routes to the law on one grid: seed Eq. 5/6 and sigma = dR/ddelta "
                 "from R(delta_root) (extract), and the law identified from load, opening and "
                 "crack readings (identify)"});
    for (std::size_t i = 0; i < routes.delta.size(); ++i)
      w.row({routes.delta[i] / mm, routes.routes[0].sigma[i] / kPa, routes.routes[1].sigma[i] / kPa,
             routes.routes[2].sigma[i] / kPa});
    w.close();
  }
  Json block = Json::object();
  block["reference"] = "eq5 (the ratios and RMS are against the Eq. 5/6 law)";
  const double G_B = e.steady.G_ss - e.steady.j_tip;
  for (const auto& r : routes.routes) {
    const bool identified = r.name == "identified";
    const std::string key = r.name == "eq6" ? "eq5" : r.name;
    block[key] = {{"peak_sigma_kPa", json_number(r.peak / kPa)},
                  {"delta_at_peak_mm", json_number(r.delta_at_peak / mm)},
                  {"area_J_m2", json_number(r.area)},
                  {"J_tip_J_m2", identified ? id.j_tip : e.steady.j_tip},
                  {"G_ss_J_m2", identified ? id.g_ss : e.steady.G_ss},
                  {"peak_ratio", json_number(r.peak_ratio)},
                  {"area_ratio", json_number(r.area_ratio)},
                  {"rms_rel", json_number(r.rms_rel)}};
  }
  block["G_B_J_m2"] = json_number(G_B);
  block["notes"] = Json::array(
      {"seed Eq. 4: dR/ddelta = (sigma - delta sigma')/2, so the old route gives about half the "
       "law where it is flat and its area equals Eq. 5/6's (both G_B): the area does not judge "
       "the routes, the peak and the shape do",
       "identified: the beam model fitted to load-opening and crack-length-opening (delta_root "
       "not used); Eq. 5/6 and dR/ddelta: R_energy(delta_root) of reduce"});
  report["law_routes"] = block;
  if (run_gnuplot(out_dir,
                  gnuplot_png_preamble("law_routes.png") +
                      "set title 'three routes to the law on the same record(s)'\n"
                      "set xlabel 'opening {/Symbol d} (mm)'\nset ylabel '{/Symbol s} (kPa)'\n"
                      "set key top right\nplot 'law_routes.csv' using 1:2 with lines lw 2 "
                      "title 'Eq. 5/6 from R({/Symbol d}_{root})', '' using 1:3 with lines lw 2 "
                      "dt 2 title 'dR/d{/Symbol d} (old method)', '' using 1:4 with lines lw 2 "
                      "title 'identified (load, opening, crack)'\n"))
    report.plots.push_back("law_routes.png");
}

} // namespace fiberbridge::app
