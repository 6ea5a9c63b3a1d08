#pragma once
// A simulation result in the archive (core/binary_archive.h), every double bit for bit: what a
// model run on another MPI rank hands to rank 0 (task_distributor.h) and what `--resume` keeps of
// a finished simulation (resume_store.h), so the restored table is the one the run computed.
#include "fiberbridge/core/binary_archive.h"
#include "fiberbridge/result/rcurve.h"

namespace fiberbridge {

/// By name (to_string), so a damaged record cannot hold a status that does not exist.
template <>
struct BinaryCodec<result::SteadyStateStatus> {
  static void save(BinaryWriter& out, const result::SteadyStateStatus& s);
  static void load(BinaryReader& in, result::SteadyStateStatus& s);
};

template <>
struct BinaryCodec<result::SimulationResult> {
  static void save(BinaryWriter& out, const result::SimulationResult& r);
  static void load(BinaryReader& in, result::SimulationResult& r);
};

} // namespace fiberbridge
