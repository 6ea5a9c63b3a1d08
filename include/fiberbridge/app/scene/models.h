#pragma once
// The simulation models of a scene (docs/design.md section 4, "One registry of models"), as ASPECT
// registers its plugins: each model's item file (items/item_<model>.cc) defines its entry with
// named fields, and items/models.cc calls the entry of every model CMake lists
// (FIBERBRIDGE_ALL_MODELS). The scene runner, resume, the task hand-out, the text report,
// compare, study, identify and the campaign ask the registry; no other code names a model. A
// fourth model: its library, its item file and its name in FIBERBRIDGE_ALL_MODELS (design.md
// shows the files).
#include "fiberbridge/app/scene/scene_context.h"
#include "fiberbridge/identify/forward_model.h"

#include <functional>
#include <string>
#include <vector>

namespace fiberbridge::app {

/// A model's progress lines, as the command line prints them to stderr; empty = none.
using ProgressLines = std::function<void(const std::string&)>;

struct SimulationModel {
  const char* name = nullptr; ///< the Run item, the key of ctx.results and of its summary block
  const char* section =
      nullptr;        ///< its prm section; the Study's "<section> ladder" varies its keys
  bool built = false; ///< compiled into this build (FIBERBRIDGE_MODELS); else only named
  void (*declare)(dealii::ParameterHandler&) = nullptr; ///< nullptr when not built
  /// Its section parsed into the scene's parameters when the scene is read (SceneItem::parse).
  void (*parse)(dealii::ParameterHandler&, SceneParameters&) = nullptr;
  void (*check)(SceneContext&) = nullptr;
  ItemOutcome (*run)(const SceneContext&) = nullptr;
  /// Relative cost on the seed specimen (the beam ~0.2 s, the 2D FEM 0.18 s of model time on
  /// its defaults, the MPM minutes: README.md, "The models in one paragraph each";
  /// docs/verification.md, "The FEM at its physical limit"): orders the runs
  /// (cheapest first in a scene) and the hand-out across ranks (costliest first,
  /// simulation_tasks.h).
  double cost = 1;
  /// Runs on all ranks of simulation_communicator() when it is the only simulation of a scene
  /// (an MPI program: the FEM); the others are serial programs, one task each.
  bool uses_all_ranks = false;
  /// Whether this scene's run of the model must have every rank even beside other models (the
  /// FEM in 3D, or with the deprecated FEM/Engine = distributed as set); nullptr = never.
  bool (*needs_all_ranks)(const SceneParameters&) = nullptr;
  const char* ladder_default = ""; ///< Study/<section> ladder: its default and its documentation
  const char* ladder_doc = "";
  /// The Study key of the error a ladder level must reach ("Target error").
  const char* target_key = "Target error";
  /// The model run with a given law and J_tip on the scene's specimen set-up and the model's
  /// section, on this process alone, writing no files and reporting nothing: for items that put
  /// many laws back in the specimen (the campaign's Fig. 10), or for a caller that shows its own
  /// progress (the Python module): `progress` takes the model's progress lines and may throw to
  /// stop the run (the model unwinds; nothing was written). nullptr when not built.
  result::SimulationResult (*simulate)(const SceneContext&, const law::TractionLaw&, double j_tip,
                                       const ProgressLines& progress) = nullptr;
  /// The model with its section's settings as identify's forward model (Identify/Forward model
  /// = <name>; identify/forward_model.h, docs/design.md section 6, "Forward model of identify").
  /// nullptr: not offered (the beam is identify's own, with the Identify section's beam keys).
  identify::ForwardModel (*identify_forward)(const SceneContext&) = nullptr;
  /// identify's own forward model (the beam, run with the Identify section's beam keys), which
  /// identify calls itself rather than through identify_forward.
  bool identify_builtin = false;
  /// A finite-element model: the campaign's Fig. 10 takes one first (the paper puts its laws back
  /// in a FE model), before the others cheapest first.
  bool finite_elements = false;

  SceneItem item() const { return {name, declare, parse, check, run}; }
};

/// Every model the project knows, built or not, in the order they joined the project (the order
/// the Run documentation lists them; the campaign's Fig. 10 takes the first that can simulate).
const std::vector<SimulationModel>& simulation_models();

/// The built models, cheapest first: the order a scene runs them.
std::vector<const SimulationModel*> built_models();

/// The model named `name` (built or not), nullptr when there is none.
const SimulationModel* find_model(const std::string& name);

/// The built model named `name`, nullptr when there is none (or it is not built).
const SimulationModel* built_model(const std::string& name);

/// "fem, mpm, beam": the known models' names, comma-separated.
std::string model_names();

} // namespace fiberbridge::app
