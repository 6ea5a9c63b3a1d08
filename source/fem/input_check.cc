#include "fiberbridge/fem/input_check.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/dcb_common.h"
#include "specimen_mesh.h"

#include <deal.II/distributed/tria.h>

namespace fiberbridge::fem {

void check_dcb_inputs(const specimen::Specimen& specimen, const specimen::Material& material,
                      const FemParameters& parameters) {
  specimen.validate();
  material.validate();
  parameters.validate();
  if (parameters.mesh.dimension == 3)
    orthotropic_stiffness<3>(material, parameters);
  else
    orthotropic_stiffness<2>(material, parameters);
  // A read mesh is read (and a .geo meshed, well under a second) here too, on this process
  // alone, so that a bad mesh fails before the scene's first item; its step is the generated one's.
  double dx;
  if (parameters.mesh.file.empty()) {
    dx = dcb_mesh_lines(specimen, parameters).dx;
  } else {
    dealii::parallel::distributed::Triangulation<2> mesh(MPI_COMM_SELF);
    dx = read_specimen_mesh(specimen, parameters, mesh).dx;
  }
  // The engine's first tip is the notch end a0 (a mesh line); its growth loop needs the tip strip
  // and one arm thickness of ligament ahead of it for the J domains.
  const double L = specimen.length, a0 = specimen.initial_crack, h = specimen.arm_thickness();
  const double needed = parameters.j_domain.half_width_elements * dx + h;
  if (a0 + needed > L + 1e-9 * L)
    throw InputError(
        "Specimen: the ligament (Length - Initial crack = " + fmt((L - a0) / units::mm) +
        " mm) is shorter than the tip J domains need (FEM/Tip J domain half-width "
        "elements + one arm thickness = " +
        fmt(needed / units::mm) + " mm)");
}

} // namespace fiberbridge::fem
