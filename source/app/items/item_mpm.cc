// Scene item "mpm": the explicit MPM model of the DCB (docs/design.md section 2), section "MPM".
#include "fiberbridge/app/scene/models.h"

#ifdef FIBERBRIDGE_HAVE_MPM
#include "fiberbridge/app/items/item_mpm.h"
#include "fiberbridge/app/outputs/report_simulation.h"
#include "fiberbridge/app/scene/scene_context.h"
#include "fiberbridge/app/scene/section.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/renamed_key.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/mpm/dcb.h"
#include "fiberbridge/mpm/parameters.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/patterns.h>

#include <algorithm>
#include <cmath>
#endif

namespace fiberbridge::app {

#ifdef FIBERBRIDGE_HAVE_MPM
using dealii::Patterns::Double;
using dealii::Patterns::Integer;
using units::mm;

namespace {
/// The MPM section: mpm::MpmParameters (which has no deal.II) declared, parsed and validated.
struct MpmSection : mpm::MpmParameters {
  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm);
};

void MpmSection::declare_parameters(dealii::ParameterHandler& prm) {
  const mpm::MpmParameters d;
  prm.declare_entry("Cell size", std::to_string(d.cell_size / mm), Double(0),
                    "Edge of the square background-grid cells in mm; at least 2 cells through "
                    "each arm. Cost grows like 1/cell^3 (particles and time steps).");
  prm.declare_entry("Particles per cell", std::to_string(d.particles_per_cell), Integer(1, 4),
                    "Particles per cell along each axis (2 = four per cell).");
  prm.declare_entry("CFL factor", std::to_string(d.cfl), Double(0, 0.9),
                    "Time step as a fraction of the time a dilatational wave crosses one cell.");
  prm.declare_entry("PIC fraction", std::to_string(d.pic_fraction), Double(0, 1),
                    "PIC damping beta: particle velocity = (1-beta) FLIP + beta PIC update. "
                    "Removes the kinetic energy that tip advances release.");
  prm.declare_entry("Loading periods", std::to_string(d.loading_periods), Double(1),
                    "Quasi-static loading: the load line reaches the LEFM initiation opening of "
                    "corrected beam theory after this many vibration periods of an a0 arm.");
  prm.declare_entry("Ramp periods", std::to_string(d.ramp_periods), Double(0),
                    "The opening rate rises smoothly from zero over this many vibration periods.");
  prm.declare_entry("Tip advance", "0", Double(0),
                    "Crack growth per propagation event in mm (the Beam's key), rounded to whole "
                    "cells, 1 to 4: the tip moves from node column to node column (the velocity "
                    "fields split per node). 0 = one cell.");
  prm.declare_entry("Growth step", "", dealii::Patterns::Anything(),
                    "Deprecated: the tip advance in whole cells (1 to 4); use Tip advance in mm. "
                    "Still accepted, with a note in the run's notes (an error if both are given "
                    "and differ).");
  prm.declare_entry(
      "J window periods", std::to_string(d.j_window_periods), Double(0, 1),
      "Growth when the tip J averaged over this many periods of the arm at the current crack "
      "length reaches J_tip; the window restarts at each advance and is cut to 0.7 of the "
      "time the loading needs to drive the tip one step.");
  prm.declare_entry("Tip J domain", std::to_string(d.tip_j_cells), Double(1),
                    "The tip J domain integral weights a frame from this many cells around the tip "
                    "to two cells farther.");
  prm.declare_entry("Rigid law rise fraction", "", dealii::Patterns::Anything(),
                    "Deprecated and ignored: rigid laws (linear or exponential softening) are "
                    "inserted extrinsically in every model (a new segment starts at sigma(0+)); "
                    "a value leaves a note in the run's notes.");
  prm.declare_entry("Minimum ligament", "0", Double(0),
                    "Stop when the ligament ahead of the tip would be shorter than this, in mm; "
                    "0 = the specimen height (the Beam's key).");
  prm.declare_entry("End ligament", "", dealii::Patterns::Anything(),
                    "Deprecated name of Minimum ligament [mm]; still accepted, with a note in the "
                    "run's notes (an error if both are given and differ).");
  prm.declare_entry("Steady growth", "0", Double(0),
                    "Stop after the notch root has moved this far in mm (0 = run to the minimum "
                    "ligament).");
  prm.declare_entry("Steady state window", std::to_string(d.steady_state_window / mm), Double(0),
                    "Steady state: after the notch root moved, R_J has stayed within the plateau "
                    "tolerance over at least this much crack growth [mm]; G_ss is its mean there "
                    "(the same rule and key in the Beam, FEM and MPM sections).");
  prm.declare_entry("Plateau tolerance", std::to_string(d.plateau_tolerance), Double(0, 1),
                    "Relative spread (max - min over mean) of R_J over the steady-state window "
                    "accepted as a plateau.");
  prm.declare_entry("Maximum steps", std::to_string(d.max_steps), Integer(1),
                    "Safety bound on the number of explicit time steps.");
  prm.declare_entry("Threads", std::to_string(d.threads), Integer(1, 256),
                    "Threads of the particle loops (the MPM's own work team; results are "
                    "identical for any count). Idle helpers sleep instead of spinning, and the "
                    "solver falls back to one thread when the second does not pay (busy cores).");
  prm.declare_entry("VTU every advances", std::to_string(d.vtu_every_advances), Integer(0),
                    "Write particles (displacement, velocity, stress) every this many tip "
                    "advances to mpm_particles_NNNN.vtu and mpm_particles.pvd (0 = none).");
  prm.declare_entry("Checkpoint interval", std::to_string(d.checkpoint_interval), Double(0),
                    "Wall time in seconds between checkpoints of the whole model state into "
                    "resume/mpm_state.bin of the output directory, which `fiberbridge run SCENE "
                    "--resume` continues from (0 = none).");
}

/// Tip advance [mm] in whole cells: rounded as the beam rounds it to elements, at least one; 0
/// (the default) = one cell, whatever the cell size. The old Growth step counted cells.
int parse_tip_advance(dealii::ParameterHandler& prm, double cell_size,
                      std::vector<std::string>& notes) {
  const RenamedKey key{"MPM", "Tip advance", "Growth step"};
  const std::string text = prm.get(key.name), old_text = prm.get(key.old_name);
  const double advance = prm.get_double(key.name) * mm;
  long cells = 1;
  if (advance > 0 && cell_size > 0) { // a bad cell size is validate()'s to name
    // Past 4 cells validate() refuses the step anyway; said here so that lround cannot overflow.
    if (!(advance / cell_size < 4.5))
      throw InputError("MPM/Tip advance: " + text + " mm is more than 4 cells of " +
                       prm.get("Cell size") + " mm (the tip advances 1 to 4 whole cells)");
    cells = std::max(1L, std::lround(advance / cell_size));
  }
  return static_cast<int>(resolve_renamed(
      key, static_cast<double>(cells), text != "0", text,
      deprecated_number(key, old_text, "a whole number of cells in [1, 4]", 1, 4, true), old_text,
      "in mm as in the Beam section, rounded to whole cells", notes));
}

void MpmSection::parse_parameters(dealii::ParameterHandler& prm) {
  cell_size = prm.get_double("Cell size") * mm;
  particles_per_cell = prm.get_integer("Particles per cell");
  cfl = prm.get_double("CFL factor");
  pic_fraction = prm.get_double("PIC fraction");
  loading_periods = prm.get_double("Loading periods");
  ramp_periods = prm.get_double("Ramp periods");
  growth_step_cells = parse_tip_advance(prm, cell_size, deprecation_notes);
  j_window_periods = prm.get_double("J window periods");
  tip_j_cells = prm.get_double("Tip J domain");
  note_ignored_key("MPM/Rigid law rise fraction", prm.get("Rigid law rise fraction"),
                   "rigid laws are inserted extrinsically in every model (no elastic rise; the "
                   "same discrete law as the beam and the FEM)",
                   deprecation_notes);
  // The old name (the shared renaming rule, core/renamed_key.h): used when given, with a note.
  const RenamedKey ligament{"MPM", "Minimum ligament", "End ligament"};
  const std::string text = prm.get(ligament.name), old_text = prm.get(ligament.old_name);
  end_ligament =
      resolve_renamed(ligament, prm.get_double(ligament.name), text != "0", text,
                      deprecated_number(ligament, old_text, "a length in mm", 0, HUGE_VAL),
                      old_text, "the Beam's key", deprecation_notes) *
      mm;
  steady_growth = prm.get_double("Steady growth") * mm;
  steady_state_window = prm.get_double("Steady state window") * mm;
  plateau_tolerance = prm.get_double("Plateau tolerance");
  max_steps = prm.get_integer("Maximum steps");
  threads = prm.get_integer("Threads");
  vtu_every_advances = prm.get_integer("VTU every advances");
  checkpoint_interval = prm.get_double("Checkpoint interval");
  validate();
}
} // namespace

