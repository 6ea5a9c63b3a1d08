// Scene item `reduce` (section Test): raw DCB records -> R(a) (reduce_step.h).
#include "fiberbridge/app/items.h"
#include "fiberbridge/app/reduce_step.h"
#include "fiberbridge/app/scene.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <cmath>
#include <filesystem>
#include <sstream>

namespace fiberbridge::app {

using units::mm;

void declare_test_section(dealii::ParameterHandler& prm) {
  prm.enter_subsection("Test");
  prm.declare_entry("Files", "", dealii::Patterns::Anything(),
                    "Comma-separated raw DCB records (replicates), relative to the scene.");
  prm.declare_entry("Columns", "", dealii::Patterns::Anything(),
                    "Our column names mapped to the files' headers, e.g. 'time_s: Time (s), "
                    "opening_mm: Extension (mm), load_N: Load (N), a_mm: Crack length (mm)'; "
                    "optional delta_root_mm, record. Empty: the files use our names.");
  prm.declare_entry("Use specimen initial crack", "false", dealii::Patterns::Bool(),
                    "a0 = Specimen/Initial crack; false: each record's first crack reading.");
  prm.declare_entry("Smoothing window", "0", dealii::Patterns::Double(0),
                    "Window in crack length of the direct-energy slope fits in mm; 0: automatic "
                    "(the larger of 10 reading spacings and 4 arm thicknesses).");
  prm.declare_entry("Large displacement correction", "true", dealii::Patterns::Bool(),
                    "ASTM D5528 / ISO 15024 F and N on MBT, CC, MCC.");
  prm.declare_entry("Pin to arm mid-plane", "0", dealii::Patterns::Double(0),
                    "l1 of D5528/ISO 15024 in mm; 0: half the arm thickness (hinges).");
  prm.declare_entry("Pin to block edge", "0", dealii::Patterns::Double(0),
                    "l2 of D5528/ISO 15024 in mm (end blocks); 0: no blocks (l2 = 0 in N).");
  prm.declare_entry("Crack back tolerance", "1", dealii::Patterns::Double(0),
                    "Crack readings may fall this far (mm) below the longest earlier reading "
                    "(tracking noise) and are held at it; further is an error.");
  prm.declare_entry("Plateau fraction", "0.333333", dealii::Patterns::Double(0.01, 1),
                    "The plateau is the mean over this last fraction of the crack extension.");
  prm.leave_subsection();
}

namespace {

/// The Test section and the Specimen, as `reduce` uses them; every listed record must exist.
ReduceStepOptions parse_test_section(SceneContext& ctx) {
  auto& prm = *ctx.prm;
  ReduceStepOptions o;
  o.where = ctx.scene_file + ": Specimen";
  const specimen::Specimen s = ctx.specimen();
  o.specimen.width = s.width;
  o.specimen.arm_thickness = s.arm_thickness();
  o.specimen.length = s.length;
  prm.enter_subsection("Test");
  const std::string files = prm.get("Files"), columns = prm.get("Columns");
  o.read.crack_back_tolerance = prm.get_double("Crack back tolerance") * mm;
  const bool use_specimen_a0 = prm.get_bool("Use specimen initial crack");
  const double w = prm.get_double("Smoothing window");
  o.reduce.large_displacement_correction = prm.get_bool("Large displacement correction");
  o.reduce.plateau_fraction = prm.get_double("Plateau fraction");
  const double l1 = prm.get_double("Pin to arm mid-plane"),
               l2 = prm.get_double("Pin to block edge");
  prm.leave_subsection();
  std::istringstream list(files);
  for (std::string f; std::getline(list, f, ',');) {
    const auto b = f.find_first_not_of(" \t");
    if (b == std::string::npos)
      continue;
    f = f.substr(b, f.find_last_not_of(" \t") - b + 1);
    const std::string path = resolve_scene_path(f, ctx.scene_file);
    if (!std::filesystem::exists(path))
      throw InputError(ctx.scene_file + ": Test/Files: record '" + f + "' not found");
    o.files.push_back(path);
  }
  if (o.files.empty())
    throw InputError(ctx.scene_file + ": Test/Files lists no record; give one or more CSV files");
  o.read.columns = analysis::RecordColumnMap::parse(columns, ctx.scene_file + ": Test/Columns");
  if (use_specimen_a0)
    o.specimen.initial_crack = s.initial_crack;
  o.reduce.smoothing_window = w > 0 ? w * mm : NAN;
  o.specimen.pin_to_arm_midplane = l1 > 0 ? l1 * mm : NAN;
  o.specimen.pin_to_block_edge = l2 > 0 ? l2 * mm : NAN;
  return o;
}

} // namespace

void check_reduce_item(SceneContext& ctx) {
  parse_test_section(ctx);
}

void run_reduce_item(SceneContext& ctx) {
  auto& prm = *ctx.prm;
  const ReduceStepOptions o = parse_test_section(ctx);
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
