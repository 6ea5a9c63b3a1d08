#pragma once
// A simulation item's outcome as bytes (core/binary_archive.h): the one record that --resume keeps
// in resume/item_<model>.rec (resume_store.h) and that a simulation task sends back to the ranks
// (simulation_tasks.h). It holds what such an outcome holds: the report (summary blocks, plots)
// and the simulation result. The layout is the one resume records had before outcomes were
// typed (the blocks, the plots as a JSON array, the result), so their records still restore.
#include "fiberbridge/app/scene/item_outcome.h"
#include "fiberbridge/core/binary_archive.h"

namespace fiberbridge {

template <>
struct BinaryCodec<app::ItemOutcome> {
  /// Throws std::logic_error for an outcome that hands on analysis values or has no simulation
  /// result: only a simulation item's outcome is kept or sent.
  static void save(BinaryWriter& out, const app::ItemOutcome& o);
  static void load(BinaryReader& in, app::ItemOutcome& o);
};

} // namespace fiberbridge
