// Tables, plots and the summary block of the dic step (dic_writers.h).
#include "outputs/dic_writers.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/median.h"
#include "fiberbridge/core/plot.h"

#include <algorithm>
#include <cmath>

namespace fiberbridge::app {

namespace {

constexpr double to_mm = 1e3;

/// Up to `k` used frames evenly spread over the used ones (first and last included).
std::vector<std::size_t> spread_used(const dic::DicAnalysis& a, std::size_t k) {
  std::vector<std::size_t> used;
  for (std::size_t i = 0; i < a.frames.size(); ++i)
    if (a.frames[i].used)
      used.push_back(i);
  if (used.size() <= k)
    return used;
  std::vector<std::size_t> pick;
  for (std::size_t j = 0; j < k; ++j)
    pick.push_back(used[j * (used.size() - 1) / (k - 1)]);
  return pick;
}

} // namespace

void write_dic_frames(const std::string& out_dir, const DicStepOptions& o,
                      const dic::DicAnalysis& a) {
  CsvWriter w(out_dir + "/dic_frames.csv",
              {"frame", "image_number", "time_s", "used", "tip_reading_mm", "tip_reading_sd_mm",
               "s_tip_mm", "s_tip_sd_mm", "a_mm", "delta_root_mm", "delta_root_sd_mm",
               "strain_noise", "n_points", "n_failed", "n_stations"},
              {"one row per DIC frame; s from the notch root along the growth direction; "
               "tip_reading: this frame's threshold point, s_tip: tracked (never behind an "
               "earlier one); notes per frame in summary.json dic.frame_notes"});
  for (std::size_t i = 0; i < a.frames.size(); ++i) {
    const auto& f = a.frames[i];
    w.row({static_cast<double>(i), static_cast<double>(f.file.number), f.time, f.used ? 1.0 : 0.0,
           f.tip.s * to_mm, f.tip.sd * to_mm, f.s_tip * to_mm, f.s_tip_sd * to_mm,
           f.used ? (o.initial_crack + f.s_tip) * to_mm : NAN, f.extensometer.opening * to_mm,
           f.extensometer.sd * to_mm, f.tip.noise, static_cast<double>(f.n_points),
           static_cast<double>(f.n_failed), static_cast<double>(f.profile.s.size())});
  }
  w.close();
}

void plot_dic(const std::string& out_dir, const DicStepOptions& o, const DicOutcome& r,
              ItemReport& report) {
  const auto& a = r.analysis;
  const auto picked = spread_used(a, 6);
  if (picked.empty())
    return;
  {
    CsvWriter w(
        out_dir + "/dic_profiles.csv", {"frame", "time_s", "s_mm", "eyy"},
        {"crack-normal strain on the crack plane at up to six frames (the paper's Fig. 2)"});
    for (const std::size_t i : picked)
      for (std::size_t k = 0; k < a.frames[i].profile.s.size(); ++k)
        w.row({static_cast<double>(i), a.frames[i].time, a.frames[i].profile.s[k] * to_mm,
               a.frames[i].profile.eyy[k]});
    w.close();
  }
  std::string p = gnuplot_png_preamble("dic_strain_profiles.png");
  p += "set termoption noenhanced\nset xlabel 's from the notch root along the crack plane (mm)'\n"
       "set ylabel 'strain normal to the crack plane'\nset key top right\nset yrange [*:" +
       fmt(6 * o.dic.tip.threshold) + "]\nplot ";
  for (std::size_t j = 0; j < picked.size(); ++j)
    p += "'dic_profiles.csv' using ($1 == " + std::to_string(picked[j]) +
         " ? $3 : 1/0):4 with linespoints pt 7 ps 0.4 title 't = " + fmt(a.frames[picked[j]].time) +
         " s', ";
  p += fmt(o.dic.tip.threshold) + " with lines lw 2 dt 2 lc rgb 'black' title 'threshold " +
       fmt(100 * o.dic.tip.threshold) + " %'\n";
  if (run_gnuplot(out_dir, p))
    report.plots.push_back("dic_strain_profiles.png");

  std::string c = gnuplot_png_preamble("dic_crack_and_root.png");
  c += "set termoption noenhanced\nset xlabel 'time (s)'\nset ylabel 'crack length a (mm)'\n"
       "set y2label 'delta_root (mm)'\nset y2tics\nset ytics nomirror\nset key top left\n"
       "plot 'dic_record.csv' using 1:4:6 with yerrorlines pt 7 ps 0.4 title 'a (DIC, 1 sd)', "
       "'' using 1:5:7 axes x1y2 with yerrorlines pt 6 ps 0.4 title 'delta_root (extensometer)'\n";
  if (run_gnuplot(out_dir, c))
    report.plots.push_back("dic_crack_and_root.png");

  // One frame's field: the last used one, read again (the analysis keeps no fields).
  const std::size_t last = picked.back();
  const auto& lf = a.frames[last];
  const dic::PlaneFrame f =
      dic::to_crack_coordinates(dic::read_frame(lf.file.path, o.dic.read), o.dic.geometry);
  {
    CsvWriter w(out_dir + "/dic_field.csv", {"s_mm", "n_mm", "eyy"},
                {"frame " + lf.file.path + " at t = " + fmt(lf.time) +
                 " s in crack coordinates (valid points)"});
    for (std::size_t i = 0; i < f.s.size(); ++i)
      if (f.valid[i])
        w.row({f.s[i] * to_mm, f.n[i] * to_mm, f.eyy[i]});
    w.close();
  }
  const double g = 0.5 * o.dic.gauge_length * to_mm;
  std::string fp = gnuplot_png_preamble("dic_field.png", 1000, 500);
  fp += "set termoption noenhanced\nset title 'strain normal to the crack plane, t = " +
        fmt(lf.time) +
        " s'\nset xlabel 's (mm)'\nset ylabel 'n (mm)'\nset cblabel 'eyy'\n"
        "set cbrange [0:" +
        fmt(3 * o.dic.tip.threshold) +
        "]\nset palette rgb 33,13,10\nset key outside bottom center horizontal\n"
        "$tip << EOD\n" +
        fmt(lf.s_tip * to_mm, 8) + ",0\nEOD\n$ext << EOD\n0," + fmt(g, 8) + "\n0," + fmt(-g, 8) +
        "\nEOD\nplot 'dic_field.csv' using 1:2:3 with points pt 5 ps 0.5 palette notitle, "
        "$tip using 1:2 with points pt 9 ps 3 lc rgb 'black' title 'tip (" +
        fmt(100 * o.dic.tip.threshold) +
        " % rule)', $ext using 1:2 with linespoints pt 2 ps 2 lw 2 lc rgb 'green' title "
        "'extensometer'\n";
  if (run_gnuplot(out_dir, fp))
    report.plots.push_back("dic_field.png");
}

Json dic_summary(const DicStepOptions& o, const DicOutcome& r,
                 const std::vector<std::string>& record_notes) {
  const auto& a = r.analysis;
  Json j;
  j["frames_read"] = a.frames.size();
  j["frames_used"] = a.frames_used;
  j["rows_written"] = r.rows.size();
  j["points_used"] = a.points_used;
  j["points_failed"] = a.points_failed;
  j["layout"] = dic::layout_name(a.layout);
  j["columns"] = a.columns_used;
  j["strain_factor"] = a.strain_factor;
  j["point_spacing_mm"] = json_number(a.spacing * to_mm);
  j["tip_rule"] = {
      {"threshold", o.dic.tip.threshold},
      {"strain", "crack-normal strain on the crack plane, interpolated from the nearest valid "
                 "point above and below it, one station per column of points"},
      {"tip", "end of the run of stations at or above the threshold that starts at the notch "
              "root; one station below it bridged over; linear crossing"},
      {"tracking", "never heals: the tip is the furthest reading so far"},
      {"bridged_dips", o.dic.tip.bridged_dips}};
  j["extensometer"] = {{"gauge_length_mm", o.dic.gauge_length * to_mm},
                       {"points_per_fit", o.dic.points_per_fit},
                       {"fit", "local least-squares plane v = a + b s + c n per point, own side "
                               "of the crack, failed points excluded"}};
  j["clock"] = {{"time_source", dic::frame_time_source_name(a.time_source)},
                {"frame_rate_Hz", o.dic.clock.frame_rate},
                {"first_frame_time_s", o.dic.clock.first_frame_time}};
  j["machine_record"] = o.machine_record;
  j["initial_crack_mm"] = o.initial_crack * to_mm;
  j["record"] = "dic_record.csv";
  std::vector<double> noise, tip_sd, root_sd;
  for (const auto& f : a.frames)
    if (f.used) {
      noise.push_back(f.tip.noise);
      tip_sd.push_back(f.s_tip_sd);
      root_sd.push_back(f.extensometer.sd);
    }
  j["strain_noise_median"] = json_number(median_upper(noise));
  j["tip_sd_median_mm"] = json_number(median_upper(tip_sd) * to_mm);
  j["delta_root_sd_median_mm"] = json_number(median_upper(root_sd) * to_mm);
  if (!r.rows.empty()) {
    j["final_a_mm"] = r.rows.back().a * to_mm;
    j["final_delta_root_mm"] = r.rows.back().delta_root * to_mm;
  }
  j["frame_notes"] = Json::array();
  for (std::size_t i = 0; i < a.frames.size(); ++i)
    for (const auto& n : a.frames[i].notes)
      j["frame_notes"].push_back({{"frame", i}, {"file", a.frames[i].file.path}, {"note", n}});
  j["notes"] = record_notes;
  j["algorithm_wall_time_s"] = a.wall_time_s;
  return j;
}

} // namespace fiberbridge::app
