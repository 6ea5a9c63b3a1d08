#include "fiberbridge/core/error.h"
#include "fiberbridge/core/renamed_key.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/dcb_simulation.h"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <deal.II/base/parameter_handler.h>

namespace fiberbridge::fem {

using dealii::Patterns::Double;
using dealii::Patterns::Integer;

namespace {
/// Throws InputError "FEM/<key>: <what>" unless `ok`.
void require(bool ok, const char* key, const char* what) {
  if (!ok)
    throw InputError(std::string("FEM/") + key + ": " + what);
}

/// A length in mm (Double(0)) or "auto". A pattern, not Anything: a bad value fails where it
/// is set (a study ladder's level names its ladder, as with Double(0) before auto).
class SizeOrAuto : public dealii::Patterns::PatternBase {
public:
  bool match(const std::string& text) const override {
    return text == "auto" || Double(0).match(text);
  }
  std::string description(const OutputStyle style = Machine) const override {
    // Machine style as Anything's, which deal.II's pattern_factory can read back.
    return style == Machine ? "[Anything]" : "A non-negative number or auto";
  }
  std::unique_ptr<dealii::Patterns::PatternBase> clone() const override {
    return std::make_unique<SizeOrAuto>();
  }
};

/// The declared default of Steady state window [mm]: a scene that writes another text gives the
/// key (resolve_renamed).
constexpr const char* default_window_mm = "10";
} // namespace

void FemParameters::Mesh::declare_parameters(dealii::ParameterHandler& prm) {
  prm.declare_entry("Element size", "auto", SizeOrAuto(),
                    "Element length along the crack plane [mm]; also the tip advance per "
                    "release. Uniform over the whole beam length. auto (the default): chosen per "
                    "run from the arm (at most 2 mm, at most 4 crack-plane layers long, the notch "
                    "and ligament) and the law (an estimated cohesive zone length over 6, as far "
                    "as the mesh stays within 65000 dofs); summary.json fem.mesh says what was "
                    "chosen and why. A number is used as given.");
  prm.declare_entry("Grading", "1.3", Double(1),
                    "Growth ratio of element heights from the crack plane (where elements are "
                    "square) towards the beam faces.");
  prm.declare_entry("Minimum layers per arm", "4", Integer(1),
                    "Element layers through each arm at least: the crack-plane layer is "
                    "min(Element size, arm thickness / this number), heights are capped at arm "
                    "thickness / this number. Crack-plane elements more than 4 times longer "
                    "than high are refused.");
  prm.declare_entry("Polynomial degree", "auto", dealii::Patterns::Selection("1|2|auto"),
                    "Degree of the FE_Q elements. auto: Q2 where Q1 elements would bend too "
                    "stiffly (parasitic shear (G_LT/E_L)(Element size/arm thickness)^2 above "
                    "0.004, about 0.5 % load error: thin arms), Q1 elsewhere; the run notes "
                    "the choice.");
  prm.declare_entry("Dimension", "2", Integer(2, 3),
                    "2: plane stress/strain (Material/Plane); 3: the specimen extruded over "
                    "Specimen/Width with free side faces (Material/Plane is then not used).");
  prm.declare_entry("Width elements", "0", Integer(0),
                    "3D only: element layers across the width (0: width / element size, "
                    "rounded, at least 1).");
  prm.declare_entry("Mesh file", "", dealii::Patterns::Anything(),
                    "2D only: the specimen mesh to read instead of the generated rectangle, a "
                    "Gmsh .geo (meshed by gmsh when the run starts) or .msh (format 2 or 4) file, "
                    "relative to the scene, coordinates in mm. Physical surfaces 1 (upper arm, y > "
                    "0) and 2 (lower "
                    "arm); the crack plane y = 0 as two coincident curves, one per arm, with "
                    "nodes every Element size from the load line x = 0 to Specimen/Length. A "
                    ".geo gets the numbers L, a0, h, dx (mm), layers and grading from the scene "
                    "(mesh/README.md). Empty: the generated rectangle.");
  prm.declare_entry("Mesh file parameters", "", dealii::Patterns::Anything(),
                    "More numbers for a .geo Mesh file, as name: value pairs separated by "
                    "commas, lengths in mm (for example taper: 0.02, block_length: 12.7).");
}

void FemParameters::Mesh::parse_parameters(dealii::ParameterHandler& prm) {
  element_size =
      prm.get("Element size") == "auto" ? automatic : prm.get_double("Element size") * units::mm;
  grading = prm.get_double("Grading");
  min_layers = prm.get_integer("Minimum layers per arm");
  degree = prm.get("Polynomial degree") == "auto" ? 0 : prm.get_integer("Polynomial degree");
  dimension = prm.get_integer("Dimension");
  width_elements = prm.get_integer("Width elements");
  file = prm.get("Mesh file");
  file_parameters = prm.get("Mesh file parameters");
}

void FemParameters::Mesh::validate() const {
  require(element_size > 0 || automatic_size(), "Element size", "must be positive (mm) or auto");
  require(grading >= 1, "Grading", "must be >= 1");
  require(min_layers >= 1, "Minimum layers per arm", "must be >= 1");
  require(degree <= 2, "Polynomial degree", "must be 1, 2 or auto");
  require(dimension == 2 || dimension == 3, "Dimension", "must be 2 or 3");
  require(file.empty() || dimension == 2, "Mesh file",
          "reads 2D meshes only; set FEM/Dimension = 2 or leave Mesh file empty");
  require(file_parameters.empty() || !file.empty(), "Mesh file parameters", "needs a Mesh file");
}

void FemParameters::Elasticity3d::declare_parameters(dealii::ParameterHandler& prm) {
  prm.declare_entry("G_LR over E_L", "0.064", Double(0),
                    "3D only: shear modulus in the L-R (x-z) plane over E_L (Wood Handbook, "
                    "Douglas-fir).");
  prm.declare_entry("G_RT over E_L", "0.007", Double(0),
                    "3D only: shear modulus in the R-T (z-y) plane over E_L (Wood Handbook, "
                    "Douglas-fir).");
}

void FemParameters::Elasticity3d::parse_parameters(dealii::ParameterHandler& prm) {
  G_LR_over_E_L = prm.get_double("G_LR over E_L");
  G_RT_over_E_L = prm.get_double("G_RT over E_L");
}

void FemParameters::Elasticity3d::validate() const {
  require(G_LR_over_E_L > 0, "G_LR over E_L", "must be positive");
  require(G_RT_over_E_L > 0, "G_RT over E_L", "must be positive");
}

void FemParameters::Interface::declare_parameters(dealii::ParameterHandler& prm) {
  prm.declare_entry("Interface sub-intervals", "4", Integer(1, 64),
                    "Sub-intervals of the composite Gauss-Lobatto rule on each crack-plane "
                    "element (1: the element nodes only). Resolves the law next to the tip, where "
                    "the opening rises from zero within one element.");
  prm.declare_entry("Contact stiffness factor", "10", Double(0),
                    "Frictionless contact penalty on closed crack faces = factor * E_T / element "
                    "size [Pa/m].");
  prm.declare_entry("Rigid law stiffness factor", "", dealii::Patterns::Anything(),
                    "Deprecated and ignored: rigid laws (linear, exponential) are inserted "
                    "extrinsically in every model (a released segment starts at sigma(0+)); a "
                    "value leaves a note in the run's notes.");
}

void FemParameters::Interface::parse_parameters(dealii::ParameterHandler& prm,
                                                std::vector<std::string>& notes) {
  subintervals = prm.get_integer("Interface sub-intervals");
  contact_stiffness_factor = prm.get_double("Contact stiffness factor");
  note_ignored_key("FEM/Rigid law stiffness factor", prm.get("Rigid law stiffness factor"),
                   "rigid laws are inserted extrinsically in every model (no elastic rise; the "
                   "same discrete law as the beam and the MPM)",
                   notes);
}

void FemParameters::Interface::validate() const {
  require(subintervals >= 1, "Interface sub-intervals", "must be >= 1");
  require(contact_stiffness_factor > 0, "Contact stiffness factor", "must be positive");
}

void FemParameters::Nonlinear::declare_parameters(dealii::ParameterHandler& prm) {
  prm.declare_entry("Maximum opening increment", "0.5", Double(0),
                    "Largest change of the load-point opening in one nonlinear solve [mm]; "
                    "larger changes are reached in sub-steps.");
  prm.declare_entry("Tip toughness tolerance", "0.001", Double(0, 0.1),
                    "Relative deviation of the tip J from J tip accepted when the tip advances.");
  prm.declare_entry("Newton tolerance", "1e-9", Double(0, 1e-3),
                    "Residual norm relative to the load-line reaction norm.");
  prm.declare_entry("Maximum Newton iterations", "25", Integer(1),
                    "Nonlinear iterations per equilibrium solve (either nonlinear solver).");
  prm.declare_entry("Nonlinear solver", "newton", dealii::Patterns::Selection("newton|kinsol"),
                    "newton: own Newton with backtracking line search; kinsol: SUNDIALS KINSOL "
                    "with its line search. Same Jacobian, same tolerance; a KINSOL result is "
                    "re-checked against the Newton tolerance and a failure is reported.");
  prm.declare_entry("Kinematics", "small", dealii::Patterns::Selection("small|finite"),
                    "small: small-strain linear elasticity (fast; its load is low by about "
                    "0.13 (opening/crack length)^2, and a run says so past 1 %); finite: total "
                    "Lagrangian St Venant-Kirchhoff for large arm rotations (thin arms, openings "
                    "of a sizeable fraction of the crack length), J in the reference "
                    "configuration, the load line held at its mean opening.");
}

void FemParameters::Nonlinear::parse_parameters(dealii::ParameterHandler& prm) {
  max_opening_increment = prm.get_double("Maximum opening increment") * units::mm;
  tip_tolerance = prm.get_double("Tip toughness tolerance");
  newton_tolerance = prm.get_double("Newton tolerance");
  max_newton_iterations = prm.get_integer("Maximum Newton iterations");
  solver = prm.get("Nonlinear solver") == "kinsol" ? Solver::kinsol : Solver::newton;
  kinematics = prm.get("Kinematics") == "finite" ? Kinematics::finite : Kinematics::small;
}

void FemParameters::Nonlinear::validate() const {
  require(max_opening_increment > 0, "Maximum opening increment", "must be positive (mm)");
  require(tip_tolerance > 0 && tip_tolerance < 0.1, "Tip toughness tolerance",
          "must lie in (0, 0.1)");
  require(newton_tolerance > 0 && newton_tolerance < 1e-3, "Newton tolerance",
          "must lie in (0, 1e-3)");
  require(max_newton_iterations >= 1, "Maximum Newton iterations", "must be >= 1");
}

void FemParameters::Linear::declare_parameters(dealii::ParameterHandler& prm) {
  prm.declare_entry(
      "Linear solver", "auto",
      dealii::Patterns::Selection("auto|klu|umfpack|mumps|cg_amg|condensed"),
      "Solver of the Jacobian systems: condensed (the linear elastic arms condensed "
      "onto the crack plane once per mesh, a dense inverse of the crack-plane system "
      "bordered at each release, tangent changes by the Woodbury identity, Newton on the "
      "crack-plane unknowns; the same R curves as klu, 4.6 times as fast on the seed mesh; "
      "2D, one MPI rank, Kinematics = small only, else an input "
      "error); auto (condensed where it applies and the "
      "crack plane has at most 1000 dofs, else klu); klu (Trilinos Amesos "
      "KLU; on several ranks "
      "the matrix is gathered on one), mumps (Trilinos Amesos MUMPS, distributed "
      "direct; the choice for MPI runs), both with a low-rank (Woodbury) update "
      "between factorizations; or cg_amg (CG with Trilinos ML AMG: the Jacobian is "
      "made SPD by using the secant instead of the negative softening tangent, so "
      "Newton becomes a quasi-Newton with the same residual test; for meshes too "
      "large for a direct solver). umfpack: deprecated, runs klu (the one engine "
      "has no serial-only solver).");
  prm.declare_entry("Linear tolerance", "1e-10", Double(0, 1),
                    "cg_amg only: CG stops at this residual relative to the right-hand side.");
  prm.declare_entry("Engine", "auto", dealii::Patterns::Selection("auto|serial|distributed"),
                    "Deprecated: there is one engine (p4est + Trilinos, serial on one rank); a "
                    "value other than auto leaves a note in the run's notes. What is left of "
                    "it: distributed keeps the FEM one run over all ranks in a scene of several "
                    "simulations under mpirun (as Dimension = 3 does; docs/cluster.md).");
}

void FemParameters::Linear::parse_parameters(dealii::ParameterHandler& prm,
                                             std::vector<std::string>& notes) {
  // The patterns admit only these values.
  const std::string ls = prm.get("Linear solver");
  solver = ls == "mumps"       ? Solver::mumps
           : ls == "cg_amg"    ? Solver::cg_amg
           : ls == "condensed" ? Solver::condensed
           : ls == "auto"      ? Solver::automatic
                               : Solver::klu;
  if (ls == "umfpack")
    notes.push_back("FEM/Linear solver = umfpack is deprecated: ran klu (the one "
                    "engine's direct solvers are klu and mumps)");
  tolerance = prm.get_double("Linear tolerance");
  const std::string engine = prm.get("Engine");
  if (engine != "auto")
    notes.push_back("FEM/Engine = " + engine +
                    " is deprecated: one engine (p4est + Trilinos) runs on any number of ranks" +
                    (engine == "distributed"
                         ? " (in a scene of several simulations under mpirun it still keeps the "
                           "FEM one run over all ranks, docs/cluster.md)"
                         : std::string(", the value is ignored")));
}

void FemParameters::Linear::validate() const {
  require(tolerance > 0 && tolerance < 1, "Linear tolerance", "must lie in (0, 1)");
}

void FemParameters::JDomain::declare_parameters(dealii::ParameterHandler& prm) {
  prm.declare_entry("Tip J domain half-width", "4", Integer(1),
                    "Half-width of the full-height strip around the tip used for the tip J "
                    "domain integral, in elements.");
}

void FemParameters::JDomain::parse_parameters(dealii::ParameterHandler& prm) {
  half_width_elements = prm.get_integer("Tip J domain half-width");
}

void FemParameters::JDomain::validate() const {
  require(half_width_elements >= 1, "Tip J domain half-width", "must be >= 1 element");
}

void FemParameters::SteadyState::declare_parameters(dealii::ParameterHandler& prm) {
  prm.declare_entry("Steady state window", default_window_mm, Double(0),
                    "Steady state: after the notch root moved, R_J has stayed within the plateau "
                    "tolerance over at least this much crack growth [mm]; G_ss is its mean there.");
  prm.declare_entry("Steady-state window", "", dealii::Patterns::Anything(),
                    "Deprecated name of Steady state window [mm]; still accepted, with a note in "
                    "the run's notes (an error if both are given and differ).");
  prm.declare_entry("Plateau tolerance", "0.01", Double(0, 1),
                    "Relative spread (max - min over mean) of R_J over the steady-state window "
                    "accepted as a plateau.");
}

void FemParameters::SteadyState::parse_parameters(dealii::ParameterHandler& prm,
                                                  std::vector<std::string>& notes) {
  // The old name (the shared renaming rule, core/renamed_key.h): used when given, with a note.
  const RenamedKey key{"FEM", "Steady state window", "Steady-state window"};
  const std::string text = prm.get(key.name), old_text = prm.get(key.old_name);
  window = resolve_renamed(key, prm.get_double(key.name), text != default_window_mm, text,
                           deprecated_number(key, old_text, "a length in mm", 0, HUGE_VAL),
                           old_text, "the same key in the Beam, FEM and MPM sections", notes) *
           units::mm;
  plateau_tolerance = prm.get_double("Plateau tolerance");
}

void FemParameters::SteadyState::validate() const {
  require(window > 0, "Steady state window", "must be positive (mm)");
  require(plateau_tolerance > 0, "Plateau tolerance", "must be positive");
}

void FemParameters::Output::declare_parameters(dealii::ParameterHandler& prm) {
  prm.declare_entry("Output every", "0", Integer(0),
                    "Write VTU every N tip advances (0: only the final state).");
}

void FemParameters::Output::parse_parameters(dealii::ParameterHandler& prm) {
  vtu_every = prm.get_integer("Output every");
}

void FemParameters::declare_parameters(dealii::ParameterHandler& prm) {
  Mesh::declare_parameters(prm);
  Elasticity3d::declare_parameters(prm);
  Interface::declare_parameters(prm);
  Nonlinear::declare_parameters(prm);
  Linear::declare_parameters(prm);
  JDomain::declare_parameters(prm);
  SteadyState::declare_parameters(prm);
  Output::declare_parameters(prm);
  prm.enter_subsection("Virtual DIC");
  VirtualDic::declare_parameters(prm);
  prm.leave_subsection();
}

void FemParameters::parse_parameters(dealii::ParameterHandler& prm) {
  deprecation_notes.clear();
  // Linear first: its notes (umfpack, Engine) come first in the run's notes, as they always did.
  linear.parse_parameters(prm, deprecation_notes);
  mesh.parse_parameters(prm);
  elasticity_3d.parse_parameters(prm);
  interface.parse_parameters(prm, deprecation_notes);
  nonlinear.parse_parameters(prm);
  j_domain.parse_parameters(prm);
  steady_state.parse_parameters(prm, deprecation_notes);
  output.parse_parameters(prm);
  prm.enter_subsection("Virtual DIC");
  virtual_dic.parse_parameters(prm);
  prm.leave_subsection();
  validate();
}

void FemParameters::validate() const {
  mesh.validate();
  elasticity_3d.validate();
  interface.validate();
  nonlinear.validate();
  linear.validate();
  j_domain.validate();
  steady_state.validate();
  virtual_dic.validate();
  require(!virtual_dic.settings.enabled || mesh.dimension == 2, "Virtual DIC/Enabled",
          "the virtual test samples the 2D model only; set FEM/Dimension = 2");
}

} // namespace fiberbridge::fem
