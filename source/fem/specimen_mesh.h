#pragma once
// A specimen mesh read from a Gmsh file instead of the generated rectangle (docs/design.md
// section 2, "Specimen meshes"; mesh/README.md). The rest of the engine finds the crack plane
// (y = 0) and the load line (x = 0) geometrically, so a read mesh must give it what the generated
// one gives: two arms that share no vertex on the crack plane, crack-plane nodes every dx from
// x = 0 to Specimen/Length with one at a0, and a vertical end face or pin line at x = 0.
#include "dcb_geometry.h"

#include <deal.II/distributed/tria.h>

#include <string>
#include <utility>
#include <vector>

namespace fiberbridge::fem {

/// The Gmsh numbers a .geo file gets: L, a0, h (the arm thickness), dx (crack_plane_step), in
/// mm; layers (Minimum layers per arm) and grading; then FEM/Mesh file parameters. Throws
/// InputError naming FEM/Mesh file parameters on a malformed pair.
std::vector<std::pair<std::string, double>> gmsh_numbers(const specimen::Specimen& specimen,
                                                         const FemParameters& parameters);

/// Reads FEM/Mesh file (a .geo is meshed by the gmsh executable first; coordinates in mm) into
/// `triangulation`
/// with material id 0 on the upper arm (physical surface 1) and 1 on the lower arm (2), checks it
/// against the specimen and returns its mesh lines. Throws InputError naming the file and what it
/// expected.
DcbGeometry read_specimen_mesh(const specimen::Specimen& specimen, const FemParameters& parameters,
                               dealii::parallel::distributed::Triangulation<2>& triangulation);

} // namespace fiberbridge::fem
