// The files, plots and summary blocks of `identify` (identify_writers.h).
#include "outputs/identify_writers.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/plot.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace fiberbridge::app {

using units::kPa;
using units::mm;

std::string title_of(std::string name) {
  std::replace(name.begin(), name.end(), '_', ' ');
  return name;
}

Json identification_json(const identify::Identification& id) {
  Json j = Json::object();
  j["trilinear"] = {{"d1_mm", id.law.d1 / mm},
                    {"sigma1_kPa", id.law.s1 / kPa},
                    {"d2_mm", id.law.d2 / mm},
                    {"sigma2_kPa", id.law.s2 / kPa},
                    {"delta_c_mm", id.law.dc / mm}};
  j["J_tip_J_m2"] = id.j_tip;
  j["G_ss_J_m2"] = id.g_ss;
  j["load_rms_rel"] = id.load_rms_rel;
  j["crack_rms_mm"] = id.crack_rms / mm;
  j["evaluations"] = id.evaluations;
  j["wall_time_s"] = id.wall_time_s;
  j["J_c_J_m2"] = id.law.area();
  j["J_c_std_error_J_m2"] = json_number(id.j_c_std_error);
  Json se = Json::object();
  for (const auto& p : id.parameters)
    se[p.name] = json_number(p.std_error);
  j["std_error"] = se;
  Json corr = Json::array();
  for (const auto& row : id.correlation) {
    Json r = Json::array();
    for (double v : row)
      r.push_back(json_number(v));
    corr.push_back(r);
  }
  j["correlation"] = {{"order", {"d1", "sigma1", "d2", "sigma2", "delta_c", "J_tip"}},
                      {"matrix", corr}};
  j["chi2"] = id.chi2;
  j["n_residuals"] = id.n_residuals;
  j["forward_runs"] = id.forward_runs;
  j["forward_time_s"] = id.forward_time_s;
  Json recs = Json::array();
  for (const auto& r : id.records)
    recs.push_back({{"record", r.name},
                    {"a0_mm", r.initial_crack / mm},
                    {"initial_compliance_mm_N", r.initial_compliance / mm},
                    {"E_L_effective_GPa", r.E_L * 1e-9},
                    {"peak_load_N", r.peak_load},
                    {"load_rms_rel", r.load_rms_rel},
                    {"crack_rms_mm", r.crack_rms / mm},
                    {"max_opening_over_a", r.max_opening_over_a},
                    {"min_F", r.min_F}});
  j["records"] = recs;
  j["notes"] = id.notes;
  return j;
}

void write_identification(const SceneContext& ctx, const identify::Identification& id,
                          ItemReport& report) {
  {
    CsvWriter w(ctx.out("identify_fit.csv"),
                {"record", "opening_mm", "load_N", "model_load_N", "a_mm", "model_a_mm"},
                {"measured rows and the identified beam model at the same openings"});
    for (const auto& r : id.records)
      for (std::size_t i = 0; i < r.opening.size(); ++i)
        w.row({r.name}, {r.opening[i] / mm, r.load[i], r.model_load[i], r.crack_length[i] / mm,
                         r.model_crack_length[i] / mm});
    w.close();
  }
  {
    CsvWriter w(ctx.out("identify_law.csv"),
                {"delta_mm", "sigma_kPa", "sigma_lo_kPa", "sigma_hi_kPa"},
                {"identified trilinear law with a one-standard-error band (Jacobian covariance)"});
    for (std::size_t i = 0; i < id.band_delta.size(); ++i)
      w.row({id.band_delta[i] / mm, id.band_sigma[i] / kPa, id.band_lo[i] / kPa,
             id.band_hi[i] / kPa});
    w.close();
  }
  // One curve per record: gnuplot's 'every' cannot select by label, so each record is a block.
  std::string load_plot, crack_plot;
  for (std::size_t k = 0; k < id.records.size(); ++k) {
    const std::string file = "identify_fit_" + std::to_string(k) + ".csv";
    CsvWriter w(ctx.out(file), {"opening_mm", "load_N", "model_load_N", "a_mm", "model_a_mm"});
    const auto& r = id.records[k];
    for (std::size_t i = 0; i < r.opening.size(); ++i)
      w.row({r.opening[i] / mm, r.load[i], r.model_load[i], r.crack_length[i] / mm,
             r.model_crack_length[i] / mm});
    w.close();
    const std::string sep = k ? ", " : "plot ";
    load_plot += sep + "'" + file + "' using 1:2 with points pt 7 ps 0.4 lc " +
                 std::to_string(k + 1) + " title '" + title_of(r.name) + " measured', '" + file +
                 "' using 1:3 with lines lw 2 lc " + std::to_string(k + 1) + " title 'model'";
    crack_plot += sep + "'" + file + "' using 1:4 with points pt 7 ps 0.4 lc " +
                  std::to_string(k + 1) + " title '" + title_of(r.name) + " readings', '" + file +
                  "' using 1:5 with lines lw 2 lc " + std::to_string(k + 1) + " title 'model'";
  }
  const std::string head = "set datafile separator ','\nset key autotitle columnhead\n";
  auto plot = [&](const std::string& png, const std::string& body) {
    if (run_gnuplot(ctx.output_dir, gnuplot_png_preamble(png) + head + body))
      report.plots.push_back(png);
  };
  // Headroom above the highest load of any record (gnuplot's autoscale stops at the next tic and
  // cut DCB-01's peak at 100 N), the key top right, away from the rising branches.
  double peak = 0;
  for (const auto& r : id.records)
    peak = std::max(peak, r.peak_load);
  plot("identify_load_opening.png",
       "set title 'identify: measured and simulated P(opening)'\nset xlabel 'load-line opening "
       "(mm)'\nset ylabel 'load (N)'\nset key top right\nset yrange [0:" +
           std::to_string(1.1 * peak) + "]\n" + load_plot + "\n");
  plot("identify_crack_opening.png",
       "set title 'identify: measured and simulated a(opening)'\nset xlabel 'load-line opening "
       "(mm)'\nset ylabel 'crack length (mm)'\nset key bottom right\n" +
           crack_plot + "\n");
  plot("identify_law.png",
       "set title 'identified law, one-standard-error band'\nset xlabel 'opening {/Symbol d} "
       "(mm)'\nset ylabel '{/Symbol s} (kPa)'\nplot 'identify_law.csv' using 1:3:4 with "
       "filledcurves fs transparent solid 0.3 title 'band', '' using 1:2 with lines lw 2 title "
       "'identified'\n");
}

