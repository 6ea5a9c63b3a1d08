#include "fiberbridge/app/analysis_steps.h"

#include "fiberbridge/analysis/degradation.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/output_guard.h"
#include "fiberbridge/core/plot.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/law/piecewise_linear_law.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <set>

namespace fiberbridge::app {

using units::kPa;
using units::mm;

void ensure_directory(const std::string& dir) {
  if (dir.find_first_not_of(" \t") == std::string::npos)
    throw InputError("Output directory is empty; expected a directory name (e.g. output/run)");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw InputError(dir + ": cannot create output directory (" + ec.message() + ")");
}

void remove_stale_summary(const std::string& out_dir) {
  // Marker first: from here until write_run_summary() the directory says it is incomplete, so a
  // run killed at any moment leaves either this marker or a finished run's summary.json.
  write_file_atomically(
      out_dir + "/" + incomplete_marker,
      "fiberbridge has not finished a run into this directory (the run is in progress, failed or "
      "was killed): the files here may come from this run or an earlier one. summary.json is "
      "written, and this file removed, only when a run completes.\n");
  std::error_code ec;
  std::filesystem::remove(out_dir + "/summary.json", ec);
  // Temporary files of a killed run (core writers write NAME.partial, then rename).
  for (const auto& entry : std::filesystem::directory_iterator(out_dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.size() > 8 && name.compare(name.size() - 8, 8, ".partial") == 0)
      std::filesystem::remove(entry.path(), ec);
  }
}

void write_run_summary(const std::string& out_dir, const Json& summary) {
  write_json_atomically(out_dir + "/summary.json", summary);
  if (!output_enabled()) // an MPI rank other than 0 (core/output_guard.h)
    return;
  std::error_code ec;
  std::filesystem::remove(out_dir + "/" + incomplete_marker, ec);
}

namespace {

void write_law_csv(const std::string& path, const std::vector<double>& delta,
                   const std::vector<double>& sigma, const std::string& what) {
  CsvWriter w(path, {"delta_mm", "sigma_kPa"}, {what});
  for (std::size_t i = 0; i < delta.size(); ++i)
    w.row({delta[i] / mm, sigma[i] / kPa});
  w.close();
}

} // namespace

ExtractionOutcome run_extraction(const ExtractionOptions& o, const std::string& out_dir,
                                 Json& summary) {
  if (o.intervals < 4)
    throw InputError("Data/Intervals: need at least 4 grid intervals for Eq. 6, got " +
                     std::to_string(o.intervals));
  if (o.half_width < 1 || 2 * o.half_width >= o.intervals)
    throw InputError("Data/Smoothing half-width: must lie in [1, intervals/2), got " +
                     std::to_string(o.half_width));
  ExtractionOutcome e;
  e.curve = analysis::average_replicates(o.data ? *o.data : analysis::read_rdelta_csv(o.data_file),
                                         o.grid_points);
  analysis::SteadyStateOptions so;
  so.delta_c = o.delta_c;
  so.j_tip = o.j_tip;
  e.steady = analysis::find_steady_state(e.curve, so, o.data_file);
  e.laws = analysis::extract_cohesive_laws(e.curve, e.steady.delta_c, o.intervals, o.half_width);

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
  summary["J_tip_J_m2"] = json_number(e.steady.j_tip);
  summary["G_ss_J_m2"] = json_number(e.steady.G_ss);
  summary["delta_c_mm"] = json_number(e.steady.delta_c / mm);
  summary["peak_sigma_eq5_kPa"] = json_number(peak_eq6 / kPa);
  summary["peak_sigma_dRdd_kPa"] = json_number(peak_dRdd / kPa);
  summary["extract"] = {{"data_file", o.data_file},
                        {"replicates", e.curve.n_replicates},
                        {"averaging", e.curve.report},
                        {"steady_state_criterion", e.steady.criterion},
                        {"delta_c_automatic", e.steady.delta_c_automatic},
                        {"J_tip_automatic", e.steady.j_tip_automatic},
                        {"intervals_n", o.intervals},
                        {"smoothing_half_width_k", o.half_width},
                        {"G_B_J_m2", json_number(G_B)},
                        {"area_eq5_J_m2", json_number(e.laws.area_eq6)},
                        {"area_dRdd_J_m2", json_number(e.laws.area_dRdd)},
                        {"peak_ratio_eq5_over_dRdd", json_number(peak_eq6 / peak_dRdd)}};
  return e;
}

analysis::TrilinearFit run_trilinear_fit(const ExtractionOutcome& e, const FitOptions& o,
                                         const std::string& out_dir, Json& summary) {
  const double dc = e.steady.delta_c;
  const double G_B = e.steady.G_ss - e.steady.j_tip;
  analysis::TrilinearFit fit;
  if (o.free_breakpoints) {
    const double d2_max = o.d2_max > 0 ? o.d2_max : 0.5 * dc;
    fit = analysis::fit_trilinear_free(e.laws.delta, e.laws.sigma_eq6, dc, G_B, o.d1_min, o.d1_max,
                                       d2_max);
  } else {
    if (!(o.d1 > 0 && o.d1 < o.d2 && o.d2 < dc))
      throw InputError("Fit: need 0 < Delta 1 < Delta 2 < delta_c (" + std::to_string(dc / mm) +
                       " mm); got Delta 1 = " + std::to_string(o.d1 / mm) +
                       " mm, Delta 2 = " + std::to_string(o.d2 / mm) + " mm");
    fit = analysis::fit_trilinear_fixed(e.laws.delta, e.laws.sigma_eq6, o.d1, o.d2, dc, G_B);
  }
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
  summary["trilinear"] = {{"delta1_mm", t.d1 / mm},
                          {"sigma1_kPa", t.s1 / kPa},
                          {"delta2_mm", t.d2 / mm},
                          {"sigma2_kPa", t.s2 / kPa},
                          {"delta_c_mm", t.dc / mm},
                          {"J1_J_m2", t.j1()},
                          {"J2_J_m2", t.j2()},
                          {"rms_residual_kPa", fit.rms_residual / kPa},
                          {"max_residual_kPa", fit.max_residual / kPa},
                          {"breakpoints", fit.d1_d2_free ? "free (variable projection)" : "fixed"}};
  return fit;
}

void plot_extraction(const ExtractionOutcome& e, const analysis::TrilinearFit* fit,
                     const std::string& out_dir, Json& summary) {
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
  s += "\n";
  if (run_gnuplot(out_dir, s))
    pngs.push_back("cohesive_law.png");
  for (const auto& p : pngs)
    summary["plots"].push_back(p);
}

void run_ranking(const RankOptions& o, const std::string& out_dir, Json& summary) {
  const auto table = analysis::read_property_table(o.table_file);
  const auto rows = analysis::analyse_degradation(table);
  const auto ranks = analysis::rank_materials(rows);
  const auto issues =
      analysis::check_row_consistency(table, o.d1_mm, o.d2_mm, &analysis::seed_delta_c_mm);
  {
    CsvWriter w(out_dir + "/degradation.csv",
                {"material", "property", "slope_per_cycle", "intercept", "r2", "slope_std_error",
                 "normalized_rate_per_cycle", "significant", "printed_slope", "printed_r2"},
                {"degradation statistics per material and property from " + o.table_file});
    for (const auto& r : rows)
      w.row({r.material, r.property},
            {r.fit.slope, r.fit.intercept, r.fit.r2, r.fit.slope_std_error, r.normalized_rate,
             r.significant ? 1.0 : 0.0, r.has_printed ? r.printed_slope : NAN,
             r.has_printed ? r.printed_r2 : NAN});
    w.close();
  }
  Json deg = Json::array();
  for (const auto& r : rows)
    deg.push_back({{"material", r.material},
                   {"property", r.property},
                   {"slope_per_cycle", r.fit.slope},
                   {"intercept", r.fit.intercept},
                   {"r2", r.fit.r2},
                   {"slope_std_error", json_number(r.fit.slope_std_error)},
                   {"normalized_rate_per_cycle", r.normalized_rate},
                   {"significant", r.significant},
                   {"matches_printed", r.matches_printed}});
  Json ranking = Json::array(), ranking_detail = Json::array();
  for (const auto& m : ranks) {
    ranking.push_back(m.material);
    ranking_detail.push_back({{"material", m.material},
                              {"rank", m.rank},
                              {"degradation_score_per_cycle", m.degradation_score},
                              {"significant_properties", m.significant_properties}});
  }
  Json cons = Json::array();
  for (const auto& i : issues) {
    cons.push_back({{"material", i.material}, {"cycles", i.cycles}, {"message", i.message}});
    std::cerr << "warning: " << o.table_file << ": " << i.material << " at " << i.cycles
              << " cycles: " << i.message << "\n";
  }
  summary["ranking"] = ranking;
  summary["rank"] = {{"table_file", o.table_file},
                     {"rule", "a property degrades when its least-squares slope vs cycles is "
                              "negative with R^2 >= 0.8; materials ranked by the sum of "
                              "significant slope/intercept rates, most durable first"},
                     {"materials", ranking_detail},
                     {"degradation", deg},
                     {"consistency", cons}};
  // One PNG per material: each property normalized by its fitted intercept against cycles.
  std::set<std::string> materials;
  for (const auto& r : rows)
    materials.insert(r.material);
  for (const auto& mat : materials) {
    const std::string csv = "degradation_" + mat + ".csv";
    std::vector<std::string> props;
    for (const auto& r : rows)
      if (r.material == mat)
        props.push_back(r.property);
    std::vector<std::string> header{"cycles"};
    for (const auto& p : props)
      header.push_back(p + "_rel");
    CsvWriter w(out_dir + "/" + csv, header,
                {mat + ": property / fitted intercept vs VPSD cycles"});
    for (std::size_t c = 0; c < table.cycles.size(); ++c) {
      std::vector<double> row{table.cycles[c]};
      for (const auto& r : rows)
        if (r.material == mat) {
          for (const auto& tr : table.rows)
            if (tr.material == mat && tr.property == r.property)
              row.push_back(tr.values[c] / r.fit.intercept);
        }
      w.row(row);
    }
    w.close();
    std::string s = gnuplot_png_preamble("degradation_" + mat + ".png", 800, 500);
    s += "set title '" + mat +
         ": degradation vs moisture cycles'\nset xlabel 'VPSD cycles'\n"
         "set ylabel 'value / fitted value at 0 cycles'\nset key outside right\nplot ";
    for (std::size_t p = 0; p < props.size(); ++p)
      s += std::string(p ? ", " : "") + "'" + csv + "' using 1:" + std::to_string(p + 2) +
           " with linespoints lw 2 title '" + props[p] + "'";
    s += "\n";
    if (run_gnuplot(out_dir, s))
      summary["plots"].push_back("degradation_" + mat + ".png");
  }
}

} // namespace fiberbridge::app
