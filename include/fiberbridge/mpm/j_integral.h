#pragma once
// J integrals from the particle fields as equivalent domain integrals (Shih, Moran & Nakamura
// 1986) in the reference configuration:
//   J = sum_p (P_iJ u_i,1 - W delta_1J) q_,J V_p  -  int_crack t (-d delta/dX) q dX,
// with P the first Piola stress, W the strain energy density and q a weight that is 1 at the tip
// and 0 on the domain's outer edge. Quasi-static: the inertia term is left out, so the kinetic
// energy must stay small (the driver reports it).
#include "fiberbridge/mpm/crack.h"
#include "fiberbridge/mpm/explicit_solver.h"

namespace fiberbridge::mpm {

/// Tip J: q = 1 in the square of half-size r_in around (tip, 0), falling linearly to 0 at r_out
/// (a frame between two contours), minus the work of the crack-surface tractions inside the
/// domain (the traction-zone energy within it), so that the result is the energy release rate of
/// the tip alone [J/m^2].
double tip_j_integral(const ExplicitSolver& solver, const Crack& crack, double r_in, double r_out);

/// Far-field J around the whole zone: q depends on X only, rising across a strip of width w
/// centred at x_left (behind the notch root, where the crack faces are traction-free) and falling
/// across a strip centred at x_right (ahead of the tip, through the whole ligament). Equals
/// J_tip + int_0^delta_root sigma (seed Eq. 1) for any such strips [J/m^2].
double far_field_j_integral(const ExplicitSolver& solver, double x_left, double x_right, double w);

} // namespace fiberbridge::mpm
