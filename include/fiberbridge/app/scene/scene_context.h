#pragma once
// What a scene item (reduce, identify, extract, fit, rank, bridging, the simulations, compare,
// study) sees of the scene: the parsed parameters, the output directory, and what earlier items
// handed on as typed values (docs/design.md section 4, "A scene's state"): the records and their
// reduction, R(delta_root), the extraction, the identification, the crack law and the specimen
// set-up with their sources, the simulation results. An item returns what it made
// (item_outcome.h); the scene runner merges it here.
#include "fiberbridge/analysis/rdelta_data.h"
#include "fiberbridge/analysis/record_chain.h"
#include "fiberbridge/analysis/test_record.h"
#include "fiberbridge/app/scene/item_outcome.h"
#include "fiberbridge/app/scene/scene_parameters.h"
#include "fiberbridge/core/summary.h"
#include "fiberbridge/law/law_spec.h"
#include "fiberbridge/law/traction_law.h"
#include "fiberbridge/result/rcurve.h"
#include "fiberbridge/specimen/specimen.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace dealii {
class ParameterHandler; // the scene reader's (scene_reader.cc): sections declare and parse with it
}
namespace fiberbridge::app {
using analysis::ExtractionOutcome;

struct SceneContext {
  /// Every section of the scene, parsed once when it was read (scene_parameters.h); a study's
  /// run reads a copy with its overrides (derived()). The ParameterHandler is gone by the time
  /// an item checks or runs.
  std::shared_ptr<const SceneParameters> params;
  const SceneParameters& parameters() const { return *params; }
  std::string output_dir;
  /// summary.json as the run builds it: the scene runner adds each item's report
  /// (merge_outcome, run/scene_runner.h); items never write here.
  Json summary = Json::object();
  std::string scene_file; ///< for resolving relative data paths
  /// `fiberbridge run --resume`: units of work finished by an earlier run into this output
  /// directory are restored and checkpoints continued (resume_store.h, mpm/checkpoint.h).
  bool resume = false;
  /// Where the run's progress lines go: standard error, as the command line prints them, unless
  /// the caller gives its own (the Python module's run_scene, which checks for Ctrl-C at each line
  /// and may throw RunInterrupted to stop the run; the run directory then stays marked
  /// incomplete, run_directory.h). Handed on to derived contexts.
  std::function<void(const std::string&)> progress_sink;
  /// One progress line to progress_sink (or standard error).
  void progress(const std::string& line) const;

  // ---- what earlier items hand on (typed; nothing is written back into the parameters). Set
  // only by the scene runner, from the items' outcomes (item_outcome.h).

  /// The Test section's records as read, once: by `reduce` (which keeps them in its outcome) or,
  /// when reduce does not run, by `identify`'s check. identify fits these.
  std::shared_ptr<const std::vector<analysis::TestRecord>> records;
  /// What `reduce` found (records, R(a) per record and their mean).
  std::shared_ptr<const ReduceOutcome> reduced;
  /// R(delta_root) of reduce's records when every record measured delta_root: extract and fit
  /// use it unless Data/File names a file (reduce also writes it to rdelta_test.csv).
  std::shared_ptr<const analysis::RDeltaData> rdelta_root;
  /// What `extract` found (data curve, steady state, laws), for `fit` and `bridging`.
  std::shared_ptr<const ExtractionOutcome> extraction;
  /// What `identify` found; it also hands on its law (handed_law) and the effective specimen
  /// (first record's a0 and calibrated E_L, handed_specimen).
  std::shared_ptr<const identify::Identification> identification;
  /// The law for simulations when `fit` or `identify` ran (the extracted or identified law
  /// applied without retyping); else crack_law() is the Cohesive law section's.
  std::optional<CrackLaw> handed_law;
  /// The specimen set-up when `identify` ran; else the Specimen and Material sections.
  std::optional<SpecimenSetup> handed_specimen;
  /// The test records `dic` wrote (dic_record.csv) when the scene runs it: `reduce` reads these
  /// instead of Test/Files, which then names the machine record `dic` read (item_dic.cc).
  std::vector<std::string> records_from_dic;
  /// Results of the simulations that ran, by model name (models.h), for compare.
  std::map<std::string, result::SimulationResult> results;

  /// The items the scene runs: the checks before the first item (check_scene) decide from it
  /// which sections will be used (the law section only when neither fit nor identify runs).
  std::set<std::string> run_items;
  /// True when the simulations get the Specimen and Material sections (no identify in the run).
  bool specimen_from_section() const { return !run_items.count("identify") && !handed_specimen; }
  /// The law when it is known before any item runs (the Cohesive law section, built and checked),
  /// nullptr when fit or identify will provide it.
  const law::TractionLaw* law_known_before_run() const;

  /// The law, J_tip and source a simulation uses: handed_law, else the Cohesive law section
  /// (built and checked on first use).
  const CrackLaw& crack_law() const;
  law::TractionLawPtr law() const { return crack_law().law; }
  double j_tip() const { return crack_law().j_tip; }
  /// The specimen and material a simulation uses: handed_specimen, else the Specimen and
  /// Material sections (defaults: the seed's DCB of Douglas-fir).
  SpecimenSetup specimen_setup() const;
  specimen::Specimen specimen() const { return specimen_setup().specimen; }
  specimen::Material material() const { return specimen_setup().material; }
  /// How this scene reads and reduces test records: the Test section with specimen() and
  /// material() (TestSection::chain_options). reduce, dic, the campaign and identify all take
  /// this one value (analysis/record_chain.h).
  analysis::RecordChainOptions record_chain() const;
  /// Path inside the output directory.
  std::string out(const std::string& file) const { return output_dir + "/" + file; }

  /// What a context for a run inside this one gets (a study's ladder level or stability case).
  enum class HandOn {
    everything, ///< the typed state above: law, specimen set-up, records, outcomes
    sections    ///< none of it: law, specimen and material from the (overridden) sections
  };
  /// A context for a run inside this one: the same scene file, resume flag and run items, its own
  /// output directory, an empty summary and no results. `parameters`: the parameters the run
  /// reads (a copy with overrides, scene_parameters_with in scene.h); nullptr = this context's.
  SceneContext derived(const std::string& dir, HandOn what,
                       std::shared_ptr<const SceneParameters> parameters = nullptr) const;

private:
  /// The Cohesive law section, built on first use: a cache of the parameters, which do not
  /// change, so the const context may fill it.
  mutable std::optional<CrackLaw> section_law_;
};

/// One scene item: declares its prm section(s), checks them and runs. `run` returns what it made
/// (item_outcome.h) and changes nothing in the context; the scene runner merges the outcome.
struct SceneItem {
  std::string name;
  void (*declare)(dealii::ParameterHandler&); ///< may be nullptr (no own section)
  /// Parses the sections `declare` declared into the scene's parameters (parse_into, section.h),
  /// once, when the scene is read; nullptr with declare.
  void (*parse)(dealii::ParameterHandler&, SceneParameters&);
  /// Reads and validates every section the item will use, as `run` reads them, without running
  /// or writing anything; throws InputError naming the section and key. The scene calls it for
  /// every item of the run before the first item runs.
  void (*check)(SceneContext&);
  ItemOutcome (*run)(const SceneContext&);
};

/// Calls the check of every item in ctx.run_items (which it needs filled), in item order.
void check_scene(SceneContext& ctx);

/// The registry, in the order items run when a scene lists them.
const std::vector<SceneItem>& scene_items();

} // namespace fiberbridge::app
