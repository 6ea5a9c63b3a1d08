#pragma once
// `reduce` as a step shared by the command line (fiberbridge reduce) and the scene item
// (section Test): raw DCB records in, R(a) by direct energy and by MBT/CC/MCC out.
#include "fiberbridge/app/scene/item_outcome.h"
#include "fiberbridge/app/scene/step_outcomes.h"
#include "fiberbridge/specimen/specimen.h"

#include <functional>
#include <string>
#include <vector>

namespace fiberbridge::app {

/// Reads and reduces every record and averages them, writing nothing (the Python module's
/// reduce). Throws InputError for no files, a specimen without its geometry, and the records'.
ReduceOutcome reduce_records(const ReduceStepOptions& o);

/// The same on records already read (`o.files` unused): records a script handed in as arrays
/// (analysis::clean_test_record) or read beforehand. `progress`, when given, gets a line before
/// each record and may throw to stop the reduction (the Python module's Ctrl-C).
ReduceOutcome reduce_records(const ReduceStepOptions& o, std::vector<analysis::TestRecord> records,
                             const std::function<void(const std::string&)>& progress = {});

/// summary.json's `reduce` block of an outcome of `o`.
Json reduce_summary_block(const ReduceStepOptions& o, const ReduceOutcome& r);

/// reduce_records, then writes rcurve_test.csv, rcurve_test_mean.csv,
/// record_clean_<name>.csv per record (the cleaned rows the plots show, new crack readings
/// flagged), rdelta_test.csv when delta_root was measured (the R(delta_root) replicates that
/// `fiberbridge extract` reads), and the plots; adds the report's `reduce` block.
ReduceOutcome run_reduce(const ReduceStepOptions& o, const std::string& out_dir,
                         ItemReport& report);

} // namespace fiberbridge::app
