#pragma once
// The files, plots and summary block of the reduce step (reduce_step.h), apart from its
// computing (docs/design.md section 4, "Parse once and writers apart"): run_reduce reads and
// reduces, then hands its outcome to these.
#include "fiberbridge/app/scene/item_outcome.h"
#include "fiberbridge/app/scene/step_outcomes.h"

#include <string>

namespace fiberbridge::app {

/// rcurve_test.csv (R(a) per reading), initiation_test.csv (ASTM D5528 NL, 5%/max, VIS),
/// rcurve_test_mean.csv and record_clean_<name>.csv per record.
void write_reduce_tables(const ReduceOutcome& r, const std::string& out_dir);

/// rdelta_test.csv: R(delta_root) of the records (every record measured delta_root).
void write_reduce_rdelta(const ReduceOutcome& r, const std::string& out_dir);

/// summary["reduce"]: the specimen, definitions, per-record and mean values and notes.
/// `any_root`, `all_root`: whether some or every record measured delta_root.
Json reduce_summary(const ReduceStepOptions& o, const ReduceOutcome& r, bool any_root,
                    bool all_root);

/// reduce_load_opening.png, reduce_crack_opening.png and reduce_R_<name>.png (listed in
/// the report's plots when gnuplot made them).
void plot_reduce(const ReduceOutcome& r, const std::string& out_dir, ItemReport& report);

} // namespace fiberbridge::app
