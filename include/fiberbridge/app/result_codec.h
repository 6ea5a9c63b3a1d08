#pragma once
// A simulation result as bytes and back, exactly (every double bit for bit, NaN included), so
// that a run on another rank gives rank 0 the same table as a run in this process
// (task_distributor.h). CBOR of a JSON document: self-describing, and doubles stay binary.
#include "fiberbridge/core/summary.h"
#include "fiberbridge/result/rcurve.h"

#include <string>

namespace fiberbridge::app {

Json result_to_json(const result::SimulationResult& r);
result::SimulationResult result_from_json(const Json& j);

/// Binary (CBOR) form of a JSON document, and back; non-finite doubles survive.
std::string json_to_bytes(const Json& j);
Json json_from_bytes(const std::string& bytes);

} // namespace fiberbridge::app
