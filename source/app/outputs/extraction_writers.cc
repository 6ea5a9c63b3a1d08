#include "fiberbridge/app/outputs/extraction_writers.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/plot.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/law/piecewise_linear_law.h"

#include <algorithm>

namespace fiberbridge::app {

using units::kPa;
using units::mm;

namespace {

void write_law_csv(const std::string& path, const std::vector<double>& delta,
                   const std::vector<double>& sigma, const std::string& what) {
  CsvWriter w(path, {"delta_mm", "sigma_kPa"}, {what});
  for (std::size_t i = 0; i < delta.size(); ++i)
    w.row({delta[i] / mm, sigma[i] / kPa});
  w.close();
}

} // namespace

void write_extraction(const analysis::ExtractionOutcome& e, const analysis::ExtractionOptions& o,
                      const std::string& out_dir, ItemReport& report) {

  {
    CsvWriter w(out_dir + "/rdelta_averaged.csv", {"delta_mm", "R_J_m2", "R_std_J_m2"},
                {"R(delta) averaged over " + std::to_string(e.curve.n_replicates) +
                 " replicate(s) of " + o.data_file});
    for (std::size_t i = 0; i < e.curve.delta.size(); ++i)
      w.row({e.curve.delta[i] / mm, e.curve.R[i], e.curve.R_std[i]});
    w.close();
  }
  write_law_csv(out_dir + "/cohesive_law_eq5.csv", e.laws.delta, e.laws.sigma_eq6,
                "cohesive law by seed Eq. 6 (discretized Eq. 5), n = " +
                    std::to_string(o.intervals) + ", k = " + std::to_string(o.half_width));
  write_law_csv(out_dir + "/cohesive_law_dRdd.csv", e.laws.delta, e.laws.sigma_dRdd,
                "cohesive law by the old method sigma = dR/ddelta (same slopes S_i)");

  const double peak_eq6 = *std::max_element(e.laws.sigma_eq6.begin(), e.laws.sigma_eq6.end());
  const double peak_dRdd = *std::max_element(e.laws.sigma_dRdd.begin(), e.laws.sigma_dRdd.end());
  const double G_B = e.steady.G_ss - e.steady.j_tip;
  report["J_tip_J_m2"] = json_number(e.steady.j_tip);
  report["G_ss_J_m2"] = json_number(e.steady.G_ss);
  report["delta_c_mm"] = json_number(e.steady.delta_c / mm);
  report["peak_sigma_eq5_kPa"] = json_number(peak_eq6 / kPa);
  report["peak_sigma_dRdd_kPa"] = json_number(peak_dRdd / kPa);
  report["extract"] = {{"data_file", o.data_file},
                       {"replicates", e.curve.n_replicates},
                       {"averaging", e.curve.report},
                       {"steady_state_criterion", e.steady.criterion},
                       {"delta_c_automatic", e.steady.delta_c_automatic},
                       {"J_tip_automatic", e.steady.j_tip_automatic},
                       {"end_effect", e.steady.end_effect},
                       {"intervals_n", o.intervals},
                       {"smoothing_half_width_k", o.half_width},
                       {"G_B_J_m2", json_number(G_B)},
                       {"area_eq5_J_m2", json_number(e.laws.area_eq6)},
                       {"area_dRdd_J_m2", json_number(e.laws.area_dRdd)},
                       {"peak_ratio_eq5_over_dRdd", json_number(peak_eq6 / peak_dRdd)}};
}

Json trilinear_json(const law::TrilinearParameters& t) {
  return {{"delta1_mm", t.d1 / mm},   {"sigma1_kPa", t.s1 / kPa}, {"delta2_mm", t.d2 / mm},
          {"sigma2_kPa", t.s2 / kPa}, {"delta_c_mm", t.dc / mm},  {"J1_J_m2", t.j1()},
          {"J2_J_m2", t.j2()}};
}

void write_trilinear_fit(const analysis::TrilinearFit& fit, const std::string& out_dir,
                         ItemReport& report) {
  const auto& t = fit.law;
  {
    CsvWriter w(out_dir + "/trilinear_fit.csv", {"delta_mm", "sigma_kPa"},
                {"trilinear fit of the Eq. 6 law: (0,0) (d1,s1) (d2,s2) (dc,0); area constrained "
                 "to G_B = G_ss - J_tip",
                 "J1_J_m2 = " + std::to_string(t.j1()) + ", J2_J_m2 = " + std::to_string(t.j2()) +
                     ", rms_residual_kPa = " + std::to_string(fit.rms_residual / kPa)});
    w.row({0.0, 0.0});
    w.row({t.d1 / mm, t.s1 / kPa});
    w.row({t.d2 / mm, t.s2 / kPa});
    w.row({t.dc / mm, 0.0});
    w.close();
  }
  Json block = trilinear_json(t);
  block["rms_residual_kPa"] = fit.rms_residual / kPa;
  block["max_residual_kPa"] = fit.max_residual / kPa;
  block["breakpoints"] = fit.d1_d2_free ? "free (variable projection)" : "fixed";
  report["trilinear"] = block;
}

void plot_extraction(const analysis::ExtractionOutcome& e, const analysis::TrilinearFit* fit,
                     const std::string& out_dir, ItemReport& report, bool corrected) {
  // Forward R(delta) of the fitted law (Eq. 2) beside the data: the check a person looks at first.
  if (fit) {
    const auto law = law::make_trilinear(fit->law);
    CsvWriter w(out_dir + "/rdelta_fit_forward.csv", {"delta_mm", "R_J_m2"},
                {"Eq. 2 forward R curve of the fitted trilinear law with the measured J_tip"});
    const double dmax = e.curve.delta.back();
    for (int i = 0; i <= 400; ++i) {
      const double d = dmax * i / 400;
      w.row({d / mm, law::r_curve_eq2(law, e.steady.j_tip, d)});
    }
    w.close();
  }
  std::vector<std::string> pngs;
  std::string s = gnuplot_png_preamble("rdelta.png");
  s += "set xlabel 'notch-root opening delta (mm)'\nset ylabel 'R (J/m^2)'\nset key bottom right\n";
  s += "plot 'rdelta_averaged.csv' using 1:2 with lines lw 2 title 'data (averaged)'";
  if (fit)
    s += ", 'rdelta_fit_forward.csv' using 1:2 with lines lw 2 dt 2 title 'Eq. 2 of the trilinear "
         "fit'";
  s += "\n";
  if (run_gnuplot(out_dir, s))
    pngs.push_back("rdelta.png");
  s = gnuplot_png_preamble("cohesive_law.png");
  s += "set xlabel 'opening delta (mm)'\nset ylabel 'sigma (kPa)'\nset key top right\n";
  s += "plot 'cohesive_law_eq5.csv' using 1:2 with lines lw 2 title 'Eq. 5/6 (new method)', "
       "'cohesive_law_dRdd.csv' using 1:2 with lines lw 2 title 'sigma = dR/ddelta (old method)'";
  if (fit)
    s += ", 'trilinear_fit.csv' using 1:2 with linespoints lw 2 title 'trilinear fit'";
  if (corrected)
    s += ", 'trilinear_fit_corrected.csv' using 1:2 with linespoints lw 2 dt 2 title 'trilinear, "
         "corrected by simulation (handed on)'";
  s += "\n";
  if (run_gnuplot(out_dir, s))
    pngs.push_back("cohesive_law.png");
  for (const auto& p : pngs)
    report.plots.push_back(p);
}

} // namespace fiberbridge::app
