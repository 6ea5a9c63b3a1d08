#pragma once
// summary.json: one ordered JSON object that every scene item adds its block to; written once,
// at the end of a successful run (a failed run removes any stale summary first).
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

namespace fiberbridge {

using Json = nlohmann::ordered_json;

/// NaN/inf are not JSON: they become null ("not available").
inline Json json_number(double v) {
  return std::isfinite(v) ? Json(v) : Json(nullptr);
}

void write_json_atomically(const std::string& path, const Json& j);

} // namespace fiberbridge
