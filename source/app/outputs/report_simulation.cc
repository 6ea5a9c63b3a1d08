#include "fiberbridge/app/scene/scene_context.h"
#include "fiberbridge/core/plot.h"
#include "fiberbridge/core/units.h"

#include <cmath>

namespace fiberbridge::app {

ItemOutcome report_simulation(const SceneContext& ctx, result::SimulationResult r,
                              const std::string& size_key) {
  ItemOutcome outcome;
  const CrackLaw& crack_law = ctx.crack_law();
  const auto law = crack_law.law;
  const double j_tip = crack_law.j_tip;
  // r.rdelta_rel_error_vs_eq2 is the model's own (result::finish_rcurve, or the beam's same
  // call), against this law and J_tip.
  const std::string csv = "rcurve_" + r.model + ".csv";
  result::write_rcurve_csv(ctx.out(csv), r);
  const double G_ss_law = j_tip + law->area();
  Json block = {{"law", law->name()},
                {"law_source", law_source_name(crack_law.source)},
                {"J_tip_J_m2", j_tip},
                {"G_ss_J_m2", json_number(r.G_ss)},
                {"G_ss_law_J_m2", G_ss_law},
                {"G_ss_rel_error", json_number((r.G_ss - G_ss_law) / G_ss_law)},
                {"reached_steady_state", r.reached_steady_state},
                {"steady_state_status", result::to_string(r.steady_state_status)},
                {"wall_time_s", json_number(r.wall_time_s)},
                {size_key, r.n_dofs_or_particles},
                {"rdelta_rel_error_vs_eq2", json_number(r.rdelta_rel_error_vs_eq2)},
                {"tip_advances", r.rcurve.size()},
                {"rcurve_file", csv},
                {"notes", r.notes},
                {"method", r.method}};
  if (!r.rcurve.empty()) {
    double peak_load = 0;
    for (const auto& p : r.rcurve)
      if (std::isfinite(p.load))
        peak_load = std::max(peak_load, p.load);
    block["peak_load_N"] = peak_load;
    block["final_crack_length_mm"] = json_number(r.rcurve.back().a / units::mm);
  }
  outcome.report[r.model] = block;

  std::string s = gnuplot_png_preamble("rcurve_" + r.model + ".png");
  s += "set title '" + r.model +
       ": R(a)'\nset xlabel 'crack-tip position a (mm)'\n"
       "set ylabel 'R (J/m^2)'\nset key bottom right\n";
  s += "plot '" + csv + "' using 1:3 with linespoints title 'R_{energy}', '" + csv +
       "' using 1:4 with lines lw 2 title 'R_J', '" + csv +
       "' using 1:5 with lines lw 2 dt 2 title 'Eq. 2 at {/Symbol d}_{root}', " +
       std::to_string(G_ss_law) + " with lines dt 3 title 'J_{tip} + J_c'\n";
  if (run_gnuplot(ctx.output_dir, s))
    outcome.report.plots.push_back("rcurve_" + r.model + ".png");
  outcome.simulation = std::move(r);
  return outcome;
}

} // namespace fiberbridge::app
