// Scene item "beam": the fast beam model of the DCB (docs/design.md section 2), section "Beam".
#include "fiberbridge/app/scene/models.h"

#ifdef FIBERBRIDGE_HAVE_BEAM
#include "fiberbridge/app/items/item_beam.h"
#include "fiberbridge/app/outputs/report_simulation.h"
#include "fiberbridge/app/scene/scene_context.h"
#include "fiberbridge/app/scene/section.h"
#include "fiberbridge/beam/dcb_beam.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/renamed_key.h"
#include "fiberbridge/core/units.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/patterns.h>

#endif

namespace fiberbridge::app {

#ifdef FIBERBRIDGE_HAVE_BEAM
using dealii::Patterns::Double;
using dealii::Patterns::Integer;
using units::mm;

namespace {
/// Shortest decimal form of a default ("0.5", "1e-10"), as a user would type it: the stream's
/// default six significant digits.
std::string default_text(double v) {
  return fmt(v, 6);
}
} // namespace

namespace {
/// The Beam section: beam::BeamParameters (which has no deal.II) declared, parsed and validated.
struct BeamSection : beam::BeamParameters {
  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm);
};

void BeamSection::declare_parameters(dealii::ParameterHandler& prm) {
  const beam::BeamParameters d;
  prm.declare_entry("Number of elements", std::to_string(d.n_elements), Integer(4, 10000000),
                    "Timoshenko elements along the ligament from the initial crack to the far "
                    "end (the free notch is one exact element). Cost grows linearly.");
  prm.declare_entry("Tip advance", default_text(d.tip_advance / mm), Double(0),
                    "Crack growth between recorded states in mm (rounded to whole elements, at "
                    "least one). The external work is integrated over these steps.");
  prm.declare_entry("Foundation modulus", "0", Double(0),
                    "Winkler foundation of the intact ligament in MPa/mm, acting on the opening. "
                    "0 = calibrated so that the arm's root rotation matches corrected beam "
                    "theory (Hashemi, Kinloch & Williams 1990).");
  prm.declare_entry("Shear coefficient", default_text(d.shear_coefficient), Double(0),
                    "Timoshenko shear coefficient of the rectangular arm (5/6).");
  prm.declare_entry("Minimum ligament", "0", Double(0),
                    "Stop when the ligament ahead of the tip is shorter than this, in mm; 0 = the "
                    "specimen height.");
  prm.declare_entry("Steady state window", default_text(d.steady_state_window / mm), Double(0),
                    "Steady state: after the notch root moved, R_J has stayed within the plateau "
                    "tolerance over at least this much crack growth [mm]; G_ss is its mean there "
                    "(the same rule and key in the Beam, FEM and MPM sections).");
  prm.declare_entry("Plateau tolerance", default_text(d.plateau_tolerance), Double(0, 1),
                    "Relative spread (max - min over mean) of R_J over the steady-state window "
                    "accepted as a plateau.");
  prm.declare_entry("Newton tolerance", default_text(d.newton_tolerance), Double(0, 0.01),
                    "Relative residual (to the initiation load) and relative tip-opening error "
                    "at which Newton stops.");
  prm.declare_entry("Maximum Newton iterations", std::to_string(d.max_newton_iterations),
                    Integer(1, 10000), "Newton iterations per tip position before giving up.");
  prm.declare_entry("Newton iterations", "", dealii::Patterns::Anything(),
                    "Deprecated name of Maximum Newton iterations (the FEM's key); still "
                    "accepted, with a note in the run's notes (an error if both are given and "
                    "differ).");
  prm.declare_entry("Kinematics", "small", dealii::Patterns::Selection("small|finite"),
                    "small: linear beam theory. finite: the load and the load-point opening "
                    "come from the elastica of the free arm (load line to tip) at the "
                    "small-rotation tip moment, so the load's lever arm shortens as the arm "
                    "rotates (thin arms, openings past a tenth of the crack length). Small-"
                    "rotation runs say in their notes when the load is more than 1 % off.");
}

void BeamSection::parse_parameters(dealii::ParameterHandler& prm) {
  n_elements = prm.get_integer("Number of elements");
  tip_advance = prm.get_double("Tip advance") * mm;
  // MPa/mm = 1e9 Pa/m.
  foundation_modulus = prm.get_double("Foundation modulus") * 1e9;
  shear_coefficient = prm.get_double("Shear coefficient");
  minimum_ligament = prm.get_double("Minimum ligament") * mm;
  steady_state_window = prm.get_double("Steady state window") * mm;
  plateau_tolerance = prm.get_double("Plateau tolerance");
  newton_tolerance = prm.get_double("Newton tolerance");
  // The old name (the shared renaming rule, core/renamed_key.h): used when given, with a note.
  const RenamedKey key{"Beam", "Maximum Newton iterations", "Newton iterations"};
  const std::string text = prm.get(key.name), old_text = prm.get(key.old_name);
  max_newton_iterations = static_cast<int>(resolve_renamed(
      key, prm.get_integer(key.name),
      text != std::to_string(BeamParameters().max_newton_iterations), text,
      deprecated_number(key, old_text, "a whole number in [1, 10000]", 1, 10000, true), old_text,
      "the same key as the FEM's", deprecation_notes));
  finite_rotations = prm.get("Kinematics") == "finite";
  validate("Beam");
}
} // namespace

