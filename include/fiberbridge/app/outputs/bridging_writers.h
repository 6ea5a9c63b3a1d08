#pragma once
// The file and summary block of `bridging` (analysis/bridging_model.h computes the estimate).
#include "fiberbridge/analysis/bridging_model.h"
#include "fiberbridge/app/scene/item_outcome.h"

#include <string>

namespace fiberbridge::app {

/// bridging_model.csv (the model's law to twice the opening: exact, Eq. 13, Eq. 15) and the
/// summary's `bridging` block; `stress_source` says where the stress came from.
void write_bridging(const analysis::BridgingEstimate& e, const std::string& stress_source,
                    const std::string& out_dir, ItemReport& report);

} // namespace fiberbridge::app
