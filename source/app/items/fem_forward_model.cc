// The FEM as identify's forward model (app/items/fem_forward_model.h).
#include "fiberbridge/app/items/fem_forward_model.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/fem/auto_mesh.h"
#include "fiberbridge/fem/distributed_dcb.h"
#include "fiberbridge/law/exponential_law.h"

#include <algorithm>

namespace fiberbridge::app {

identify::ForwardModel fem_forward_model(fem::FemParameters parameters) {
  // No files: the virtual DIC test writes only for the scene's own FEM run.
  parameters.virtual_dic.settings.enabled = false;
  identify::ForwardModel m;
  m.name = "fem";
  // Finite kinematics rotates the arms itself: ISO 15024's F and N would count the rotation twice.
  m.geometrically_linear =
      parameters.nonlinear.kinematics == fem::FemParameters::Nonlinear::Kinematics::small;
  // The compliance before the crack grows: the first state of an LEFM run (no bridging law, so
  // nothing opens behind the notch before the tip advances), its opening over its load.
  m.initial_compliance = [parameters](const specimen::Specimen& specimen,
                                      const specimen::Material& material) {
    fem::FemParameters p = parameters;
    if (p.mesh.automatic_size())
      p.mesh.element_size = fem::arm_element_size(specimen, p);
    const auto run =
        fem::simulate_dcb(specimen, material, law::NoBridgingLaw(), 100, p, "", {}, MPI_COMM_SELF);
    if (run.rcurve.empty() || !(run.rcurve.front().load > 0))
      throw ComputationError("FEM forward model: the LEFM run for the initial compliance gave "
                             "no state");
    return run.rcurve.front().load_point_opening / run.rcurve.front().load;
  };
  m.run = [parameters](const specimen::Specimen& specimen, const specimen::Material& material,
                       const law::TractionLaw& law, double j_tip, double reach) {
    fem::FemParameters p = parameters;
    // One mesh for every trial law: auto's own choice follows the law's zone estimate
    // (fem::choose_mesh), and a mesh that changes from one trial law to the next makes the misfit
    // jump under the optimizer. The law-free part (arm, notch, ligament) stays; a zone it does
    // not resolve fails the trial below (set FEM/Element size for laws with short zones).
    if (p.mesh.automatic_size())
      p.mesh.element_size = fem::arm_element_size(specimen, p);
    // The FEM stops once R_J is flat over the window after the notch root moved; the misfit needs
    // the whole record, so the window spans the record's crack growth (the run then ends one zone
    // length or more past `reach`, or where the ligament runs out).
    p.steady_state.window = std::max(p.steady_state.window, reach - specimen.initial_crack);
    auto run = fem::simulate_dcb(specimen, material, law, j_tip, p, "", {}, MPI_COMM_SELF);
    // A run that says it cannot be trusted (the zone spans too few elements, or the energy ledger
    // does not close) is a failed trial, as a law the beam cannot follow: its curves would steer
    // the optimizer with a discretization error.
    if (run.steady_state_status == result::SteadyStateStatus::zone_unresolved ||
        run.steady_state_status == result::SteadyStateStatus::ledger_open)
      throw ComputationError("FEM forward run: steady_state_status " +
                             result::to_string(run.steady_state_status) + " (element " +
                             std::to_string(p.mesh.element_size * 1e3) + " mm)");
    return run;
  };
  return m;
}

} // namespace fiberbridge::app
