// Writers of `chain study` (chain_study_writers.h).
#include "outputs/chain_study_writers.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/plot.h"
#include "fiberbridge/core/summary.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace fiberbridge::app {

namespace {

double rel(double got, double truth) {
  return std::isfinite(got) && truth != 0 ? (got - truth) / truth : std::nan("");
}

/// A cell of text: the CSV's comma and the line end would break the row.
std::string cell(std::string s) {
  for (char& c : s)
    if (c == ',' || c == '\n' || c == '\r')
      c = c == ',' ? ';' : ' ';
  return s;
}

/// The rows varying `factor`, with the base at `base_value`, sorted by value, as a gnuplot data
/// file of relative errors in % (refused cases left out: they have no error).
bool plot_factor(const SceneContext& ctx, const std::vector<ChainRow>& rows,
                 const std::string& factor, double base_value, const std::string& xlabel,
                 const std::string& png, bool log_x) {
  std::vector<const ChainRow*> pts;
  for (const auto& r : rows)
    if ((r.factor == factor || r.factor == "base") && r.outcome == "recovered")
      pts.push_back(&r);
  if (pts.size() < 2)
    return false;
  auto x_of = [&](const ChainRow* r) { return r->factor == "base" ? base_value : r->value; };
  std::sort(pts.begin(), pts.end(), [&](auto a, auto b) { return x_of(a) < x_of(b); });
  const std::string data = "chain_recovery_" + factor + ".dat";
  {
    std::ofstream f(ctx.out(data));
    f << "# " << factor
      << " J_tip_err_pct G_ss_err_pct delta_c_err_pct sigma1_err_pct sigma2_err_pct law_L2_pct\n";
    for (const ChainRow* r : pts)
      f << x_of(r) << ' ' << 100 * rel(r->j_tip, r->j_tip_true) << ' '
        << 100 * rel(r->g_ss, r->g_ss_true) << ' ' << 100 * rel(r->delta_c, r->delta_c_true) << ' '
        << 100 * rel(r->sigma1, r->sigma1_true) << ' ' << 100 * rel(r->sigma2, r->sigma2_true)
        << ' ' << 100 * r->law_l2_rel << '\n';
  }
  std::ostringstream s;
  s << gnuplot_png_preamble(png) << "set xlabel '" << xlabel << "'\n"
    << "set ylabel 'error of the recovered value [%]'\nset grid\nset key outside right\n"
    << (log_x ? "set logscale x 2\n" : "") << "plot '" << data
    << "' u 1:2 w lp t 'J_{tip}', '' u 1:3 w lp t 'G_{ss}', '' u 1:4 w lp t '{/Symbol d}_c', "
       "'' u 1:5 w lp t '{/Symbol s}_1', '' u 1:6 w lp t '{/Symbol s}_2', '' u 1:7 w lp t 'law "
       "L2'\n";
  return run_gnuplot(ctx.output_dir, s.str());
}

/// chain_identify.csv: identify's recovery beside the chain's (only the cases where it ran).
void write_identified(const SceneContext& ctx, const std::vector<ChainRow>& rows,
                      ItemReport& report) {
  if (std::none_of(rows.begin(), rows.end(),
                   [](const ChainRow& r) { return !r.identified.outcome.empty(); }))
    return;
  CsvWriter w(ctx.out("chain_identify.csv"),
              {"case", "table1_law", "outcome", "reason", "J_tip_J_m2", "J_tip_err_rel",
               "G_ss_J_m2", "G_ss_err_rel", "delta_c_mm", "delta_c_err_rel", "sigma1_kPa",
               "sigma1_err_rel", "sigma2_kPa", "sigma2_err_rel", "law_L2_err_rel",
               "chain_law_L2_err_rel", "identify_wall_time_s"},
              {"chain study, identify (issue 39): `dic, identify` on each virtual test (machine "
               "record and DIC crack lengths, no delta_root; the beam forward model); the "
               "identified trilinear's sigma at d1 = 0.1 mm and d2 = 1.0 mm against the truth "
               "of chain_recovery.csv; chain_law_L2_err_rel: the chain's (extract, fit) beside"});
  Json cases = Json::array();
  for (const auto& r : rows) {
    const auto& id = r.identified;
    if (id.outcome.empty())
      continue;
    w.row({r.name, r.table1 ? "1" : "0", id.outcome, cell(id.reason)},
          {id.j_tip, rel(id.j_tip, r.j_tip_true), id.g_ss, rel(id.g_ss, r.g_ss_true), id.delta_c,
           rel(id.delta_c, r.delta_c_true), id.sigma1, rel(id.sigma1, r.sigma1_true), id.sigma2,
           rel(id.sigma2, r.sigma2_true), id.law_l2_rel, r.law_l2_rel, id.wall_s});
    cases.push_back({{"case", r.name},
                     {"outcome", id.outcome},
                     {"J_tip_err_rel", json_number(rel(id.j_tip, r.j_tip_true))},
                     {"G_ss_err_rel", json_number(rel(id.g_ss, r.g_ss_true))},
                     {"delta_c_err_rel", json_number(rel(id.delta_c, r.delta_c_true))},
                     {"sigma1_err_rel", json_number(rel(id.sigma1, r.sigma1_true))},
                     {"sigma2_err_rel", json_number(rel(id.sigma2, r.sigma2_true))},
                     {"law_L2_err_rel", json_number(id.law_l2_rel)}});
  }
  w.close();
  report["chain_study_identify"] = {{"table_file", "chain_identify.csv"}, {"cases", cases}};
}

} // namespace

