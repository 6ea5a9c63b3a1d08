// The tables, plot and summary block of `study` (study_writers.h).
#include "outputs/study_writers.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/plot.h"

namespace fiberbridge::app {

void write_study_ladders(const SceneContext& ctx, const std::vector<LadderOutcome>& ladders,
                         Json& block, ItemReport& report) {
  CsvWriter w(ctx.out("study_error_vs_time.csv"),
              {"model", "level", "n_dofs_or_particles", "wall_time_s", "rdelta_rel_error",
               "G_ss_rel_error"},
              {"settings per level in summary.json (study.error_vs_time)",
               "rdelta_rel_error: relative L2 of R_J (Eq. 2 with J measured) against Eq. 2 of "
               "the law over the developing part; G_ss_rel_error against J_tip + law area"});
  Json rows = Json::array();
  std::string plot = gnuplot_png_preamble("study_error_vs_time.png");
  plot += "set logscale xy\nset xlabel 'wall time (s)'\nset ylabel 'relative error'\n"
          "set key top right\nplot ";
  bool first_plot = true;
  // The ladders run the scene's law and specimen set-up: say where they came from.
  block["law_source"] = law_source_name(ctx.crack_law().source);
  block["specimen_source"] = specimen_source_name(ctx.specimen_setup().source);
  for (const auto& ladder : ladders) {
    const auto& model = ladder.model;
    const std::string csv = "study_" + model + ".csv";
    CsvWriter mw(ctx.out(csv),
                 {"wall_time_s", "rdelta_rel_error", "G_ss_rel_error", "peak_load_N",
                  "observed_order_rdelta", "observed_order_G_ss", "observed_order_peak_load"},
                 {model + " ladder; orders from successive levels, taking the ratio of the "
                          "first varied key's values as the refinement factor"});
    for (std::size_t l = 0; l < ladder.levels.size(); ++l) {
      const auto& L = ladder.levels[l];
      w.row({model, std::to_string(l)}, {double(L.r.n_dofs_or_particles), L.r.wall_time_s,
                                         L.r.rdelta_rel_error_vs_eq2, L.g_err});
      mw.row({L.r.wall_time_s, L.r.rdelta_rel_error_vs_eq2, L.g_err, L.peak, L.order_rdelta,
              L.order_G_ss, L.order_peak});
      rows.push_back({{"model", model},
                      {"level", l},
                      {"setting", L.setting},
                      {"n_dofs_or_particles", L.r.n_dofs_or_particles},
                      {"wall_time_s", json_number(L.r.wall_time_s)},
                      {"rdelta_rel_error", json_number(L.r.rdelta_rel_error_vs_eq2)},
                      {"G_ss_rel_error", json_number(L.g_err)},
                      {"peak_load_N", L.peak},
                      {"observed_order_rdelta", json_number(L.order_rdelta)},
                      {"observed_order_G_ss", json_number(L.order_G_ss)},
                      {"observed_order_peak_load", json_number(L.order_peak)},
                      {"reached_steady_state", L.r.reached_steady_state},
                      {"rank", L.rank},
                      {"cpu_s", L.cpu_s}});
    }
    const int cheapest = ladder.cheapest;
    block["cheapest"][model] = cheapest < 0
                                   ? Json("no level reached " + std::to_string(ladder.target))
                                   : Json({{"level", cheapest},
                                           {"setting", ladder.levels[cheapest].setting},
                                           {"target", ladder.target},
                                           {"wall_time_s", ladder.levels[cheapest].r.wall_time_s}});
    mw.close();
    plot += std::string(first_plot ? "" : ", ") + "'" + csv +
            "' using 1:2 with linespoints lw 2 title '" + model + " R_J vs Eq. 2', '" + csv +
            "' using 1:3 with linespoints lw 2 dt 2 title '" + model + " G_{ss}'";
    first_plot = false;
  }
  w.close();
  plot += "\n";
  if (run_gnuplot(ctx.output_dir, plot))
    report.plots.push_back("study_error_vs_time.png");
  block["error_vs_time"] = rows;
}

void write_study_stability(const SceneContext& ctx, const std::vector<Json>& rows, Json& block) {
  CsvWriter w(ctx.out("stability.csv"), {"case", "model", "outcome", "diagnosis", "wall_time_s"},
              {"outcome: converged (plateau within the tolerance of J_tip + area) | diagnosed "
               "stop (the model said why it stopped) | suspect | failure"});
  Json out = Json::array();
  for (const auto& row : rows) {
    w.row({row["case"].get<std::string>(), row["model"].get<std::string>(),
           row["outcome"].get<std::string>(), row["diagnosis"].get<std::string>()},
          {row["wall_time_s"].get<double>()});
    out.push_back(row);
  }
  w.close();
  block["stability"] = out;
}

} // namespace fiberbridge::app