static void declare_mpm_section(dealii::ParameterHandler& prm) {
  declare_section<MpmSection>(prm, "MPM");
}

mpm::MpmParameters read_mpm_section(dealii::ParameterHandler& prm) {
  return parse_section<MpmSection>(prm, "MPM");
}

static void parse_mpm_section(dealii::ParameterHandler& prm, SceneParameters& out) {
  parse_into<MpmSection, mpm::MpmParameters>(prm, "MPM", out);
}

namespace {
const mpm::MpmParameters& mpm_parameters(const SceneContext& ctx) {
  return ctx.parameters().section<mpm::MpmParameters>("MPM");
}
} // namespace

static void check_mpm_item(SceneContext& ctx) {
  const mpm::MpmParameters params = mpm_parameters(ctx);
  const law::TractionLaw* law = ctx.law_known_before_run();
  if (ctx.specimen_from_section())
    mpm::check_dcb_inputs(ctx.specimen(), ctx.material(), params, law);
}

static result::SimulationResult simulate_mpm_law(const SceneContext& ctx,
                                                 const law::TractionLaw& law, double j_tip,
                                                 const ProgressLines& progress) {
  mpm::MpmParameters params = mpm_parameters(ctx);
  params.resume = false;
  return mpm::simulate_dcb(ctx.specimen(), ctx.material(), law, j_tip, params, "", progress);
}

