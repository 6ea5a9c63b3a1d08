#pragma once
// Geometry of the FEM specimen (docs/design.md section 2, "Geometry and loading"): the mesh lines
// of dcb_mesh_lines and the slit coarse mesh with doubled crack-plane vertices, extruded over
// the width in 3D.
#include "fiberbridge/fem/dcb_simulation.h"
#include "fiberbridge/specimen/specimen.h"

#include <deal.II/distributed/tria.h>

#include <vector>

namespace fiberbridge::fem {

/// The mesh lines the rest of the engine steps along.
struct DcbGeometry {
  double dx = 0;               ///< element length along x: one tip advance [m]
  std::vector<double> x_lines; ///< from the load line x = 0 to x = Length [m]
  std::vector<double> z_lines; ///< {0} in 2D; 0 .. width in 3D [m]
  /// The x of the last free face across the arm (normal mostly along x) between the load line
  /// and the notch, such as an end block's edge; 0 on a plain arm [m]. The far-field J ramp
  /// starts one arm thickness beyond it, away from the re-entrant corner's singular W
  /// (j_integrals.h).
  double x_last_end_feature = 0;
};

/// Builds the coarse mesh of both arms in `triangulation` (material id 0 top arm, 1 bottom arm),
/// or reads FEM/Mesh file (specimen_mesh.h). The arms share no vertex on the crack plane, so
/// p4est keeps the slit open.
template <int dim>
DcbGeometry make_dcb_mesh(const specimen::Specimen& specimen, const FemParameters& parameters,
                          dealii::parallel::distributed::Triangulation<dim>& triangulation);

} // namespace fiberbridge::fem
