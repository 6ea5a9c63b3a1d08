// Scene item `reduce` (section Test): raw DCB records -> R(a) (reduce_step.h).
#include "fiberbridge/app/items.h"
#include "fiberbridge/app/reduce_step.h"
#include "fiberbridge/app/scene.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

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
                    "ASTM D5528 / ISO 15024 F (and N with end blocks) on MBT, CC, MCC.");
  prm.declare_entry("Pin to arm mid-plane", "0", dealii::Patterns::Double(0),
                    "l1 of D5528/ISO 15024 in mm; 0: half the arm thickness (hinges).");
  prm.declare_entry("Pin to block edge", "0", dealii::Patterns::Double(0),
                    "l2 of D5528/ISO 15024 in mm (end blocks); 0: no blocks, N = 1.");
  prm.declare_entry("Crack back tolerance", "1", dealii::Patterns::Double(0),
                    "Crack readings may fall this far (mm) below the longest earlier reading "
                    "(tracking noise) and are held at it; further is an error.");
  prm.declare_entry("Plateau fraction", "0.333333", dealii::Patterns::Double(0.01, 1),
                    "The plateau is the mean over this last fraction of the crack extension.");
  prm.leave_subsection();
}

void run_reduce_item(SceneContext& ctx) {
  auto& prm = *ctx.prm;
  ReduceStepOptions o;
  o.where = ctx.scene_file + ": Specimen";
  const law::Specimen s = ctx.specimen();
  o.specimen.width = s.width;
  o.specimen.arm_thickness = s.arm_thickness();
  o.specimen.length = s.length;
  prm.enter_subsection("Test");
  std::istringstream files(prm.get("Files"));
  for (std::string f; std::getline(files, f, ',');) {
    const auto b = f.find_first_not_of(" \t");
    if (b != std::string::npos)
      o.files.push_back(
          resolve_scene_path(f.substr(b, f.find_last_not_of(" \t") - b + 1), ctx.scene_file));
  }
  if (o.files.empty())
    throw InputError(ctx.scene_file + ": Test/Files lists no record; give one or more CSV files");
  o.read.columns =
      analysis::RecordColumnMap::parse(prm.get("Columns"), ctx.scene_file + ": Test/Columns");
  o.read.crack_back_tolerance = prm.get_double("Crack back tolerance") * mm;
  if (prm.get_bool("Use specimen initial crack"))
    o.specimen.initial_crack = s.initial_crack;
  const double w = prm.get_double("Smoothing window");
  o.reduce.smoothing_window = w > 0 ? w * mm : NAN;
  o.reduce.large_displacement_correction = prm.get_bool("Large displacement correction");
  o.reduce.plateau_fraction = prm.get_double("Plateau fraction");
  const double l1 = prm.get_double("Pin to arm mid-plane"),
               l2 = prm.get_double("Pin to block edge");
  o.specimen.pin_to_arm_midplane = l1 > 0 ? l1 * mm : NAN;
  o.specimen.pin_to_block_edge = l2 > 0 ? l2 * mm : NAN;
  prm.leave_subsection();
  run_reduce(o, ctx.output_dir, ctx.summary);
}

} // namespace fiberbridge::app