static void declare_beam_section(dealii::ParameterHandler& prm) {
  declare_section<BeamSection>(prm, "Beam");
}

beam::BeamParameters read_beam_section(dealii::ParameterHandler& prm) {
  return parse_section<BeamSection>(prm, "Beam");
}

static void parse_beam_section(dealii::ParameterHandler& prm, SceneParameters& out) {
  parse_into<BeamSection, beam::BeamParameters>(prm, "Beam", out);
}

namespace {
const beam::BeamParameters& beam_parameters(const SceneContext& ctx) {
  return ctx.parameters().section<beam::BeamParameters>("Beam");
}
} // namespace

static void check_beam_item(SceneContext& ctx) {
  const beam::BeamParameters params = beam_parameters(ctx);
  ctx.law_known_before_run();
  if (ctx.specimen_from_section())
    beam::check_dcb_inputs(ctx.specimen(), ctx.material(), params);
}

static result::SimulationResult simulate_beam_law(const SceneContext& ctx,
                                                  const law::TractionLaw& law, double j_tip,
                                                  const ProgressLines& progress) {
  return beam::simulate_dcb(ctx.specimen(), ctx.material(), law, j_tip, beam_parameters(ctx),
                            progress);
}

static ItemOutcome run_beam_item(const SceneContext& ctx) {
  const beam::BeamParameters params = beam_parameters(ctx);
  auto progress = [&ctx](const std::string& line) { ctx.progress(line); };
  result::SimulationResult result =
      beam::simulate_dcb(ctx.specimen(), ctx.material(), *ctx.law(), ctx.j_tip(), params, progress);
  return report_simulation(ctx, std::move(result), "n_elements");
}
#endif // FIBERBRIDGE_HAVE_BEAM

/// The model's registry entry (items/models.cc): what every build knows of it, and, when its
/// library is built, what it does.
SimulationModel beam_model() {
  SimulationModel m;
  m.name = "beam";
  m.section = "Beam";
  m.cost = 1.0;
  m.ladder_default = "Number of elements = 50, 100, 200, 400";
  m.ladder_doc = "'Key = v1, v2, ...' (keys of the Beam section; several keys separated by ';' "
                 "vary together).";
  m.identify_builtin = true;
#ifdef FIBERBRIDGE_HAVE_BEAM
  m.built = true;
  m.declare = &declare_beam_section;
  m.parse = &parse_beam_section;
  m.check = &check_beam_item;
  m.run = &run_beam_item;
  m.simulate = &simulate_beam_law;
#endif
  return m;
}

} // namespace fiberbridge::app
