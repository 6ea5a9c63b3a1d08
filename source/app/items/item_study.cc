// Scene item `study`: error against run time (refinement ladders per model) and the stability
// matrix (stiff, extreme and ill-posed cases). Both drive the simulation items themselves with
// parameter overrides, so a study measures exactly what a user's scene would run. Every run is
// an independent task: under mpirun they are spread over the ranks (task_distributor.h) and the
// tables are the same as on one rank.
#include "outputs/study_writers.h"

#include "fiberbridge/app/items/items.h"
#include "fiberbridge/app/run/resume_store.h"
#include "fiberbridge/app/run/task_distributor.h"
#include "fiberbridge/app/scene/models.h"
#include "fiberbridge/app/scene/scene_reader.h"
#include "fiberbridge/app/scene/section.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/json_archive.h"
#include "fiberbridge/core/plot.h"
#include "fiberbridge/result/result_archive.h"

#include <deal.II/base/patterns.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <sstream>

namespace fiberbridge::app {

namespace {

// What a study task's bytes hold (core/binary_archive.h): a ladder level's result, or a
// stability case's row.
const char* ladder_run_kind = "fiberbridge study ladder level";
const char* stability_run_kind = "fiberbridge study stability case";

/// The scene's parameters with a run's settings "Section/Key=value" applied to a copy: the
/// scene's own parameters stay as they are (the later items and the other runs read them).
std::shared_ptr<const SceneParameters> with_settings(const SceneContext& ctx,
                                                     const std::vector<std::string>& sets,
                                                     const std::string& where) {
  return scene_parameters_with(ctx.parameters(), sets, where);
}

const SceneItem* find_item(const std::string& name) {
  for (const auto& i : scene_items())
    if (i.name == name)
      return &i;
  return nullptr;
}

/// The model's section (models.h); the model is known (require_model).
std::string section_of(const std::string& model) {
  return find_model(model)->section;
}

/// A simulation item by name, or InputError.
const SceneItem& simulation_item(const std::string& model) {
  const SceneItem* item = find_item(model);
  if (!item)
    throw InputError("Study: model '" + model + "' is not available in this build");
  return *item;
}

/// Runs one simulation item in `sub` (a context derived from the scene's, with its own output
/// folder and parameters) and returns its result (the run's own summary block stays in its
/// outcome: the study reports the result).
result::SimulationResult run_model(const SceneContext& sub, const std::string& model) {
  const SceneItem& item = simulation_item(model);
  std::filesystem::create_directories(sub.output_dir);
  return std::move(*item.run(sub).simulation);
}

struct Case {
  std::string name;
  std::string description;
  std::vector<std::string> sets;
  /// Non-empty: the case concerns only the model of this section (it sets that section's keys).
  std::string only_section = {};
};

/// docs/design.md section 3 "Stability on stiff and extreme cases".
std::vector<Case> stability_cases() {
  return {
      {"stiff_initial_slope",
       "trilinear with d1 = 1e-4 mm (initial slope 6.6e12 Pa/m)",
       {"Cohesive law/Type=trilinear", "Cohesive law/Points=0.0001:661, 1.0:187",
        "Cohesive law/Delta c=6"}},
      {"brittle_limit",
       "linear softening with 0.5 J/m^2 of bridging",
       {"Cohesive law/Type=linear", "Cohesive law/Peak stress=50", "Cohesive law/Delta c=0.02"}},
      {"zone_longer_than_ligament",
       "PVA control law on a 150 mm beam (50 mm ligament)",
       {"Cohesive law/Type=trilinear", "Cohesive law/Points=0.1:661, 1.0:187",
        "Cohesive law/Delta c=6", "Specimen/Length=150"}},
      {"snap_back",
       "strong, short linear law and a short pre-crack (unstable growth)",
       {"Cohesive law/Type=linear", "Cohesive law/Peak stress=3000", "Cohesive law/Delta c=0.1",
        "Specimen/Initial crack=40"}},
      {"extreme_orthotropy",
       "E_L/E_T = 50 (E_T = 268 MPa)",
       {"Cohesive law/Type=trilinear", "Cohesive law/Points=0.1:661, 1.0:187",
        "Cohesive law/Delta c=6", "Material/E_T=268"}},
      {"tiny_delta_c",
       "linear softening, delta_c = 0.01 mm, 2 MPa",
       {"Cohesive law/Type=linear", "Cohesive law/Peak stress=2000", "Cohesive law/Delta c=0.01"}},
      {"huge_delta_c",
       "PVA peaks with delta_c = 60 mm",
       {"Cohesive law/Type=trilinear", "Cohesive law/Points=0.1:661, 1.0:187",
        "Cohesive law/Delta c=60"}},
      {"near_zero_sigma2",
       "trilinear with sigma2 = 0.5 kPa",
       {"Cohesive law/Type=trilinear", "Cohesive law/Points=0.1:661, 1.0:0.5",
        "Cohesive law/Delta c=6"}},
      {"fast_loading",
       "PVA law loaded to initiation within one arm period (dynamic error)",
       {"Cohesive law/Type=trilinear", "Cohesive law/Points=0.1:661, 1.0:187",
        "Cohesive law/Delta c=6", "MPM/Loading periods=1"},
       "MPM"},
  };
}

} // namespace

namespace {

/// One model's ladder as the scene gives it: keys varied together, one value per level.
struct Ladder {
  std::string model;
  std::vector<std::pair<std::string, std::vector<std::string>>> keys;
  std::size_t levels = 0;
};

Ladder parse_ladder(const std::string& model, const std::string& text) {
  const auto spec = split_list(text, ';');
  if (spec.empty())
    throw InputError("Study/" + section_of(model) + " ladder: empty for model '" + model +
                     "' listed in Ladder models");
  Ladder ladder{model, {}, 0};
  for (const auto& s : spec) {
    const auto eq = s.find('=');
    if (eq == std::string::npos)
      throw InputError("Study/" + section_of(model) + " ladder: '" + s +
                       "' is not 'Key = v1, v2, ...'");
    auto key = s.substr(0, eq);
    key = key.substr(0, key.find_last_not_of(" \t") + 1);
    const auto values = split_list(s.substr(eq + 1), ',');
    if (ladder.levels && values.size() != ladder.levels)
      throw InputError("Study/" + section_of(model) +
                       " ladder: keys varied together need the same number of values");
    ladder.levels = values.size();
    ladder.keys.push_back({key, values});
  }
  return ladder;
}

std::string level_setting(const Ladder& ladder, std::size_t l) {
  std::string setting;
  for (const auto& [k, v] : ladder.keys)
    setting += (setting.empty() ? "" : "; ") + k + " = " + v[l];
  return setting;
}

/// One ladder's levels from the study's gathered results (`done`, the ladder's first level at
/// `first_task`): each level's errors against G_law = J_tip + law area, its peak load, the
/// observed orders, and the cheapest level whose errors are both below `target`.
LadderOutcome analyse_ladder(const Ladder& ladder, const TaskResults& done, std::size_t first_task,
                             double G_law, double target) {
  LadderOutcome out;
  out.model = ladder.model;
  out.target = target;
  auto& run_levels = out.levels;
  for (std::size_t l = 0, task = first_task; l < ladder.levels; ++l, ++task) {
    auto r = from_archive_bytes<result::SimulationResult>(done.output[task], ladder_run_kind);
    double peak = 0;
    for (const auto& p : r.rcurve)
      if (std::isfinite(p.load))
        peak = std::max(peak, p.load);
    const double g_err = std::abs(r.G_ss - G_law) / G_law;
    LadderLevel level;
    level.setting = level_setting(ladder, l);
    level.key_value = std::strtod(ladder.keys[0].second[l].c_str(), nullptr);
    level.r = std::move(r);
    level.g_err = g_err;
    level.peak = peak;
    level.rank = done.rank[task];
    level.cpu_s = done.cpu_seconds[task];
    run_levels.push_back(std::move(level));
  }
  // Observed orders: p = log(e_l / e_{l+1}) / log(refinement factor); the peak load has no
  // exact value, so its order comes from three successive levels (constant factor assumed).
  const auto factor = [&](std::size_t l) {
    const double a = run_levels[l].key_value, b = run_levels[l + 1].key_value;
    return a > 0 && b > 0 ? std::max(a / b, b / a) : result::not_available;
  };
  const auto order = [&](double e0, double e1, double f) {
    return e0 > 0 && e1 > 0 && f > 1 ? std::log(e0 / e1) / std::log(f) : result::not_available;
  };
  for (std::size_t l = 0; l < run_levels.size(); ++l) {
    auto& L = run_levels[l];
    if (l + 1 < run_levels.size()) {
      const auto& N = run_levels[l + 1];
      L.order_rdelta = order(L.r.rdelta_rel_error_vs_eq2, N.r.rdelta_rel_error_vs_eq2, factor(l));
      L.order_G_ss = order(L.g_err, N.g_err, factor(l));
      if (l + 2 < run_levels.size())
        L.order_peak =
            order(std::abs(L.peak - N.peak), std::abs(N.peak - run_levels[l + 2].peak), factor(l));
    }
    const double worst = std::max(L.r.rdelta_rel_error_vs_eq2, L.g_err);
    if (worst <= target &&
        (out.cheapest < 0 || L.r.wall_time_s < run_levels[out.cheapest].r.wall_time_s))
      out.cheapest = static_cast<int>(l);
  }
  return out;
}

/// One ladder level: the model with the level's keys, in study/<model>_level<l>.
result::SimulationResult run_ladder_level(const SceneContext& ctx, const Ladder& ladder,
                                          std::size_t l) {
  std::vector<std::string> sets;
  for (const auto& [k, v] : ladder.keys)
    sets.push_back(section_of(ladder.model) + "/" + k + "=" + v[l]);
  ctx.progress("study: " + ladder.model + " level " + std::to_string(l) + " (" +
               level_setting(ladder, l) + ")");
  // The level is the scene's own run with finer or coarser settings: everything earlier items
  // handed on (the fitted or identified law, identify's specimen and modulus) stays.
  SceneContext sub =
      ctx.derived(ctx.out("study/" + ladder.model + "_level" + std::to_string(l)),
                  SceneContext::HandOn::everything,
                  with_settings(ctx, sets, "Study/" + section_of(ladder.model) + " ladder"));
  return run_model(sub, ladder.model);
}

/// One stability case with one model: outcome, diagnosis and wall time (the model's failures are
/// outcomes here, not errors of the study).
Json run_stability_case(const SceneContext& ctx, const Case& c, const std::string& model,
                        double plateau_tol) {
  ctx.progress("study: stability " + c.name + " with " + model);
  std::string outcome, diagnosis;
  // The model's own steady-state status (issue 34): a run that stopped with an exception has none.
  std::string status = result::to_string(result::SteadyStateStatus::not_reached);
  const auto t0 = std::chrono::steady_clock::now();
  try {
    // A case is its own law, specimen and material (the sections with the case's overrides),
    // whatever earlier items of the scene found.
    SceneContext sub = ctx.derived(ctx.out("study/stability_" + c.name + "_" + model),
                                   SceneContext::HandOn::sections,
                                   with_settings(ctx, c.sets, "Study stability case " + c.name));
    const auto r = run_model(sub, model);
    const double G_law = sub.j_tip() + sub.law()->area();
    bool finite = !r.rcurve.empty();
    for (const auto& p : r.rcurve)
      finite = finite && std::isfinite(p.a) && std::isfinite(p.load);
    status = result::to_string(r.steady_state_status);
    for (const auto& n : r.notes)
      diagnosis += (diagnosis.empty() ? "" : " | ") + n;
    if (!finite) {
      outcome = "failure";
      diagnosis = "non-finite or empty R curve. " + diagnosis;
    } else if (r.reached_steady_state) {
      const double err = std::abs(r.G_ss - G_law) / G_law;
      outcome = err <= plateau_tol ? "converged" : "suspect";
      diagnosis = "G_ss " + std::to_string(r.G_ss) + " J/m^2 vs " + std::to_string(G_law) +
                  " (rel. " + std::to_string(err) + "). " + diagnosis;
    } else {
      outcome = diagnosis.empty() ? "failure" : "diagnosed stop";
      if (diagnosis.empty())
        diagnosis = "no steady state and no diagnosis from the model";
    }
    diagnosis = "steady_state_status " + status + ". " + diagnosis;
  } catch (const std::exception& e) {
    outcome = "diagnosed stop";
    diagnosis = e.what();
  }
  for (auto& ch : diagnosis)
    if (ch == ',' || ch == '\n')
      ch = ';';
  const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return {{"case", c.name},
          {"description", c.description},
          {"model", model},
          {"outcome", outcome},
          {"diagnosis", diagnosis},
          {"wall_time_s", t},
          {"steady_state_status", status}};
}

} // namespace

namespace {

/// A model named in the Study section: one of the simulation items built in.
void require_model(const std::string& model, const std::string& key) {
  if (!find_model(model))
    throw InputError("Study/" + key + ": unknown model '" + model + "', expected " + model_names());
  if (!find_item(model))
    throw InputError("Study/" + key + ": model '" + model + "' is not available in this build");
}

/// Study: ladders, stability cases and the thresholds (a step-44 section struct, section.h).
struct StudySection {
  std::vector<Ladder> ladders;
  std::vector<std::string> stability_models;
  std::vector<Case> cases;
  double plateau_tol = 0;
  std::map<std::string, double> target; ///< per model: its target error (models.h target_key)

