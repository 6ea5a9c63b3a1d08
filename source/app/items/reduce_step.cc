// The reduce step: records -> R(a) tables, summary block and plots (reduce_step.h). The step
// computes; the files and the summary block are written by reduce_writers.cc.
#include "fiberbridge/app/items/reduce_step.h"

#include "fiberbridge/core/error.h"
#include "outputs/reduce_writers.h"

#include <algorithm>

namespace fiberbridge::app {

namespace {

bool any_root(const ReduceOutcome& r) {
  return std::any_of(r.records.begin(), r.records.end(),
                     [](const analysis::TestRecord& x) { return !x.delta_root.empty(); });
}

bool all_root(const ReduceOutcome& r) {
  return std::all_of(r.records.begin(), r.records.end(),
                     [](const analysis::TestRecord& x) { return !x.delta_root.empty(); });
}

} // namespace

ReduceOutcome reduce_records(const ReduceStepOptions& o) {
  if (o.files.empty())
    throw InputError(o.where + ": no record files given");
  o.specimen.check_test_geometry(o.where);
  return reduce_records(o, analysis::read_records(o.files, o.read));
}

ReduceOutcome reduce_records(const ReduceStepOptions& o, std::vector<analysis::TestRecord> records,
                             const std::function<void(const std::string&)>& progress) {
  if (records.empty())
    throw InputError(o.where + ": no records given");
  o.specimen.check_test_geometry(o.where);
  // Reduce each record to R(a), average them.
  ReduceOutcome r;
  r.records = std::move(records);
  for (const auto& rec : r.records) {
    if (progress)
      progress("reduce: " + rec.name + " (" + std::to_string(r.reduced.size() + 1) + "/" +
               std::to_string(r.records.size()) + ")");
    r.reduced.push_back(analysis::reduce_record(rec, o.specimen, o.reduce));
  }
  r.mean = analysis::average_reduced(r.reduced, o.reduce.plateau_fraction);
  return r;
}

Json reduce_summary_block(const ReduceStepOptions& o, const ReduceOutcome& r) {
  return reduce_summary(o, r, any_root(r), all_root(r));
}

ReduceOutcome run_reduce(const ReduceStepOptions& o, const std::string& out_dir,
                         ItemReport& report) {
  ReduceOutcome r = reduce_records(o);
  // Write: the tables, R(delta_root) when every record has it, the summary block, the plots.
  write_reduce_tables(r, out_dir);
  if (any_root(r) && all_root(r))
    write_reduce_rdelta(r, out_dir);
  report["reduce"] = reduce_summary_block(o, r);
  plot_reduce(r, out_dir, report);
  return r;
}

} // namespace fiberbridge::app
