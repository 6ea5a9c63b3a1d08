#pragma once
// The input checks of the FEM DCB model that need no solve, so that a scene can make them before
// its first item runs (a bad FEM value must not surface after minutes of other simulations).
#include "fiberbridge/fem/dcb_simulation.h"

namespace fiberbridge::fem {

/// What the engine (source/fem/dcb_model.h) rejects before it solves anything: the
/// specimen, material and parameters; the 3D orthotropic compliance; a notch spanning enough
/// elements and a ligament holding the tip J domains; a FEM/Mesh file is read and checked
/// (source/fem/specimen_mesh.h). (Any law is accepted: a rigid one is
/// inserted extrinsically, law/rigid_law.h.) Throws InputError naming the section and key.
void check_dcb_inputs(const specimen::Specimen& specimen, const specimen::Material& material,
                      const FemParameters& parameters);

} // namespace fiberbridge::fem
