// The reduce step: records -> R(a) tables, summary block and plots (reduce_step.h). The step
// computes; the files and the summary block are written by reduce_writers.cc.
#include "fiberbridge/app/items/reduce_step.h"

#include "fiberbridge/core/error.h"
#include "outputs/reduce_writers.h"

namespace fiberbridge::app {

ReduceOutcome run_reduce(const ReduceStepOptions& o, const std::string& out_dir, Json& summary) {
  if (o.files.empty())
    throw InputError(o.where + ": no record files given");
  o.specimen.check_test_geometry(o.where);
  // Read every record, reduce each to R(a), average them.
  ReduceOutcome r;
  r.records = analysis::read_records(o.files, o.read);
  bool any_root = false, all_root = true;
  for (const auto& rec : r.records) {
    r.reduced.push_back(analysis::reduce_record(rec, o.specimen, o.reduce));
    any_root = any_root || !rec.delta_root.empty();
    all_root = all_root && !rec.delta_root.empty();
  }
  r.mean = analysis::average_reduced(r.reduced, o.reduce.plateau_fraction);
  // Write: the tables, R(delta_root) when every record has it, the summary block, the plots.
  write_reduce_tables(r, out_dir);
  if (any_root && all_root)
    write_reduce_rdelta(r, out_dir);
  summary["reduce"] = reduce_summary(o, r, any_root, all_root);
  plot_reduce(r, out_dir, summary);
  return r;
}

} // namespace fiberbridge::app
