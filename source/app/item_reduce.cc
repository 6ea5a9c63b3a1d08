// Scene item `reduce` (section Test): raw DCB records -> R(a) (reduce_step.h).
#include "fiberbridge/app/items.h"
#include "fiberbridge/app/reduce_step.h"
#include "fiberbridge/app/scene.h"
#include "fiberbridge/app/section.h"
#include "fiberbridge/app/test_section.h"
#include "fiberbridge/core/error.h"

#include <cmath>

namespace fiberbridge::app {

void declare_test_section(dealii::ParameterHandler& prm) {
  declare_section<TestSection>(prm, "Test");
}

namespace {

/// The Test section and the Specimen, as `reduce` uses them; every listed record must exist.
ReduceStepOptions reduce_options(SceneContext& ctx) {
  const auto t = parse_section<TestSection>(*ctx.prm, "Test");
  ReduceStepOptions o;
  o.where = ctx.scene_file + ": Specimen";
  const specimen::Specimen s = ctx.specimen();
  o.specimen.width = s.width;
  o.specimen.arm_thickness = s.arm_thickness();
  o.specimen.length = s.length;
  o.files = t.resolved_files(ctx.scene_file);
  if (o.files.empty())
    throw InputError(ctx.scene_file + ": Test/Files lists no record; give one or more CSV files");
  o.read = t.read_options(ctx.scene_file);
  // With `dic` in the scene, Test/Files is the machine record dic read; reduce reads the record
  // dic wrote from it (dic_record.csv, our column names) once dic has run (item_dic.cc).
  if (!ctx.records_from_dic.empty()) {
    o.files = ctx.records_from_dic;
    o.read.columns = {};
  }
  o.reduce.large_displacement_correction = t.large_displacement_correction;
  o.reduce.plateau_fraction = t.plateau_fraction;
  if (t.use_specimen_initial_crack)
    o.specimen.initial_crack = s.initial_crack;
  o.reduce.smoothing_window = t.smoothing_window > 0 ? t.smoothing_window : NAN;
  o.specimen.pin_to_arm_midplane = t.pin_to_arm_midplane > 0 ? t.pin_to_arm_midplane : NAN;
  o.specimen.pin_to_block_edge = t.pin_to_block_edge > 0 ? t.pin_to_block_edge : NAN;
  return o;
}

} // namespace

void check_reduce_item(SceneContext& ctx) {
  reduce_options(ctx);
}

void run_reduce_item(SceneContext& ctx) {
  auto& prm = *ctx.prm;
  const ReduceStepOptions o = reduce_options(ctx);
  const auto r = run_reduce(o, ctx.output_dir, ctx.summary);
  // With a measured notch-root opening, R(delta_root) feeds extract/fit (which run after reduce)
  // unless the scene names its own Data/File.
  if (!r.reduced.front().delta_root.empty()) {
    prm.enter_subsection("Data");
    if (prm.get("File").empty()) {
      prm.set("File", ctx.out("rdelta_test.csv"));
      ctx.summary["reduce"]["notes"].push_back("Data/File set to rdelta_test.csv: extract and fit "
                                               "use the records' R(delta_root)");
    }
    prm.leave_subsection();
  }
}

} // namespace fiberbridge::app
