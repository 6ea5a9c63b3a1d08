#pragma once
// The files, plots and summary blocks of rank (analysis/law_extraction.h computes them).
#include "fiberbridge/analysis/law_extraction.h"
#include "fiberbridge/app/scene/item_outcome.h"

#include <string>

namespace fiberbridge::app {

/// degradation.csv, degradation_<material>.csv and .png per material, the `ranking` list and the
/// `rank` block (degradation, materials, consistency); a warning per consistency issue.
void write_ranking(const analysis::RankingOutcome& r, const analysis::RankOptions& o,
                   const std::string& out_dir, ItemReport& report);

} // namespace fiberbridge::app
