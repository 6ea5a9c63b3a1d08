// Scene item `chain study` (issue 39 item 1; docs/design.md, "Virtual tests as the chain's
// verification"): for each case, the FEM writes a virtual test (FEM/Virtual DIC: frames,
// machine.csv, virtual_test_truth.csv, dic_scene.prm), then the measuring chain runs on what it
// wrote exactly as a user runs it: the generated dic_scene.prm through the scene runner with
// `Run = dic, reduce, extract, fit`. Nothing of the chain is re-implemented here, so a change to
// any estimator shows in this study's table without touching it. A refusal by the chain is a row
// of the table with its reason, never a failure of the study.
#include "items/chain_study_cases.h"
#include "items/virtual_test_run.h"
#include "outputs/chain_study_writers.h"

#include "fiberbridge/app/items/items.h"
#include "fiberbridge/app/run/scene_runner.h"
#include "fiberbridge/app/scene/scene_reader.h"
#include "fiberbridge/app/scene/section.h"
#include "fiberbridge/core/clock.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/law/law_spec.h"
#include "items/chain_study_item.h"

#include <deal.II/base/patterns.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace fiberbridge::app {

using namespace units;

namespace {

namespace fs = std::filesystem;

struct ChainStudySection {
  std::string cases;
  std::string table1;
  std::string chain_run;
  std::string model_correction;
  bool reuse = true;
  bool identify = false;

