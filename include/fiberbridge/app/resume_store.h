#pragma once
// Finished units of work of a run (a simulation item, a run of a study, an identify fit), kept in
// the output directory's resume/ folder as they finish, so that `fiberbridge run SCENE --resume`
// restores them instead of running them again (docs/design.md section 5, "Checkpoints and
// --resume"). A record holds the unit's result bit for bit (CBOR, as result_codec.h) and the
// inputs it was made with; a record made with other inputs is refused, naming the first input
// that differs. A run without --resume starts by removing the folder.
#include "fiberbridge/app/scene_context.h"
#include "fiberbridge/core/summary.h"

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fiberbridge::app {

/// The inputs a unit's result depends on, as (name, value) pairs.
using Fingerprint = std::vector<std::pair<std::string, std::string>>;

/// Every entry of the scene's parameters as it stands (the file, --set, and overrides a study
/// has in force), "Section/Key" -> value, without the run-control entries that do not change a
/// result (Output directory, MPM/Threads, MPM/Checkpoint interval).
Fingerprint scene_fingerprint(const SceneParameters& parameters);

/// scene_fingerprint plus what a simulation takes from earlier items: the law (law_fingerprint)
/// and J_tip, the specimen and the material in effect (identify and fit set them).
Fingerprint simulation_fingerprint(SceneContext& ctx);

/// <output_dir>/resume
std::string resume_directory(const std::string& output_dir);

/// With `resume`, the payload of unit `unit` kept by an earlier run into `output_dir`, if any.
/// Throws InputError naming the record and the first input that differs from `inputs`, or the
/// record when it cannot be read.
std::optional<Json> find_finished_unit(const std::string& output_dir, bool resume,
                                       const std::string& unit, const Fingerprint& inputs);

/// Keeps the payload of a finished unit (atomically; nothing on an MPI rank that does not write,
/// core/output_guard.h).
void keep_finished_unit(const std::string& output_dir, const std::string& unit,
                        const Fingerprint& inputs, const Json& payload);

/// At the start of a run without --resume: removes <output_dir>/resume (the records and
/// checkpoints of an earlier run must not be restored into this one).
void clear_resume_state(const std::string& output_dir);

/// A unit whose result is bytes (a task of task_distributor.h): restored from its record when
/// resuming, else run and kept. After a run, `unit_dir`/resume (the checkpoints of the models the
/// unit ran in its own folder) is removed: the record replaces them. Prints a line to stderr when
/// it restores.
std::string run_or_restore(const std::string& output_dir, bool resume, const std::string& unit,
                           const Fingerprint& inputs, const std::string& unit_dir,
                           const std::function<std::string()>& run);

/// Simulation items (beam, fem, mpm) are units of a scene: runs `item` into ctx, or restores what
/// it left there (its summary blocks, plots and result; its files are already in the directory)
/// from the record of an earlier run. After a run keeps the record and removes the item's
/// checkpoint (<output_dir>/resume/<item>_state.bin, the convention of the models' checkpoints).
void run_or_restore_simulation_item(SceneContext& ctx, const SceneItem& item);

/// Is `item` a simulation item (a unit of run_or_restore_simulation_item)?
bool is_simulation_item(const std::string& item);

} // namespace fiberbridge::app
