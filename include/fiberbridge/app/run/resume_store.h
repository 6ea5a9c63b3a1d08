#pragma once
// Finished units of work of a run (a simulation item, a run of a study, an identify fit), kept in
// the output directory's resume/ folder as they finish, so that `fiberbridge run SCENE --resume`
// restores them instead of running them again (docs/design.md section 5, "Checkpoints and
// --resume"). A record (resume/<unit>.rec) is one archive (core/binary_archive.h): the unit's
// name, the inputs it was made with, then its result bit for bit; a record made with other
// inputs is refused, naming the first input that differs. A run without --resume starts by
// removing the folder.
#include "fiberbridge/app/scene/scene_context.h"
#include "fiberbridge/core/binary_archive.h"
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
Fingerprint simulation_fingerprint(const SceneContext& ctx);

/// <output_dir>/resume
std::string resume_directory(const std::string& output_dir);

/// With `resume`, the record of unit `unit` kept by an earlier run into `output_dir`, if any,
/// read up to its payload. Throws InputError naming the record and the first input that differs
/// from `inputs`, or the record when it cannot be read (damaged, of another kind, or written by
/// another version of fiberbridge: a record of before issue 30 is a CBOR file <unit>.cbor).
/// Throws InputError naming `path` and the first input that differs between a record's `saved`
/// inputs and this run's `inputs` (new, changed or gone), with the advice to start afresh.
void check_same_inputs(const std::string& path, const Fingerprint& saved,
                       const Fingerprint& inputs);

std::optional<BinaryReader> open_finished_unit(const std::string& output_dir, bool resume,
                                               const std::string& unit, const Fingerprint& inputs);

/// The unit's record with its name and inputs, ready for its payload.
BinaryWriter finished_unit_record(const std::string& unit, const Fingerprint& inputs);

/// Writes a record made by finished_unit_record (atomically; nothing on an MPI rank that does not
/// write, core/output_guard.h).
void store_finished_unit(const std::string& output_dir, const std::string& unit,
                         const BinaryWriter& record);

/// "fiberbridge: resume: <unit> restored from <path>" on stderr (on the rank that writes).
void report_restored(const std::string& unit, const std::string& path);

/// With `resume`, the payload (a T, read by its BinaryCodec) of unit `unit` kept by an earlier
/// run, if any; prints a line to stderr when it restores. Errors as open_finished_unit.
template <class T>
std::optional<T> find_finished_unit(const std::string& output_dir, bool resume,
                                    const std::string& unit, const Fingerprint& inputs) {
  auto in = open_finished_unit(output_dir, resume, unit, inputs);
  if (!in)
    return std::nullopt;
  T payload{};
  in->get(payload);
  in->expect_end();
  report_restored(unit, in->source());
  return payload;
}

/// Keeps the payload of a finished unit.
template <class T>
void keep_finished_unit(const std::string& output_dir, const std::string& unit,
                        const Fingerprint& inputs, const T& payload) {
  BinaryWriter record = finished_unit_record(unit, inputs);
  record.put(payload);
  store_finished_unit(output_dir, unit, record);
}

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

/// Simulation items (beam, fem, mpm) are units of a scene: runs `item` and returns its outcome, or
/// restores the outcome it returned (its summary blocks, plots and result; its files are already
/// in the directory) from the record of an earlier run (outcome_archive.h). After a run keeps the
/// record and removes the item's checkpoint (<output_dir>/resume/<item>_state.bin, the
/// convention of the models' checkpoints).
ItemOutcome run_or_restore_simulation_item(const SceneContext& ctx, const SceneItem& item);

/// Is `item` a simulation item (a unit of run_or_restore_simulation_item)?
bool is_simulation_item(const std::string& item);

} // namespace fiberbridge::app