  static void declare_parameters(dealii::ParameterHandler& prm) {
    prm.declare_entry("Cases", "all", dealii::Patterns::Anything(),
                      "all, or case names separated by commas: base, the Table 1 laws "
                      "(PVA_c0 ... DF_c24), linear, bilinear, exponential, short_zone, long_zone, "
                      "dice, gom, y_down, px, dice_px_y_down, noise_<mm>, failed_<fraction>, "
                      "frame_rate_<Hz>, crosshead_<mm/min> (chain_recovery.csv lists them).");
    prm.declare_entry("Table 1", "data/reference/seed_table1.csv", dealii::Patterns::Anything(),
                      "The laws of the Table 1 cases (seed_table1.csv's format), relative to the "
                      "working directory or the scene file.");
    prm.declare_entry("Reuse virtual tests", "true", dealii::Patterns::Bool(),
                      "Keep a case's virtual test from an earlier run into the same output "
                      "directory when it was made from the same scene text and settings: the FEM "
                      "does not change when the chain's estimators do (the chain always runs).");
    prm.declare_entry("Identify", "false", dealii::Patterns::Bool(),
                      "Also run `dic, identify` on each virtual test (the machine record with the "
                      "DIC crack lengths, no delta_root; the Identify section's defaults: the beam "
                      "forward model) and tabulate its recovery in chain_identify.csv (about 20 s "
                      "a case).");
    prm.declare_entry("Chain run", "dic, reduce, extract, fit", dealii::Patterns::Anything(),
                      "The Run list set on each generated dic_scene.prm: the chain as a user runs "
                      "it on a virtual test.");
    prm.declare_entry("Model correction", "", dealii::Patterns::Selection("|auto|none|beam|fem"),
                      "Fit/Model correction set on each chain scene; empty: the scene's default "
                      "(auto). beam measures the chain as a campaign's groups correct it "
                      "(scripts/chain_accuracy.py; docs/verification.md, \"The correction's "
                      "records reduced with the measured windows\").");
  }
  void parse_parameters(dealii::ParameterHandler& prm) {
    cases = prm.get("Cases");
    table1 = prm.get("Table 1");
    chain_run = prm.get("Chain run");
    model_correction = prm.get("Model correction");
    reuse = prm.get_bool("Reuse virtual tests");
    identify = prm.get_bool("Identify");
  }
};

/// The recovered numbers from the chain scene's summary.json (analysis_steps.cc writes them).
void read_recovered(const std::string& summary_path, ChainRow& row) {
  std::ifstream f(summary_path);
  if (!f)
    throw ComputationError("chain study: the chain's scene left no " + summary_path);
  const Json s = Json::parse(f);
  auto get = [](const Json& j, const char* key) {
    return j.contains(key) && j[key].is_number() ? j[key].get<double>() : std::nan("");
  };
  row.j_tip = get(s, "J_tip_J_m2");
  row.g_ss = get(s, "G_ss_J_m2");
  row.delta_c = get(s, "delta_c_mm");
  if (s.contains("trilinear")) {
    row.sigma1 = get(s["trilinear"], "sigma1_kPa");
    row.sigma2 = get(s["trilinear"], "sigma2_kPa");
  }
  // The fit corrected by simulation (Fit/Model correction) is what the chain hands on: the
  // recovery is its, and the seed's fit stays beside.
  if (s.contains("fit_correction")) {
    row.uncorrected = {row.j_tip, row.g_ss, row.delta_c, row.sigma1, row.sigma2};
    const bool converged = s["fit_correction"].value("converged", false);
    row.correction = converged ? "converged" : "not converged";
    if (converged) {
      const Json& c = s["trilinear_corrected"];
      row.j_tip = get(c, "J_tip_J_m2");
      // The corrected law's own G_ss (J_tip + J1 + J2): the law the chain hands on. It also
      // loses the plateau's overshoot past delta_c and, with a model that holds the specimen's
      // far end, its cut-short plateau (docs/verification.md, "The specimen's far end in the
      // chain").
      row.g_ss = get(c, "G_ss_J_m2");
      row.delta_c = get(c, "delta_c_mm");
      row.sigma1 = get(c, "sigma1_kPa");
      row.sigma2 = get(c, "sigma2_kPa");
    }
  }
}

/// The fitted trilinear (0,0) (d1,s1) (d2,s2) (dc,0) at delta [kPa, mm].
double trilinear_at(double d, double d1, double s1, double d2, double s2, double dc) {
  if (!(d >= 0) || d >= dc)
    return 0;
  if (d < d1)
    return s1 * d / d1;
  if (d < d2)
    return s1 + (s2 - s1) * (d - d1) / (d2 - d1);
  return s2 * (dc - d) / (dc - d2);
}

/// ||fit - law||_2 / ||law||_2 over [0, law's delta_c] (midpoint rule, 4000 cells: the laws'
/// kinks cost < 0.1 % of the norm there).
double law_l2_error(const law::TractionLaw& truth, const ChainRow& r, double d1_mm, double d2_mm) {
  if (!std::isfinite(r.sigma1) || !std::isfinite(r.sigma2) || !std::isfinite(r.delta_c))
    return std::nan("");
  const double dc = truth.critical_opening() / mm;
  const int n = 4000;
  double num = 0, den = 0;
  for (int i = 0; i < n; ++i) {
    const double d = (i + 0.5) * dc / n;
    const double t = truth.envelope(d * mm) / kPa;
    const double e = trilinear_at(d, d1_mm, r.sigma1, d2_mm, r.sigma2, r.delta_c) - t;
    num += e * e;
    den += t * t;
  }
  return den > 0 ? std::sqrt(num / den) : std::nan("");
}

/// The identified law from `identify`'s block of summary.json: its trilinear evaluated at the
/// paper's d1 and d2 (identify frees the breakpoints), J_tip, G_ss, delta_c, L2 against `truth`.
void read_identified(const std::string& summary_path, const law::TractionLaw& truth, double d1,
                     double d2, ChainRow::Identified& id) {
  std::ifstream f(summary_path);
  if (!f)
    throw ComputationError("chain study: identify left no " + summary_path);
  const Json s = Json::parse(f).at("identify");
  auto get = [](const Json& j, const char* key) {
    return j.contains(key) && j[key].is_number() ? j[key].get<double>() : std::nan("");
  };
  const Json& t = s.at("trilinear");
  const double id1 = get(t, "d1_mm"), is1 = get(t, "sigma1_kPa"), id2 = get(t, "d2_mm"),
               is2 = get(t, "sigma2_kPa"), idc = get(t, "delta_c_mm");
  id.j_tip = get(s, "J_tip_J_m2");
  id.g_ss = get(s, "G_ss_J_m2");
  id.delta_c = idc;
  id.sigma1 = trilinear_at(d1, id1, is1, id2, is2, idc);
  id.sigma2 = trilinear_at(d2, id1, is1, id2, is2, idc);
  ChainRow as_fit;
  as_fit.sigma1 = is1;
  as_fit.sigma2 = is2;
  as_fit.delta_c = idc;
  id.law_l2_rel = law_l2_error(truth, as_fit, id1, id2);
}

/// Issue 39's targets (the defaults, Table 1 laws at 1 Hz): G_ss 2 %, J_tip 10 % or 20 J/m^2,
/// delta_c 10 %, sigma1 and sigma2 12 % or 15 kPa, no refusal.
void judge_targets(ChainRow& r) {
  std::string m;
  auto add = [&](const std::string& s) { m += (m.empty() ? "" : "; ") + s; };
  if (r.outcome != "recovered")
    add("refused");
  else {
    auto off = [](double got, double truth, double rel_tol, double abs_tol) {
      return !std::isfinite(got) ||
             (std::abs(got - truth) > rel_tol * std::abs(truth) && std::abs(got - truth) > abs_tol);
    };
    if (off(r.g_ss, r.g_ss_true, 0.02, 0))
      add("G_ss");
    if (off(r.j_tip, r.j_tip_true, 0.10, 20))
      add("J_tip");
    if (off(r.delta_c, r.delta_c_true, 0.10, 0))
      add("delta_c");
    if (off(r.sigma1, r.sigma1_true, 0.12, 15))
      add("sigma1");
    if (off(r.sigma2, r.sigma2_true, 0.12, 15))
      add("sigma2");
  }
  r.missed = m;
  r.targets_met = m.empty();
}

/// One case: the virtual test, then the chain on what it wrote.
ChainRow run_case(const SceneContext& ctx, const ChainStudySection& section, const ChainCase& c) {
  ChainRow row;
  row.name = c.name;
  row.factor = c.factor;
  row.value = c.value;
  row.table1 = c.table1;
  const double nan = std::nan("");
  row.j_tip = row.g_ss = row.delta_c = row.sigma1 = row.sigma2 = row.law_l2_rel = nan;

  // The truth: the case's Cohesive law as the FEM reads it.
  const auto params = scene_parameters_with(ctx.parameters(), c.sets, "Chain study case " + c.name);
  const law::LawSpec& spec = params->law();
  const auto truth = law::make_law(spec);
  const double d1 = 0.1, d2 = 1.0; // the paper's fixed breakpoints [mm] (Fit section defaults)
  row.j_tip_true = spec.j_tip;
  row.g_ss_true = spec.j_tip + truth->area();
  row.delta_c_true = truth->critical_opening() / mm;
  row.sigma1_true = truth->envelope(d1 * mm) / kPa;
  row.sigma2_true = truth->envelope(d2 * mm) / kPa;

  const std::string dir = ctx.out("cases/" + c.name);
  const std::string fem_dir = fs::absolute(dir + "/fem").string();
  const std::string chain_dir = fs::absolute(dir + "/chain").string();
  auto t0 = std::chrono::steady_clock::now();
  try {
    run_virtual_test(ctx, c.sets, fem_dir, section.reuse);
  } catch (const std::exception& e) {
    row.outcome = "fem_failed";
    row.stage = "fem";
    row.reason = e.what();
    row.fem_wall_s = seconds_since(t0);
    judge_targets(row);
    return row;
  }
  row.fem_wall_s = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  try {
    std::vector<std::string> set = {"Run=" + section.chain_run, "Output directory=" + chain_dir};
    if (!section.model_correction.empty())
      set.push_back("Fit/Model correction=" + section.model_correction);
    run_scene(fem_dir + "/virtual_test/dic_scene.prm", set, false, ctx.progress_sink);
    read_recovered(chain_dir + "/summary.json", row);
    row.outcome = "recovered";
  } catch (const std::exception& e) {
    // InputError (a refusal with its reason: "no steady state", ...) or ComputationError: the
    // chain's answer on this record, a row of the table.
    row.outcome = "refused";
    row.stage = "chain";
    row.reason = e.what();
  }
  row.chain_wall_s = seconds_since(t0);
  row.law_l2_rel = law_l2_error(*truth, row, d1, d2);
  judge_targets(row);
  if (section.identify) {
    // The same virtual test through `dic, identify`: no reduce, so identify fits the record dic
    // wrote (item_identify.cc), crack lengths from the frames, no delta_root.
    const std::string id_dir = fs::absolute(dir + "/identify").string();
    t0 = std::chrono::steady_clock::now();
    try {
      run_scene(fem_dir + "/virtual_test/dic_scene.prm",
                {"Run=dic, identify", "Output directory=" + id_dir}, false, ctx.progress_sink);
      read_identified(id_dir + "/summary.json", *truth, d1, d2, row.identified);
      row.identified.outcome = "identified";
    } catch (const std::exception& e) {
      row.identified.outcome = "refused";
      row.identified.reason = e.what();
    }
    row.identified.wall_s = seconds_since(t0);
  }
  return row;
}

} // namespace

