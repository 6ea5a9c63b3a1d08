#pragma once
// identify's units of work for `--resume` (resume_store.h): the joint fit of all records and,
// with Identify/Per record, each record's own fit. A finished fit is kept bit for bit in the
// output directory's resume/ folder, tied to the scene's parameters and the records' data
// (find_finished_unit/keep_finished_unit, called by item_identify.cc, which also spreads the
// fits over MPI ranks). The same archive (core/binary_archive.h) carries a fit from the rank
// that ran it to rank 0.
#include "fiberbridge/analysis/test_record.h"
#include "fiberbridge/app/run/resume_store.h"
#include "fiberbridge/core/binary_archive.h"
#include "fiberbridge/identify/identify.h"

#include <functional>
#include <string>
#include <vector>

namespace fiberbridge {

/// An identification in the archive, every double bit for bit: the resume record of a fit and
/// the bytes of a fit run on another rank.
template <>
struct BinaryCodec<identify::Identification> {
  static void save(BinaryWriter& out, const identify::Identification& id);
  static void load(BinaryReader& in, identify::Identification& id);
};

} // namespace fiberbridge

namespace fiberbridge::app {

/// The scene's parameters and, per record, its name and a hash of its rows (a changed data file
/// is a changed input even when the scene is not).
Fingerprint identify_inputs(const SceneContext& ctx,
                            const std::vector<analysis::TestRecord>& records);

} // namespace fiberbridge::app
