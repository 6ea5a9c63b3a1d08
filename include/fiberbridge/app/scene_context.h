#pragma once
// What a scene item (extract, fit, rank, bridging, fem, mpm, beam, compare, study) sees of the
// scene: the parsed parameters, the output directory, the summary it adds its block to, and what
// earlier items handed on (the fitted law, simulation results for compare).
#include "fiberbridge/core/summary.h"
#include "fiberbridge/law/law_spec.h"
#include "fiberbridge/law/traction_law.h"
#include "fiberbridge/result/rcurve.h"
#include "fiberbridge/specimen/specimen.h"

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace fiberbridge::app {

struct ExtractionOutcome; // analysis_steps.h
}
namespace fiberbridge::identify {
struct Identification; // identify/identify.h
}
namespace fiberbridge::app {

struct SceneContext {
  dealii::ParameterHandler* prm = nullptr; ///< every section declared, the scene parsed
  std::string output_dir;
  Json summary = Json::object();

  /// The law for simulations: from `fit` when the scene runs it (extracted law applied without
  /// retyping), else from the `Cohesive law` section. Built on first use (law()).
  law::TractionLawPtr fitted_law;
  double fitted_j_tip = 0;

  /// What `extract` found (data curve, steady state, laws), for `fit` and `bridging`.
  std::shared_ptr<const ExtractionOutcome> extraction;
  std::string scene_file; ///< for resolving relative data paths
  /// `fiberbridge run --resume`: units of work finished by an earlier run into this output
  /// directory are restored and checkpoints continued (resume_store.h, mpm/checkpoint.h).
  bool resume = false;

  /// What `identify` found; it also sets fitted_law/fitted_j_tip and the effective specimen
  /// (first record's a0) and material (its calibrated E_L) that specimen()/material() return.
  std::shared_ptr<const identify::Identification> identification;
  std::optional<specimen::Specimen> identified_specimen;
  std::optional<specimen::Material> identified_material;

  /// The test records `dic` wrote (dic_record.csv) when the scene runs it: `reduce` reads these
  /// instead of Test/Files, which then names the machine record `dic` read (item_dic.cc).
  std::vector<std::string> records_from_dic;

  /// Results of the simulations that ran, by model name ("fem", "mpm", "beam"), for compare.
  std::map<std::string, result::SimulationResult> results;

  /// The items the scene runs: the checks before the first item (check_scene) decide from it
  /// which sections will be used (the law section only when neither fit nor identify runs).
  std::set<std::string> run_items;
  /// True when the simulations get the Specimen and Material sections (no identify in the run).
  bool specimen_from_section() const { return !run_items.count("identify"); }
  /// The law when it is known before any item runs (the Cohesive law section, built and checked),
  /// nullptr when fit or identify will provide it.
  const law::TractionLaw* law_known_before_run();

  /// The law and J_tip a simulation uses (fit's output, else the Cohesive law section).
  law::TractionLawPtr law();
  double j_tip();
  specimen::Specimen specimen() const; ///< the Specimen section (defaults: the seed's DCB)
  specimen::Material material() const; ///< the Material section (defaults: Douglas-fir)
  /// Path inside the output directory.
  std::string out(const std::string& file) const { return output_dir + "/" + file; }

private:
  law::TractionLawPtr section_law_;
  double section_j_tip_ = 0;
};

/// One scene item: declares its prm section(s), checks them and runs. Simulation items return
/// their result through ctx.results[name]; all items add their block to ctx.summary.
struct SceneItem {
  std::string name;
  void (*declare)(dealii::ParameterHandler&); ///< may be nullptr (no own section)
  /// Reads and validates every section the item will use, as `run` reads them, without running
  /// or writing anything; throws InputError naming the section and key. The scene calls it for
  /// every item of the run before the first item runs.
  void (*check)(SceneContext&);
  void (*run)(SceneContext&);
};

/// Calls the check of every item in ctx.run_items (which it needs filled), in item order.
void check_scene(SceneContext& ctx);

/// The registry, in the order items run when a scene lists them.
const std::vector<SceneItem>& scene_items();

/// Common writer for a simulation item: rcurve_<model>.csv, the summary block (docs/design.md
/// section 5: G_ss_J_m2, wall_time_s, n_dofs or n_particles, rdelta_rel_error_vs_eq2, notes) and an
/// R(a) PNG. Every simulation item calls this once with its result.
void report_simulation(SceneContext& ctx, result::SimulationResult result,
                       const std::string& size_key /* "n_dofs" or "n_particles" or "n_elements" */);

} // namespace fiberbridge::app