void write_chain_study(const SceneContext& ctx, const std::vector<ChainRow>& rows, double wall_s,
                       ItemReport& report) {
  CsvWriter w(ctx.out("chain_recovery.csv"),
              {"case",
               "factor",
               "outcome",
               "stage",
               "targets_met",
               "missed",
               "reason",
               "correction",
               "value",
               "table1_law",
               "J_tip_true_J_m2",
               "J_tip_J_m2",
               "J_tip_err_rel",
               "G_ss_true_J_m2",
               "G_ss_J_m2",
               "G_ss_err_rel",
               "delta_c_true_mm",
               "delta_c_mm",
               "delta_c_err_rel",
               "sigma1_true_kPa",
               "sigma1_kPa",
               "sigma1_err_rel",
               "sigma2_true_kPa",
               "sigma2_kPa",
               "sigma2_err_rel",
               "law_L2_err_rel",
               "fem_wall_time_s",
               "chain_wall_time_s",
               "J_tip_uncorrected_J_m2",
               "G_ss_uncorrected_J_m2",
               "delta_c_uncorrected_mm",
               "sigma1_uncorrected_kPa",
               "sigma2_uncorrected_kPa"},
              {"chain study (issue 39 item 1): virtual tests (FEM/Virtual DIC) through the "
               "measuring chain as a user runs it (dic, reduce, extract, fit on the written "
               "dic_scene.prm); truth from the case's Cohesive law; sigma at d1 = 0.1 mm and "
               "d2 = 1.0 mm; err_rel = (recovered - true) / true; law L2 over [0, true delta_c]",
               "correction: converged = the recovered J_tip, delta_c, sigma1, sigma2 are the fit "
               "corrected by simulation (Fit/Model correction) and G_ss its J_tip + J1 + J2, "
               "*_uncorrected the seed's fit and extract's plateau G_ss beside"});
  for (const auto& r : rows)
    w.row({r.name, r.factor, r.outcome, r.stage, r.targets_met ? "yes" : "no", cell(r.missed),
           cell(r.reason), r.correction},
          {r.value,
           r.table1 ? 1.0 : 0.0,
           r.j_tip_true,
           r.j_tip,
           rel(r.j_tip, r.j_tip_true),
           r.g_ss_true,
           r.g_ss,
           rel(r.g_ss, r.g_ss_true),
           r.delta_c_true,
           r.delta_c,
           rel(r.delta_c, r.delta_c_true),
           r.sigma1_true,
           r.sigma1,
           rel(r.sigma1, r.sigma1_true),
           r.sigma2_true,
           r.sigma2,
           rel(r.sigma2, r.sigma2_true),
           r.law_l2_rel,
           r.fem_wall_s,
           r.chain_wall_s,
           r.uncorrected.j_tip,
           r.uncorrected.g_ss,
           r.uncorrected.delta_c,
           r.uncorrected.sigma1,
           r.uncorrected.sigma2});
  w.close();

  write_identified(ctx, rows, report);

  Json block = Json::object();
  int n_refused = 0, n_met = 0, n_t1 = 0, n_t1_met = 0, n_t1_refused = 0;
  Json cases = Json::array();
  for (const auto& r : rows) {
    n_refused += r.outcome != "recovered";
    n_met += r.targets_met;
    if (r.table1) {
      ++n_t1;
      n_t1_met += r.targets_met;
      n_t1_refused += r.outcome != "recovered";
    }
    cases.push_back({{"case", r.name},
                     {"outcome", r.outcome},
                     {"targets_met", r.targets_met},
                     {"missed", r.missed},
                     {"reason", r.reason},
                     {"correction", r.correction},
                     {"J_tip_uncorrected_J_m2", json_number(r.uncorrected.j_tip)},
                     {"G_ss_uncorrected_J_m2", json_number(r.uncorrected.g_ss)},
                     {"delta_c_uncorrected_mm", json_number(r.uncorrected.delta_c)},
                     {"sigma1_uncorrected_kPa", json_number(r.uncorrected.sigma1)},
                     {"sigma2_uncorrected_kPa", json_number(r.uncorrected.sigma2)},
                     {"J_tip_true_J_m2", r.j_tip_true},
                     {"J_tip_J_m2", json_number(r.j_tip)},
                     {"G_ss_true_J_m2", r.g_ss_true},
                     {"G_ss_J_m2", json_number(r.g_ss)},
                     {"delta_c_true_mm", r.delta_c_true},
                     {"delta_c_mm", json_number(r.delta_c)},
                     {"sigma1_true_kPa", r.sigma1_true},
                     {"sigma1_kPa", json_number(r.sigma1)},
                     {"sigma2_true_kPa", r.sigma2_true},
                     {"sigma2_kPa", json_number(r.sigma2)},
                     {"J_tip_err_rel", json_number(rel(r.j_tip, r.j_tip_true))},
                     {"G_ss_err_rel", json_number(rel(r.g_ss, r.g_ss_true))},
                     {"delta_c_err_rel", json_number(rel(r.delta_c, r.delta_c_true))},
                     {"sigma1_err_rel", json_number(rel(r.sigma1, r.sigma1_true))},
                     {"sigma2_err_rel", json_number(rel(r.sigma2, r.sigma2_true))},
                     {"law_L2_err_rel", json_number(r.law_l2_rel)}});
  }
  block["table_file"] = "chain_recovery.csv";
  block["n_cases"] = rows.size();
  block["n_refused"] = n_refused;
  block["n_targets_met"] = n_met;
  block["table1_cases"] = n_t1;
  block["table1_targets_met"] = n_t1_met;
  block["table1_refused"] = n_t1_refused;
  block["wall_time_s"] = wall_s;
  block["cases"] = cases;
  report["chain_study"] = block;
  // Base values: 1 Hz, 0.002 mm noise (the scene's own; prm/study_chain.prm).
  if (plot_factor(ctx, rows, "frame_rate_Hz", 1.0, "frame rate [Hz]",
                  "chain_recovery_vs_frame_rate.png", true))
    report.plots.push_back("chain_recovery_vs_frame_rate.png");
  if (plot_factor(ctx, rows, "noise_mm", 0.002, "displacement noise [mm]",
                  "chain_recovery_vs_noise.png", false))
    report.plots.push_back("chain_recovery_vs_noise.png");
}

} // namespace fiberbridge::app