static ItemOutcome run_mpm_item(const SceneContext& ctx) {
  mpm::MpmParameters params = mpm_parameters(ctx);
  params.resume = ctx.resume;
  auto progress = [&ctx](const std::string& line) { ctx.progress(line); };
  result::SimulationResult result = mpm::simulate_dcb(
      ctx.specimen(), ctx.material(), *ctx.law(), ctx.j_tip(), params, ctx.output_dir, progress);
  return report_simulation(ctx, std::move(result), "n_particles");
}
#endif // FIBERBRIDGE_HAVE_MPM

/// The model's registry entry (items/models.cc): what every build knows of it, and, when its
/// library is built, what it does.
SimulationModel mpm_model() {
  SimulationModel m;
  m.name = "mpm";
  m.section = "MPM";
  m.cost = 100.0; // minutes on the seed specimen (models.h)
  m.ladder_doc = "As Beam ladder, keys of the MPM section.";
  m.target_key = "MPM target error";
#ifdef FIBERBRIDGE_HAVE_MPM
  m.built = true;
  m.declare = &declare_mpm_section;
  m.parse = &parse_mpm_section;
  m.check = &check_mpm_item;
  m.run = &run_mpm_item;
  m.simulate = &simulate_mpm_law;
#endif
  return m;
}

} // namespace fiberbridge::app