Json identify_summary(const std::vector<identify::Identification>& fits,
                      const identify::IdentifySettings& settings, const specimen::Material& quoted,
                      const std::vector<analysis::TestRecord>& records) {
  Json block = identification_json(fits.front());
  block["modulus"] = settings.calibrate_modulus
                         ? "E_L calibrated per record from the initial compliance (CBT)"
                         : "E_L as quoted (Material/E_L)";
  block["E_L_quoted_GPa"] = quoted.E_L * 1e-9;
  if (std::all_of(records.begin(), records.end(),
                  [](const analysis::TestRecord& r) { return !r.delta_root.empty(); }))
    block["notes"].push_back("delta_root measured: with 'extract' in Run (after reduce) the "
                             "scene compares Eq. 5/6, dR/ddelta and this law (law_routes)");
  if (fits.size() > 1) {
    Json each = Json::array();
    for (std::size_t k = 0; k + 1 < fits.size(); ++k) {
      Json j = identification_json(fits[k + 1]);
      j["record"] = records[k].name;
      each.push_back(j);
    }
    block["per_record"] = each;
  }
  return block;
}

void write_identified_against_simulations(const SceneContext& ctx, const identify::RecordFit& rec,
                                          const std::vector<SimulationAgainstRecord>& checks,
                                          ItemReport& report) {
  Json block = Json::object();
  std::string plot = "plot 'identify_fit_0.csv' using 1:2 with points pt 7 ps 0.4 title '" +
                     title_of(rec.name) + " measured'";
  for (const auto& c : checks) {
    const std::string& name = c.model;
    const std::string file = "identify_check_" + name + ".csv";
    CsvWriter w(ctx.out(file), {"opening_mm", "load_N", "model_load_N", "a_mm", "model_a_mm"},
                {name + " with the identified law at the record's openings"});
    for (std::size_t i = 0; i < c.compared; ++i)
      w.row({rec.opening[i] / mm, rec.load[i], c.load[i],
             (rec.crack_length.empty() ? NAN : rec.crack_length[i]) / mm, c.a[i] / mm});
    w.close();
    block[name] = {{"record", rec.name},
                   {"load_rms_rel", c.load_rms_rel},
                   {"rows_compared", c.compared},
                   {"rows", c.load.size()},
                   {"final_a_mm", c.final_a / mm}};
    plot += ", '" + file + "' using 1:3 with lines lw 2 title '" + name + "'";
  }
  report["identify_check"] = block;
  // The simulations' R(a) beside the record's measured R(a) when `reduce` ran in this scene.
  if (std::filesystem::exists(ctx.out("rcurve_test.csv"))) {
    std::string r_plot = "plot 'rcurve_test.csv' using 2:(strcol(1) eq '" + rec.name +
                         "' ? $4 : NaN) every ::1 with points pt 7 ps 0.5 title '" +
                         title_of(rec.name) + " R_{energy} measured', '' using 2:(strcol(1) eq '" +
                         rec.name +
                         "' ? $7 : NaN) every ::1 with points pt 6 ps 0.5 title 'R_{MBT} measured'";
    for (const auto& [name, result] : ctx.results)
      r_plot += ", 'rcurve_" + name + ".csv' using 1:4 every ::1 with lines lw 2 title '" + name +
                " R_J, identified law'";
    if (run_gnuplot(ctx.output_dir,
                    gnuplot_png_preamble("identify_check_R_a.png") +
                        "set datafile separator ','\nset title 'identified law in the "
                        "simulations against the measured R(a)'\nset xlabel 'crack length a "
                        "(mm)'\nset ylabel 'R (J/m^2)'\nset key bottom right\n" +
                        r_plot + "\n"))
      report.plots.push_back("identify_check_R_a.png");
  }
  if (run_gnuplot(ctx.output_dir,
                  gnuplot_png_preamble("identify_check_load.png") +
                      "set datafile separator ','\nset title 'identified law in the "
                      "simulations against the record'\nset xlabel 'load-line opening (mm)'\n"
                      "set ylabel 'load (N)'\n" +
                      plot + "\n"))
    report.plots.push_back("identify_check_load.png");
}

} // namespace fiberbridge::app
