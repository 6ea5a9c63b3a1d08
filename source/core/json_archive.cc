#include "fiberbridge/core/json_archive.h"

#include "fiberbridge/core/error.h"

#include <cstdint>
#include <vector>

namespace fiberbridge {

void BinaryCodec<Json>::save(BinaryWriter& out, const Json& j) {
  const std::vector<std::uint8_t> cbor = Json::to_cbor(j);
  out.put(std::string(cbor.begin(), cbor.end()));
}

void BinaryCodec<Json>::load(BinaryReader& in, Json& j) {
  const auto cbor = in.get<std::string>();
  try {
    j = Json::from_cbor(cbor);
  } catch (const Json::exception& e) {
    throw InputError(in.source() + ": a JSON block that does not read back (" + e.what() + ")");
  }
}

} // namespace fiberbridge
