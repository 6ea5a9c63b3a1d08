// Scene item `dic` (section DIC): DIC frames and the machine record (Test/Files) -> the test record
// dic_record.csv that `reduce` reads in the same scene (dic_step.h).
#include "fiberbridge/app/items/dic_step.h"
#include "fiberbridge/app/items/items.h"
#include "fiberbridge/app/scene/dic_section.h"
#include "fiberbridge/app/scene/section.h"
#include "fiberbridge/app/scene/test_section.h"
#include "fiberbridge/core/error.h"

#include <filesystem>

namespace fiberbridge::app {

void declare_dic_section(dealii::ParameterHandler& prm) {
  declare_section<DicSection>(prm, "DIC");
}

void parse_dic_section(dealii::ParameterHandler& prm, SceneParameters& out) {
  parse_into<DicSection>(prm, "DIC", out);
}

namespace {

/// The DIC and Test sections as the item uses them; every file must exist.
DicStepOptions dic_options(SceneContext& ctx) {
  const auto& d = ctx.parameters().section<DicSection>("DIC");
  const auto& t = ctx.parameters().section<TestSection>("Test");
  DicStepOptions o;
  o.where = ctx.scene_file;
  o.dic = d.options();
  if (d.frames.empty())
    throw InputError(ctx.scene_file + ": DIC/Frames names no frame; give a glob or a list");
  o.frames =
      dic::expand_frame_list(d.frames, std::filesystem::path(ctx.scene_file).parent_path().string(),
                             ctx.scene_file + ": DIC/Frames");
  const auto machine = t.resolved_files(ctx.scene_file);
  if (machine.size() != 1)
    throw InputError(ctx.scene_file +
                     ": Test/Files must name the one machine record (time, "
                     "opening, load) that the DIC frames belong to; it lists " +
                     std::to_string(machine.size()));
  o.machine_record = machine.front();
  o.machine_read = ctx.record_chain().read;
  o.initial_crack = ctx.specimen().initial_crack;
  return o;
}

} // namespace

void check_dic_item(SceneContext& ctx) {
  dic_options(ctx);
}

void run_dic_item(SceneContext& ctx) {
  const DicStepOptions o = dic_options(ctx);
  const DicOutcome r = run_dic(o, ctx.output_dir, ctx.summary);
  // reduce (which runs after dic) reads this record instead of Test/Files (item_reduce.cc).
  ctx.records_from_dic = {r.record_path};
}

} // namespace fiberbridge::app
