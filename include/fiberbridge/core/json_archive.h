#pragma once
// A JSON document in the archive (core/binary_archive.h): summary blocks and plot lists that a
// finished unit hands back (resume_store.h). Written as CBOR inside a string, which keeps every
// double binary (NaN and infinities too, where JSON text would turn them into null).
#include "fiberbridge/core/binary_archive.h"
#include "fiberbridge/core/summary.h"

namespace fiberbridge {

template <>
struct BinaryCodec<Json> {
  static void save(BinaryWriter& out, const Json& j);
  static void load(BinaryReader& in, Json& j);
};

} // namespace fiberbridge
