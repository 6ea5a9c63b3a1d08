// The files, plots and summary block of the reduce step (reduce_writers.h).
#include "outputs/reduce_writers.h"

#include "fiberbridge/analysis/synthetic_data.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/plot.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <cmath>

namespace fiberbridge::app {

using units::mm;

namespace {

Json method_json(const analysis::MethodSummary& m) {
  return {{"initiation_J_m2", json_number(m.initiation)},
          {"plateau_J_m2", json_number(m.plateau)},
          {"plateau_std_J_m2", json_number(m.plateau_std)}};
}

Json methods_json(const analysis::MethodSummary& e, const analysis::MethodSummary& mbt,
                  const analysis::MethodSummary& cc, const analysis::MethodSummary& mcc,
                  const analysis::MethodSummary& cbbm) {
  return {{"energy", method_json(e)},
          {"MBT", method_json(mbt)},
          {"CC", method_json(cc)},
          {"MCC", method_json(mcc)},
          {"CBBM", method_json(cbbm)}};
}

/// The three ASTM D5528 initiation points of a record, in a fixed order.
std::vector<std::pair<std::string, const analysis::InitiationPoint*>>
initiation_points(const analysis::InitiationValues& v) {
  return {{"NL", &v.nl}, {"5%/max", &v.offset5_max}, {"VIS", &v.vis}};
}

/// Mean over the records where the point was found and G is finite (NaN when none).
double mean_initiation(const ReduceOutcome& r, std::size_t k, bool cbbm, int& n) {
  double s = 0;
  n = 0;
  for (const auto& x : r.reduced) {
    const auto* p = initiation_points(x.initiation)[k].second;
    const double G = cbbm ? p->G_CBBM : p->G_MBT;
    if (p->found && std::isfinite(G)) {
      s += G;
      ++n;
    }
  }
  return n ? s / n : NAN;
}

void write_initiation(const ReduceOutcome& r, const std::string& out_dir) {
  CsvWriter w(out_dir + "/initiation_test.csv",
              {"record", "point", "line", "load_N", "opening_mm", "G_MBT_J_m2", "G_CBBM_J_m2"},
              {"ASTM D5528 initiation values: NL (compliance above the initial one by more than "
               "1 % from there on up to 5%/max), 5%/max (compliance +5 % or the maximum load, "
               "whichever first), VIS (first crack reading beyond a0; absent without crack "
               "readings); G_MBT at a0 + MBT's |Delta| (ASTM D5528 uses a0), G_CBBM at the "
               "equivalent crack; record 'mean' is the mean over the records where found"});
  for (const auto& x : r.reduced)
    for (const auto& [name, p] : initiation_points(x.initiation))
      if (p->found)
        w.row({x.name, name},
              {static_cast<double>(p->line), p->load, p->opening / mm, p->G_MBT, p->G_CBBM});
  for (std::size_t k = 0; k < 3; ++k) {
    int n_mbt = 0, n_cbbm = 0;
    const double mbt = mean_initiation(r, k, false, n_mbt),
                 cbbm = mean_initiation(r, k, true, n_cbbm);
    if (n_mbt || n_cbbm)
      w.row({"mean", initiation_points(r.reduced.front().initiation)[k].first},
            {NAN, NAN, NAN, mbt, cbbm});
  }
  w.close();
}

Json initiation_json(const analysis::InitiationValues& v) {
  Json j;
  for (const auto& [name, p] : initiation_points(v)) {
    if (!p->found) {
      j[name] = nullptr;
      continue;
    }
    j[name] = {{"line", p->line},
               {"load_N", p->load},
               {"opening_mm", p->opening / mm},
               {"G_MBT_J_m2", json_number(p->G_MBT)},
               {"G_CBBM_J_m2", json_number(p->G_CBBM)},
               {"definition", p->definition}};
  }
  return j;
}

} // namespace

void write_reduce_tables(const ReduceOutcome& r, const std::string& out_dir) {
  const bool root = !r.reduced.front().delta_root.empty();
  // The first columns keep their places (plots and readers use them by position); the CBBM
  // columns follow delta_root's.
  std::vector<std::string> header = {
      "record",           "a_mm",       "da_mm",     "R_energy_J_m2", "R_energy_lo_J_m2",
      "R_energy_hi_J_m2", "R_MBT_J_m2", "R_CC_J_m2", "R_MCC_J_m2"};
  if (root) {
    header.push_back("delta_root_mm");
    header.push_back("R_delta_J_m2");
  }
  for (const char* c : {"equivalent_crack", "a_eq_mm", "R_CBBM_J_m2", "R_energy_eq_J_m2",
                        "R_energy_eq_lo_J_m2", "R_energy_eq_hi_J_m2", "R_energy_readings_J_m2"})
    header.push_back(c);
  CsvWriter w(out_dir + "/rcurve_test.csv", header,
              {"R(a) per crack reading, or per step of the CBBM equivalent crack where "
               "equivalent_crack = 1 (no crack readings: a = a_eq, no MBT/CC/MCC): direct energy "
               "(band +-2 x the "
               "larger of the local slope's standard error and the scatter of neighbouring "
               "estimates) and ASTM D5528 / ISO 15024 MBT, CC, MCC; CBBM against the equivalent "
               "crack a_eq (from the load line) and direct energy against a_eq beside; "
               "R_energy_readings is the direct energy against the readings as read; R_delta is "
               "R_energy at the measured notch-root opening"});
  auto at = [](const std::vector<double>& v, std::size_t i, double unit = 1.0) {
    return i < v.size() ? v[i] / unit : NAN;
  };
  for (const auto& x : r.reduced)
    for (std::size_t i = 0; i < x.a.size(); ++i) {
      std::vector<double> v = {x.a[i] / mm,      x.da[i] / mm, x.R_energy[i], x.R_energy_lo[i],
                               x.R_energy_hi[i], x.R_MBT[i],   x.R_CC[i],     x.R_MCC[i]};
      if (root) {
        v.push_back(x.delta_root.empty() ? NAN : x.delta_root[i] / mm);
        v.push_back(x.delta_root.empty() ? NAN : x.R_energy[i]);
      }
      for (double y : {x.crack == "equivalent" ? 1.0 : 0.0, at(x.a_eq, i, mm), at(x.R_CBBM, i),
                       at(x.R_energy_eq, i), at(x.R_energy_eq_lo, i), at(x.R_energy_eq_hi, i),
                       at(x.R_energy_readings, i)})
        v.push_back(y);
      w.row({x.name}, v);
    }
  w.close();
  write_initiation(r, out_dir);

  const auto& m = r.mean;
  CsvWriter mw(out_dir + "/rcurve_test_mean.csv",
               {"da_mm", "R_energy_J_m2", "R_energy_std_J_m2", "R_MBT_J_m2", "R_MBT_std_J_m2",
                "R_CC_J_m2", "R_CC_std_J_m2", "R_MCC_J_m2", "R_MCC_std_J_m2", "R_CBBM_J_m2",
                "R_CBBM_std_J_m2"},
               {"mean of " + std::to_string(m.n_records) +
                " record(s) on a common crack-extension grid; std = sample standard deviation "
                "over the records (0 for one)"});
  for (std::size_t i = 0; i < m.da.size(); ++i)
    mw.row({m.da[i] / mm, m.R_energy[i], m.R_energy_std[i], m.R_MBT[i], m.R_MBT_std[i], m.R_CC[i],
            m.R_CC_std[i], m.R_MCC[i], m.R_MCC_std[i], m.R_CBBM[i], m.R_CBBM_std[i]});
  mw.close();

  for (const auto& rec : r.records) {
    CsvWriter c(out_dir + "/record_clean_" + rec.name + ".csv",
                {"line", "opening_mm", "load_N", "a_mm", "new_reading"},
                {"rows of " + rec.source + " after cleaning (summary.json reduce.records)"});
    const auto readings = analysis::crack_reading_rows(rec);
    std::size_t next = 0;
    for (std::size_t i = 0; i < rec.opening.size(); ++i) {
      const bool fresh = next < readings.size() && readings[next] == i;
      next += fresh;
      // NaN (an empty cell) on a row without a crack reading, or in a record without any.
      const double a = rec.crack_length.empty() ? NAN : rec.crack_length[i];
      c.row({static_cast<double>(rec.line[i]), rec.opening[i] / mm, rec.load[i], a / mm,
             fresh ? 1.0 : 0.0});
    }
    c.close();
  }
}

void plot_reduce(const ReduceOutcome& r, const std::string& out_dir, ItemReport& report) {
  // The load axis ends 10 % above the largest load of any record: gnuplot's autoscale ends at
  // the next tick, which for DCB-01's 99.8 N peak is 100 N, and drew the peak on the frame.
  double peak = 0;
  for (const auto& rec : r.records)
    for (double P : rec.load)
      peak = std::max(peak, P);
  // noenhanced: record names carry underscores, which gnuplot would make subscripts.
  std::string p = gnuplot_png_preamble("reduce_load_opening.png");
  p += "set termoption noenhanced\nset datafile separator ','\nset xlabel 'load-line opening "
       "(mm)'\nset ylabel 'load "
       "(N)'\nset key top right\nset xrange [0:*]\nset yrange [0:" +
       std::to_string(1.1 * peak) + "]\nplot ";
  std::string a = gnuplot_png_preamble("reduce_crack_opening.png");
  a += "set termoption noenhanced\nset datafile separator ','\nset xlabel 'load-line opening "
       "(mm)'\nset ylabel 'crack length "
       "from the load line (mm)'\nset key bottom right\nplot ";
  for (std::size_t k = 0; k < r.records.size(); ++k) {
    const std::string f = "'record_clean_" + r.records[k].name + ".csv'";
    const std::string lc = " lc " + std::to_string(k + 1);
    p += std::string(k ? ", " : "") + f + " using 2:3 with lines" + lc + " title '" +
         r.records[k].name + "', " + f + " using 2:($5 > 0 ? $3 : 1/0) with points pt 7 ps 0.5" +
         lc + (k ? " notitle" : " title 'crack readings'");
    a += std::string(k ? ", " : "") + f + " using 2:($5 > 0 ? $4 : 1/0) with points pt 7 ps 0.5" +
         lc + " title '" + r.records[k].name + "'";
  }
  if (run_gnuplot(out_dir, p + "\n"))
    report.plots.push_back("reduce_load_opening.png");
  if (run_gnuplot(out_dir, a + "\n"))
    report.plots.push_back("reduce_crack_opening.png");
  // R_CBBM's column in rcurve_test.csv (write_reduce_tables): after the 9 fixed ones, delta_root's
  // two when measured, equivalent_crack and a_eq_mm.
  const int cbbm_column = 9 + (r.reduced.front().delta_root.empty() ? 0 : 2) + 3;
  for (const auto& x : r.reduced) {
    const std::string png = "reduce_R_" + x.name + ".png";
    std::string s = gnuplot_png_preamble(png);
    s += "set termoption noenhanced\nset title '" + x.name +
         "'\nset datafile separator ','\nset xlabel 'crack length a (mm)'\nset ylabel 'R (J/m^2)'\n"
         "set key bottom right\nsel(c) = strcol(1) eq '" +
         x.name +
         "' ? column(c) : 1/0\nplot 'rcurve_test.csv' using 2:(sel(5)):(sel(6)) with "
         "filledcurves fs transparent solid 0.3 lc 1 title 'direct energy band', "
         "'' using 2:(sel(4)) with lines lw 2 lc 1 title 'direct energy', '' using 2:(sel(7)) "
         "with lines lw 2 lc 2 title 'MBT', '' using 2:(sel(8)) with lines lc 3 title 'CC', '' "
         "using 2:(sel(9)) with lines lc 4 dt 2 title 'MCC', '' using 2:(sel(" +
         std::to_string(cbbm_column) + ")) with lines lc 5 dt 3 title 'CBBM'\n";
    if (run_gnuplot(out_dir, s))
      report.plots.push_back(png);
  }
}

void write_reduce_rdelta(const ReduceOutcome& r, const std::string& out_dir) {
  analysis::write_rdelta_csv(out_dir + "/rdelta_test.csv", analysis::to_rdelta(r.reduced, "reduce"),
                             {"R(delta_root) from the direct-energy R(a) of the records with "
                              "a measured notch-root opening (fiberbridge reduce)"});
}

Json reduce_summary(const ReduceStepOptions& o, const ReduceOutcome& r, bool any_root,
                    bool all_root) {
  Json block;
  block["width_mm"] = o.specimen.width / mm;
  block["arm_thickness_mm"] = o.specimen.arm_thickness() / mm;
  block["plateau_definition"] = "mean over the last " + std::to_string(o.reduce.plateau_fraction) +
                                " of each record's crack extension";
  block["initiation_definition"] =
      "initiation_J_m2: value at the first row beyond a0 (visual onset with readings); "
      "initiation: ASTM D5528 NL, 5%/max and VIS (initiation_test.csv)";
  block["records"] = Json::array();
  for (const auto& x : r.reduced) {
    Json j = {
        {"name", x.name},
        {"source", x.source},
        {"a0_mm", x.a0 / mm},
        {"readings", x.a.size()},
        {"crack_extension_mm", x.da.back() / mm},
        {"smoothing_window_mm", x.window / mm},
        {"MBT_Delta_mm", x.mbt_delta / mm},
        {"CC_n", x.cc_n},
        {"MCC_A1", x.mcc_A1},
        {"max_opening_over_a", x.max_opening_over_a},
        {"delta_root_measured", !x.delta_root.empty()},
        {"crack", x.crack},
        {"CBBM_flexural_modulus_GPa", json_number(x.flexural_modulus / 1e9)},
        {"CBBM_Delta_mm", json_number(x.cbbm_delta / mm)},
        {"initial_compliance_mm_N", json_number(x.initial_compliance / mm)},
        {"final_equivalent_crack_mm", json_number(x.a_eq.empty() ? NAN : x.a_eq.back() / mm)}};
    j.update(methods_json(x.energy, x.mbt, x.cc, x.mcc, x.cbbm));
    j["energy_vs_equivalent_crack"] = method_json(x.energy_eq);
    j["initiation"] = initiation_json(x.initiation);
    j["cleaning"] = x.cleaning;
    j["notes"] = x.notes;
    block["records"].push_back(j);
  }
  Json mean = {{"n_records", r.mean.n_records}, {"crack_extension_mm", r.mean.da.back() / mm}};
  mean.update(methods_json(r.mean.energy, r.mean.mbt, r.mean.cc, r.mean.mcc, r.mean.cbbm));
  for (std::size_t k = 0; k < 3; ++k) {
    int n_mbt = 0, n_cbbm = 0;
    const double mbt = mean_initiation(r, k, false, n_mbt),
                 cbbm = mean_initiation(r, k, true, n_cbbm);
    mean["initiation"][initiation_points(r.reduced.front().initiation)[k].first] = {
        {"G_MBT_J_m2", json_number(mbt)},
        {"G_CBBM_J_m2", json_number(cbbm)},
        {"records_MBT", n_mbt},
        {"records_CBBM", n_cbbm}};
  }
  block["mean"] = mean;
  bool any_equivalent = false, any_measured = false;
  for (const auto& x : r.reduced) {
    any_equivalent = any_equivalent || x.crack == "equivalent";
    any_measured = any_measured || x.crack == "measured";
  }
  if (any_equivalent && any_measured)
    block["notes"].push_back("records with and without crack readings: the mean mixes crack "
                             "extensions measured and equivalent (rcurve_test.csv column crack)");
  if (any_root && !all_root)
    block["notes"].push_back("delta_root measured on some records only: no rdelta_test.csv");
  return block;
}

} // namespace fiberbridge::app
