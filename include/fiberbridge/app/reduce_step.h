#pragma once
// `reduce` as a step shared by the command line (fiberbridge reduce) and the scene item
// (section Test): raw DCB records in, R(a) by direct energy and by MBT/CC/MCC out.
#include "fiberbridge/analysis/record_chain.h"
#include "fiberbridge/analysis/record_reduction.h"
#include "fiberbridge/analysis/test_record.h"
#include "fiberbridge/core/summary.h"
#include "fiberbridge/specimen/specimen.h"

#include <string>
#include <vector>

namespace fiberbridge::app {

/// The files and the one chain's settings (analysis/record_chain.h): a scene's from
/// record_chain_options (test_section.h), the command line's from its options.
struct ReduceStepOptions : analysis::RecordChainOptions {
  std::vector<std::string> files;
  std::string where = "reduce"; ///< names the geometry's origin in messages (scene or CLI)
};

struct ReduceOutcome {
  std::vector<analysis::TestRecord> records;
  std::vector<analysis::ReducedRecord> reduced;
  analysis::ReducedMean mean;
};

/// Reads and reduces every record; writes rcurve_test.csv, rcurve_test_mean.csv,
/// record_clean_<name>.csv per record (the cleaned rows the plots show, new crack readings
/// flagged), rdelta_test.csv when delta_root was measured (the R(delta_root) replicates that
/// `fiberbridge extract` reads), and the plots; adds summary["reduce"].
ReduceOutcome run_reduce(const ReduceStepOptions& o, const std::string& out_dir, Json& summary);

} // namespace fiberbridge::app
