// The reduce step: records -> R(a) tables, summary block and plots (reduce_step.h).
#include "fiberbridge/app/reduce_step.h"

#include "fiberbridge/analysis/synthetic_data.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/plot.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <cmath>

namespace fiberbridge::app {

namespace {

using units::mm;

Json method_json(const analysis::MethodSummary& m) {
  return {{"initiation_J_m2", json_number(m.initiation)},
          {"plateau_J_m2", json_number(m.plateau)},
          {"plateau_std_J_m2", json_number(m.plateau_std)}};
}

Json methods_json(const analysis::MethodSummary& e, const analysis::MethodSummary& mbt,
                  const analysis::MethodSummary& cc, const analysis::MethodSummary& mcc) {
  return {{"energy", method_json(e)},
          {"MBT", method_json(mbt)},
          {"CC", method_json(cc)},
          {"MCC", method_json(mcc)}};
}

void write_tables(const ReduceOutcome& r, const std::string& out_dir) {
  const bool root = !r.reduced.front().delta_root.empty();
  std::vector<std::string> header = {
      "record",           "a_mm",       "da_mm",     "R_energy_J_m2", "R_energy_lo_J_m2",
      "R_energy_hi_J_m2", "R_MBT_J_m2", "R_CC_J_m2", "R_MCC_J_m2"};
  if (root) {
    header.push_back("delta_root_mm");
    header.push_back("R_delta_J_m2");
  }
  CsvWriter w(out_dir + "/rcurve_test.csv", header,
              {"R(a) per crack reading: direct energy (band +-2 x the larger of the local "
               "slope's standard error and the scatter of neighbouring estimates) and ASTM "
               "D5528 / ISO 15024 MBT, CC, MCC; R_delta is R_energy at the measured notch-root "
               "opening"});
  for (const auto& x : r.reduced)
    for (std::size_t i = 0; i < x.a.size(); ++i) {
      std::vector<double> v = {x.a[i] / mm,      x.da[i] / mm, x.R_energy[i], x.R_energy_lo[i],
                               x.R_energy_hi[i], x.R_MBT[i],   x.R_CC[i],     x.R_MCC[i]};
      if (root) {
        v.push_back(x.delta_root.empty() ? NAN : x.delta_root[i] / mm);
        v.push_back(x.delta_root.empty() ? NAN : x.R_energy[i]);
      }
      w.row({x.name}, v);
    }
  w.close();

  const auto& m = r.mean;
  CsvWriter mw(out_dir + "/rcurve_test_mean.csv",
               {"da_mm", "R_energy_J_m2", "R_energy_std_J_m2", "R_MBT_J_m2", "R_MBT_std_J_m2",
                "R_CC_J_m2", "R_CC_std_J_m2", "R_MCC_J_m2", "R_MCC_std_J_m2"},
               {"mean of " + std::to_string(m.n_records) +
                " record(s) on a common crack-extension grid; std = sample standard deviation "
                "over the records (0 for one)"});
  for (std::size_t i = 0; i < m.da.size(); ++i)
    mw.row({m.da[i] / mm, m.R_energy[i], m.R_energy_std[i], m.R_MBT[i], m.R_MBT_std[i], m.R_CC[i],
            m.R_CC_std[i], m.R_MCC[i], m.R_MCC_std[i]});
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

void plot(const ReduceOutcome& r, const std::string& out_dir, Json& summary) {
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
    summary["plots"].push_back("reduce_load_opening.png");
  if (run_gnuplot(out_dir, a + "\n"))
    summary["plots"].push_back("reduce_crack_opening.png");
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
         "using 2:(sel(9)) with lines lc 4 dt 2 title 'MCC'\n";
    if (run_gnuplot(out_dir, s))
      summary["plots"].push_back(png);
  }
}

} // namespace

ReduceOutcome run_reduce(const ReduceStepOptions& o, const std::string& out_dir, Json& summary) {
  if (o.files.empty())
    throw InputError(o.where + ": no record files given");
  o.specimen.check(o.where);
  ReduceOutcome r;
  for (const auto& f : o.files)
    for (auto& rec : analysis::read_test_records(f, o.read))
      r.records.push_back(std::move(rec));
  bool any_root = false, all_root = true;
  for (const auto& rec : r.records) {
    for (const auto& other : r.reduced)
      if (other.name == rec.name)
        throw InputError(rec.source + ": record name '" + rec.name +
                         "' repeats a record already read; give each record its own name");
    r.reduced.push_back(analysis::reduce_record(rec, o.specimen, o.reduce));
    any_root = any_root || !rec.delta_root.empty();
    all_root = all_root && !rec.delta_root.empty();
  }
  r.mean = analysis::average_reduced(r.reduced, o.reduce.plateau_fraction);
  write_tables(r, out_dir);
  if (any_root && all_root)
    analysis::write_rdelta_csv(out_dir + "/rdelta_test.csv",
                               analysis::to_rdelta(r.reduced, "reduce"),
                               {"R(delta_root) from the direct-energy R(a) of the records with "
                                "a measured notch-root opening (fiberbridge reduce)"});

  Json block;
  block["width_mm"] = o.specimen.width / mm;
  block["arm_thickness_mm"] = o.specimen.arm_thickness / mm;
  block["plateau_definition"] = "mean over the last " + std::to_string(o.reduce.plateau_fraction) +
                                " of each record's crack extension";
  block["initiation_definition"] = "value at the first crack reading beyond a0 (visual onset)";
  block["records"] = Json::array();
  for (const auto& x : r.reduced) {
    Json j = {{"name", x.name},
              {"source", x.source},
              {"a0_mm", x.a0 / mm},
              {"readings", x.a.size()},
              {"crack_extension_mm", x.da.back() / mm},
              {"smoothing_window_mm", x.window / mm},
              {"MBT_Delta_mm", x.mbt_delta / mm},
              {"CC_n", x.cc_n},
              {"MCC_A1", x.mcc_A1},
              {"max_opening_over_a", x.max_opening_over_a},
              {"delta_root_measured", !x.delta_root.empty()}};
    j.update(methods_json(x.energy, x.mbt, x.cc, x.mcc));
    j["cleaning"] = x.cleaning;
    j["notes"] = x.notes;
    block["records"].push_back(j);
  }
  Json mean = {{"n_records", r.mean.n_records}, {"crack_extension_mm", r.mean.da.back() / mm}};
  mean.update(methods_json(r.mean.energy, r.mean.mbt, r.mean.cc, r.mean.mcc));
  block["mean"] = mean;
  if (any_root && !all_root)
    block["notes"].push_back("delta_root measured on some records only: no rdelta_test.csv");
  summary["reduce"] = block;
  plot(r, out_dir, summary);
  return r;
}

} // namespace fiberbridge::app
