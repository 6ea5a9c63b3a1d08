// Scene item `dic` (section DIC): DIC frames and the machine record (Test/Files) -> the test record
// dic_record.csv that `reduce` reads in the same scene (dic_step.h).
#include "fiberbridge/app/items/dic_step.h"
#include "fiberbridge/app/items/items.h"
#include "fiberbridge/app/scene/dic_section.h"
#include "fiberbridge/app/scene/section.h"

namespace fiberbridge::app {

void declare_dic_section(dealii::ParameterHandler& prm) {
  declare_section<DicSection>(prm, "DIC");
}

void parse_dic_section(dealii::ParameterHandler& prm, SceneParameters& out) {
  parse_into<DicSection>(prm, "DIC", out);
}

void check_dic_item(SceneContext& ctx) {
  dic_step_options(ctx);
}

ItemOutcome run_dic_item(const SceneContext& ctx) {
  const DicStepOptions o = dic_step_options(ctx);
  ItemOutcome out;
  const DicOutcome r = run_dic(o, ctx.output_dir, out.report);
  // reduce (which runs after dic) reads this record instead of Test/Files (item_reduce.cc).
  out.records_from_dic = std::vector<std::string>{r.record_path};
  return out;
}

} // namespace fiberbridge::app
