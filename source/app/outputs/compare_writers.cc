#include "fiberbridge/app/outputs/compare_writers.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/plot.h"
#include "fiberbridge/core/units.h"

#include <iostream>
#include <utility>

namespace fiberbridge::app {

void write_comparison(const analysis::ModelComparison& c,
                      const std::vector<const result::SimulationResult*>& models,
                      const law::TractionLaw& law, double j_tip, const std::string& out_dir,
                      ItemReport& report) {
  Json block = Json::object();
  Json pairs = Json::array();
  {
    CsvWriter w(out_dir + "/compare.csv",
                {"model_a", "model_b", "quantity", "rel_l2_developing", "plateau_rel_diff",
                 "peak_load_rel_diff", "n_points"},
                {"pairwise differences of R(a) (b relative to a); developing = before either "
                 "notch root moves"});
    for (const auto& d : c.pairs) {
      w.row({d.model_a, d.model_b, d.quantity},
            {d.rel_l2_developing, d.plateau_rel_diff, d.peak_load_rel_diff, double(d.n_points)});
      pairs.push_back({{"model_a", d.model_a},
                       {"model_b", d.model_b},
                       {"quantity", d.quantity},
                       {"rel_l2_developing", json_number(d.rel_l2_developing)},
                       {"plateau_rel_diff", json_number(d.plateau_rel_diff)},
                       {"peak_load_rel_diff", json_number(d.peak_load_rel_diff)}});
    }
    w.close();
  }
  block["pairwise"] = pairs;

  // Shared axes: R_J and R_energy against a; load against load-point opening; delta_root(a).
  std::string rplot = gnuplot_png_preamble("compare_R_a.png", 1000, 650);
  rplot += "set title 'R(a) from each model (J_{tip} + J_c dotted)'\nset xlabel 'crack-tip "
           "position a (mm)'\nset ylabel 'R (J/m^2)'\nset key bottom right\nplot ";
  std::string lplot = gnuplot_png_preamble("compare_load.png", 1000, 650);
  lplot += "set xlabel 'load-point opening (mm)'\nset ylabel 'load (N)'\nset key top right\nplot ";
  std::string dplot = gnuplot_png_preamble("compare_delta_root.png", 1000, 650);
  dplot += "set xlabel 'crack-tip position a (mm)'\nset ylabel 'delta_{root} (mm)'\nplot ";
  bool first = true;
  for (const auto* r : models) {
    const std::string f = "'rcurve_" + r->model + ".csv'";
    const std::string sep = first ? "" : ", ";
    rplot += sep + f + " using 1:4 with lines lw 2 title '" + r->model + " R_J', " + f +
             " using 1:3 with points pt 7 ps 0.5 title '" + r->model + " R_{energy}'";
    lplot += sep + f + " using 8:7 with lines lw 2 title '" + r->model + "'";
    dplot += sep + f + " using 1:2 with lines lw 2 title '" + r->model + "'";
    first = false;
  }
  rplot += ", " + std::to_string(j_tip + law.area()) + " with lines dt 3 notitle\n";
  for (auto* s : {&rplot, &lplot, &dplot})
    *s += "\n";
  for (const auto& [png, script] : {std::pair<std::string, std::string>{"compare_R_a.png", rplot},
                                    {"compare_load.png", lplot},
                                    {"compare_delta_root.png", dplot}})
    if (run_gnuplot(out_dir, script))
      report.plots.push_back(png);

  if (!c.loops.empty()) {
    Json rows = Json::array();
    CsvWriter w(out_dir + "/closed_loop.csv",
                {"model", "R_source", "method", "peak_kPa", "peak_true_kPa", "delta_at_peak_mm",
                 "delta_at_peak_true_mm", "area_J_m2", "area_true_J_m2", "curve_rel_l2"},
                {"input law -> simulated R(delta_root) -> recovered law; R_energy is what an "
                 "experiment measures, R_eq2 is Eq. 2 at the simulated delta_root (control)"});
    for (const auto& l : c.loops) {
      if (!l.diagnosis.empty()) {
        // A model too coarse for the loop does not invalidate the comparison: say so.
        rows.push_back({{"model", l.model}, {"diagnosis", l.diagnosis}});
        std::cerr << "warning: " << l.diagnosis << "\n";
        continue;
      }
      const auto& loop_rows = l.rows;
      CsvWriter lw(out_dir + "/closed_loop_laws_" + l.model + ".csv",
                   {"delta_mm", "sigma_true_kPa", "sigma_eq6_from_R_energy_kPa",
                    "sigma_dRdd_from_R_energy_kPa", "sigma_eq6_from_R_eq2_kPa"},
                   {"closed loop for " + l.model});
      const auto& le = loop_rows[0].laws; // R_energy
      const auto& lq = loop_rows[2].laws; // R_eq2
      for (std::size_t i = 0; i < le.delta.size(); ++i)
        lw.row({le.delta[i] / units::mm, law.envelope(le.delta[i]) / units::kPa,
                le.sigma_eq6[i] / units::kPa, le.sigma_dRdd[i] / units::kPa,
                lq.sigma_eq6[i] / units::kPa});
      lw.close();
      for (const auto& c : loop_rows) {
        w.row({c.model, c.r_source, c.method},
              {c.peak_kPa, c.peak_true_kPa, c.delta_at_peak_mm, c.delta_at_peak_true_mm,
               c.area_J_m2, c.area_true_J_m2, c.curve_rel_l2});
        rows.push_back({{"model", c.model},
                        {"R_source", c.r_source},
                        {"method", c.method},
                        {"peak_kPa", c.peak_kPa},
                        {"peak_true_kPa", c.peak_true_kPa},
                        {"delta_at_peak_mm", c.delta_at_peak_mm},
                        {"area_J_m2", c.area_J_m2},
                        {"area_true_J_m2", c.area_true_J_m2},
                        {"curve_rel_l2", c.curve_rel_l2}});
      }
      const std::string f = "'closed_loop_laws_" + l.model + ".csv'";
      std::string s = gnuplot_png_preamble("closed_loop_" + l.model + ".png");
      s += "set title '" + l.model +
           ": law recovered from the simulated R(delta_{root})'\n"
           "set xlabel 'opening (mm)'\nset ylabel 'sigma (kPa)'\nset key top right\nplot " +
           f + " using 1:2 with lines lw 3 lc rgb 'black' title 'input law', " + f +
           " using 1:3 with lines lw 2 title 'Eq. 6 from R_{energy}', " + f +
           " using 1:4 with lines lw 2 title 'dR/d{/Symbol d} from R_{energy}', " + f +
           " using 1:5 with lines lw 2 dt 2 title 'Eq. 6 from Eq. 2 at {/Symbol d}_{root}'\n";
      if (run_gnuplot(out_dir, s))
        report.plots.push_back("closed_loop_" + l.model + ".png");
    }
    w.close();
    block["closed_loop"] = rows;
  }
  report["compare"] = block;
}

} // namespace fiberbridge::app