  static void declare_parameters(dealii::ParameterHandler& prm) {
    prm.declare_entry("Ladder models", "", dealii::Patterns::Anything(),
                      "Models (beam, fem, mpm) whose refinement ladders run: error vs wall time.");
    for (const auto& m : simulation_models())
      prm.declare_entry(std::string(m.section) + " ladder", m.ladder_default,
                        dealii::Patterns::Anything(), m.ladder_doc);
    prm.declare_entry("Stability models", "", dealii::Patterns::Anything(),
                      "Models that run the stability matrix (empty = none).");
    prm.declare_entry("Stability cases", "all", dealii::Patterns::Anything(),
                      "Comma-separated case names, or all: stiff_initial_slope, brittle_limit, "
                      "zone_longer_than_ligament, snap_back, extreme_orthotropy, tiny_delta_c, "
                      "huge_delta_c, near_zero_sigma2, fast_loading (MPM only).");
    prm.declare_entry("Target error", "0.01", dealii::Patterns::Double(0),
                      "The cheapest ladder level whose R_J and G_ss errors are both below this is "
                      "reported (beam, FEM).");
    prm.declare_entry("MPM target error", "0.03", dealii::Patterns::Double(0),
                      "The same for the MPM ladder.");
    prm.declare_entry("Plateau tolerance", "0.05", dealii::Patterns::Double(0),
                      "A converged run whose G_ss differs from J_tip + area by more than this "
                      "relative amount is reported 'suspect'.");
  }
  void parse_parameters(dealii::ParameterHandler& prm) {
    const auto ladder_models = split_list(prm.get("Ladder models"), ',');
    stability_models = split_list(prm.get("Stability models"), ',');
    const std::string case_list = prm.get("Stability cases");
    plateau_tol = prm.get_double("Plateau tolerance");
    for (const auto& m : simulation_models())
      target[m.name] = prm.get_double(m.target_key);
    if (ladder_models.empty() && stability_models.empty())
      throw InputError("Study: neither 'Ladder models' nor 'Stability models' names a model");
    for (const auto& model : ladder_models) {
      require_model(model, "Ladder models");
      ladders.push_back(parse_ladder(model, prm.get(section_of(model) + " ladder")));
    }
    for (const auto& model : stability_models)
      require_model(model, "Stability models");
    if (!stability_models.empty()) {
      const auto all = stability_cases();
      const auto wanted = split_list(case_list, ',');
      for (const auto& name : wanted)
        if (name != "all" &&
            std::none_of(all.begin(), all.end(), [&](const Case& c) { return c.name == name; }))
          throw InputError("Study/Stability cases: unknown case '" + name + "'");
      for (const auto& c : all)
        if (case_list == "all" || std::find(wanted.begin(), wanted.end(), c.name) != wanted.end())
          cases.push_back(c);
      if (cases.empty())
        throw InputError("Study/Stability cases: no known case in '" + case_list + "'");
    }
  }
};

} // namespace

void declare_study_section(dealii::ParameterHandler& prm) {
  declare_section<StudySection>(prm, "Study");
}

void parse_study_section(dealii::ParameterHandler& prm, SceneParameters& out) {
  parse_into<StudySection>(prm, "Study", out);
}

void check_study_item(SceneContext& ctx) {
  const auto& plan = ctx.parameters().section<StudySection>("Study");
  // Every ladder level is the model's section with the level's keys: check each as the model's
  // item would (a misspelt key or a bad value fails now, not after the coarser levels ran). The
  // stability cases' failures are outcomes of the study, not input errors.
  for (const auto& ladder : plan.ladders)
    for (std::size_t l = 0; l < ladder.levels; ++l) {
      std::vector<std::string> sets;
      for (const auto& [k, v] : ladder.keys)
        sets.push_back(section_of(ladder.model) + "/" + k + "=" + v[l]);
      SceneContext level =
          ctx.derived(ctx.output_dir, SceneContext::HandOn::everything,
                      with_settings(ctx, sets, "Study/" + section_of(ladder.model) + " ladder"));
      find_item(ladder.model)->check(level);
    }
  ctx.law_known_before_run();
}

ItemOutcome run_study_item(const SceneContext& ctx) {
  const auto& plan = ctx.parameters().section<StudySection>("Study");
  const auto& ladders = plan.ladders;
  const auto& stability_models = plan.stability_models;
  const auto& cases = plan.cases;
  const double plateau_tol = plan.plateau_tol;

  // ---- every run of the study is one task (task_distributor.h): ladder levels, then the
  // stability cases. Each task writes its own study/<run> folder; the tables come from the
  // gathered results below, written by rank 0 alone. Cost estimates only order the hand-out:
  // levels are listed coarse to fine and a 2D level about quadruples the work of the previous
  // one; a stability case counts as one coarsest level.
  //
  // Each run is a unit of work that --resume restores once finished (resume_store.h): its result
  // is kept in resume/ as it finishes, tied to the scene's parameters and the law in effect.
  const Fingerprint inputs = simulation_fingerprint(ctx);
  std::vector<std::function<std::string()>> tasks;
  std::vector<double> cost;
  for (const auto& ladder : ladders)
    for (std::size_t l = 0; l < ladder.levels; ++l) {
      tasks.push_back([&ctx, &ladder, l, &inputs] {
        TaskOwnsItsFiles own;
        const std::string run = ladder.model + "_level" + std::to_string(l);
        return run_or_restore(
            ctx.output_dir, ctx.resume, "study_" + run, inputs, ctx.out("study/" + run),
            [&] { return to_archive_bytes(run_ladder_level(ctx, ladder, l), ladder_run_kind); });
      });
      cost.push_back(std::pow(4.0, double(l)));
    }
  const std::size_t first_case_task = tasks.size();
  std::vector<std::pair<const Case*, std::string>> case_runs;
  for (const auto& c : cases)
    for (const auto& model : stability_models)
      if (c.only_section.empty() || c.only_section == section_of(model))
        case_runs.push_back({&c, model});
  for (const auto& [c, model] : case_runs) {
    tasks.push_back([&ctx, c = c, model = model, plateau_tol, &inputs] {
      TaskOwnsItsFiles own;
      const std::string run = "stability_" + c->name + "_" + model;
      return run_or_restore(
          ctx.output_dir, ctx.resume, "study_" + run, inputs, ctx.out("study/" + run), [&] {
            return to_archive_bytes(run_stability_case(ctx, *c, model, plateau_tol),
                                    stability_run_kind);
          });
    });
    cost.push_back(1.0);
  }
  const auto done = run_tasks_across_ranks(
      tasks.size(), [&](std::size_t i) { return tasks[i](); }, simulation_communicator(), cost);

  // ---- the ladders' levels with their errors and observed orders, the stability rows
  std::vector<LadderOutcome> outcomes;
  if (!ladders.empty()) {
    const double G_law = ctx.j_tip() + ctx.law()->area();
    std::size_t task = 0;
    for (const auto& ladder : ladders) {
      outcomes.push_back(analyse_ladder(ladder, done, task, G_law, plan.target.at(ladder.model)));
      task += ladder.levels;
    }
  }
  std::vector<Json> stability_rows;
  for (std::size_t k = 0; k < case_runs.size(); ++k) {
    Json row = from_archive_bytes<Json>(done.output[first_case_task + k], stability_run_kind);
    row["rank"] = done.rank[first_case_task + k];
    row["cpu_s"] = done.cpu_seconds[first_case_task + k];
    stability_rows.push_back(std::move(row));
  }

  // ---- written: the tables, plots and the summary block
  Json block = Json::object();
  int n_ranks = 1;
  MPI_Comm_size(simulation_communicator(), &n_ranks);
  block["ranks"] = n_ranks;
  ItemOutcome out;
  if (!ladders.empty())
    write_study_ladders(ctx, outcomes, block, out.report);
  if (!stability_models.empty())
    write_study_stability(ctx, stability_rows, block);
  out.report["study"] = block;
  return out;
}

} // namespace fiberbridge::app
