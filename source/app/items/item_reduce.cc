// Scene item `reduce` (section Test): raw DCB records -> R(a) (reduce_step.h).
#include "fiberbridge/app/items/items.h"
#include "fiberbridge/app/items/reduce_step.h"
#include "fiberbridge/app/scene/scene_reader.h"
#include "fiberbridge/app/scene/section.h"
#include "fiberbridge/app/scene/test_section.h"
#include "fiberbridge/core/error.h"

#include <algorithm>
#include <cmath>

namespace fiberbridge::app {

void declare_test_section(dealii::ParameterHandler& prm) {
  declare_section<TestSection>(prm, "Test");
}

void parse_test_section(dealii::ParameterHandler& prm, SceneParameters& out) {
  parse_into<TestSection>(prm, "Test", out);
}

namespace {

/// The Test section and the Specimen, as `reduce` uses them; every listed record must exist.
ReduceStepOptions reduce_options(const SceneContext& ctx) {
  const auto& t = ctx.parameters().section<TestSection>("Test");
  ReduceStepOptions o;
  static_cast<analysis::RecordChainOptions&>(o) = ctx.record_chain();
  o.where = ctx.scene_file + ": Specimen";
  o.files = t.resolved_files(ctx.scene_file);
  if (o.files.empty())
    throw InputError(ctx.scene_file + ": Test/Files lists no record; give one or more CSV files");
  // With `dic` in the scene, Test/Files is the machine record dic read; reduce reads the record
  // dic wrote from it (dic_record.csv, our column names) once dic has run (item_dic.cc).
  if (!ctx.records_from_dic.empty()) {
    o.files = ctx.records_from_dic;
    o.read.columns = {};
  }
  return o;
}

} // namespace

void check_reduce_item(SceneContext& ctx) {
  reduce_options(ctx);
}

ItemOutcome run_reduce_item(const SceneContext& ctx) {
  const ReduceStepOptions o = reduce_options(ctx);
  ItemOutcome out;
  auto r = std::make_shared<const ReduceOutcome>(run_reduce(o, ctx.output_dir, out.report));
  // Handed on as typed values (docs/design.md section 4): identify fits these records, and with
  // a measured notch-root opening on every record (run_reduce then also writes rdelta_test.csv)
  // extract and fit take R(delta_root) unless the scene names its own Data/File.
  out.reduced = r;
  out.records = std::shared_ptr<const std::vector<analysis::TestRecord>>(r, &r->records);
  const bool all_root =
      std::all_of(r->reduced.begin(), r->reduced.end(),
                  [](const analysis::ReducedRecord& x) { return !x.delta_root.empty(); });
  if (all_root) {
    out.rdelta_root = std::make_shared<const analysis::RDeltaData>(
        analysis::to_rdelta(r->reduced, ctx.out("rdelta_test.csv")));
    // The key as set: reduce does not validate the Data section (extract does, when it runs).
    const bool data_file_given = !ctx.parameters().entry("Data/File").empty();
    if (!data_file_given)
      out.report["reduce"]["notes"].push_back("extract and fit use the records' R(delta_root) "
                                              "(rdelta_test.csv): Data/File names no file");
  }
  return out;
}

} // namespace fiberbridge::app
