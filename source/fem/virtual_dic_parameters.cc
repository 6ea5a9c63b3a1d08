// FEM/Virtual DIC (dcb_simulation.h, FemParameters::VirtualDic): the keys of the virtual test,
// in the scene's units (mm, mm/min, Hz, s).
#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/dcb_simulation.h"

#include <deal.II/base/parameter_handler.h>

namespace fiberbridge::fem {

using dealii::Patterns::Bool;
using dealii::Patterns::Double;
using dealii::Patterns::Integer;
using dealii::Patterns::Selection;

void FemParameters::VirtualDic::declare_parameters(dealii::ParameterHandler& prm) {
  prm.declare_entry("Enabled", "false", Bool(),
                    "Write the files a DIC system and a testing machine would write for this run "
                    "into <Output directory>/virtual_test (2D, one MPI rank): frames/dcb_0001... "
                    "in the Format's layout, machine.csv, virtual_test_truth.csv and dic_scene.prm "
                    "(docs/design.md section 2, \"Virtual DIC test\").");
  prm.declare_entry("Format", "vic", Selection(result::dic_layout_selection()),
                    "The frames' layout: " + result::dic_layout_descriptions() +
                        " (dic/layouts.h says what each writes).");
  prm.declare_entry("Frame rate", "1", Double(0), "Images per second [Hz].");
  prm.declare_entry("Record rate", "10", Double(0), "Machine record rows per second [Hz].");
  prm.declare_entry("Crosshead rate", "5", Double(0),
                    "Load-point opening rate of the virtual machine [mm/min]: the clock of the "
                    "frames and the record (time = opening / rate, running maximum).");
  prm.declare_entry("First frame time", "0", Double(),
                    "Time of the first image on the machine's clock [s] (a trigger offset).");
  prm.declare_entry("X from", "0", Double(), "Field of view, x from the load line [mm].");
  prm.declare_entry("X to", "0", Double(),
                    "Field of view [mm]; X to <= X from: the specimen's length.");
  prm.declare_entry("Y from", "0", Double(), "Field of view, y from the crack plane [mm].");
  prm.declare_entry("Y to", "0", Double(),
                    "Field of view [mm]; Y to <= Y from: both arms. Rows sit half a Point "
                    "spacing off the crack plane.");
  prm.declare_entry("Point spacing", "1", Double(0), "DIC step between points [mm].");
  prm.declare_entry("Displacement noise", "0.001", Double(0),
                    "Standard deviation of the Gaussian noise on each displacement component "
                    "[mm] (seeded: Seed).");
  prm.declare_entry("Strain window", "5", Double(0),
                    "Side of the square window of the least-squares plane fit that gives the "
                    "strains [mm] (VIC's strain filter, DICe's virtual strain gauge).");
  prm.declare_entry("Strain tensor", "infinitesimal", Selection("infinitesimal|lagrange"),
                    "Strain exported: infinitesimal or Green-Lagrange.");
  prm.declare_entry("Coordinates", "mm", Selection("mm|px"),
                    "Frame coordinates and displacements in mm (specimen coordinates) or pixels "
                    "(Pixel size; from a corner one spacing outside the field of view).");
  prm.declare_entry("Pixel size", "0.02", Double(0),
                    "[mm/px]; also turns the noise into VIC's and DICe's sigma [px].");
  prm.declare_entry("Y axis", "up", Selection("up|down"),
                    "Frame y axis: up (specimen) or down (image convention; v and exy flip).");
  prm.declare_entry("Failed fraction", "0", Double(0, 1),
                    "Share of points that fail to correlate in each frame (random, seeded).");
  prm.declare_entry("Seed", "1", Integer(0), "Seed of the noise and the failed points.");
}

void FemParameters::VirtualDic::parse_parameters(dealii::ParameterHandler& prm) {
  using units::mm;
  auto& s = settings;
  s.enabled = prm.get_bool("Enabled");
  s.layout = result::parse_dic_layout(prm.get("Format"), "FEM/Virtual DIC/Format");
  s.frame_rate = prm.get_double("Frame rate");
  s.record_rate = prm.get_double("Record rate");
  s.crosshead_rate = prm.get_double("Crosshead rate") * mm / 60;
  s.first_frame_time = prm.get_double("First frame time");
  s.x_from = prm.get_double("X from") * mm;
  s.x_to = prm.get_double("X to") * mm;
  s.y_from = prm.get_double("Y from") * mm;
  s.y_to = prm.get_double("Y to") * mm;
  s.spacing = prm.get_double("Point spacing") * mm;
  s.noise = prm.get_double("Displacement noise") * mm;
  s.strain_window = prm.get_double("Strain window") * mm;
  s.lagrange = prm.get("Strain tensor") == "lagrange";
  s.pixels = prm.get("Coordinates") == "px";
  s.pixel_size = prm.get_double("Pixel size") * mm;
  s.y_down = prm.get("Y axis") == "down";
  s.failed_fraction = prm.get_double("Failed fraction");
  s.seed = std::uint64_t(prm.get_integer("Seed"));
}

} // namespace fiberbridge::fem