void declare_chain_study_section(dealii::ParameterHandler& prm) {
  declare_section<ChainStudySection>(prm, "Chain study");
}

void parse_chain_study_section(dealii::ParameterHandler& prm, SceneParameters& out) {
  parse_into<ChainStudySection>(prm, "Chain study", out);
}

void check_chain_study_item(SceneContext& ctx) {
  const auto& section = ctx.parameters().section<ChainStudySection>("Chain study");
  const auto table =
      analysis::read_property_table(resolve_scene_path(section.table1, ctx.scene_file));
  // Every case's settings are applied now: a misspelt key fails before the first FEM run.
  for (const auto& c :
       select_chain_cases(chain_study_cases(table), section.cases, "Chain study/Cases"))
    law::make_law(
        scene_parameters_with(ctx.parameters(), c.sets, "Chain study case " + c.name)->law());
}

ItemOutcome run_chain_study_item(const SceneContext& ctx) {
  const auto& section = ctx.parameters().section<ChainStudySection>("Chain study");
  const auto table =
      analysis::read_property_table(resolve_scene_path(section.table1, ctx.scene_file));
  const auto cases =
      select_chain_cases(chain_study_cases(table), section.cases, "Chain study/Cases");
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<ChainRow> rows;
  // One case after the other on this rank: each virtual test writes its own folder and the FEM
  // with a virtual DIC runs on one MPI rank only (docs/design.md, "Virtual DIC test").
  for (const auto& c : cases) {
    rows.push_back(run_case(ctx, section, c));
    const auto& r = rows.back();
    ctx.progress("chain study: " + r.name + " " + r.outcome +
                 (r.missed.empty() ? "" : " (missed: " + r.missed + ")") + ", " +
                 fmt(r.fem_wall_s + r.chain_wall_s, 3) + " s");
  }
  ItemOutcome out;
  write_chain_study(ctx, rows, seconds_since(t0), out.report);
  return out;
}

} // namespace fiberbridge::app
