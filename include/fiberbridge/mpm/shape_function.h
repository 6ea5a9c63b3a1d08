#pragma once
// Shape functions between particles and the regular background grid, one axis at a time; the 2D
// weight is the tensor product S = S_x S_y.
#include <cmath>

namespace fiberbridge::mpm {

/// Weights of the (up to) three grid nodes first, first+1, first+2 along one axis, and their
/// derivatives with respect to the particle position.
struct AxisWeights {
  int first = 0;
  double S[3] = {0, 0, 0};
  double dS[3] = {0, 0, 0};
};

/// Constants of the uGIMP weights of one axis: the cell, the particle half-width and the
/// reciprocals the weights need, so that the hot loop multiplies instead of dividing (the
/// divisions were a fifth of the particle-to-grid time).
struct UgimpAxis {
  double cell, lp, inv_cell, inv_clp, inv_2clp, inv_4clp;
  UgimpAxis(double cell_, double lp_)
      : cell(cell_), lp(lp_), inv_cell(1 / cell_), inv_clp(1 / (cell_ * lp_)),
        inv_2clp(1 / (2 * cell_ * lp_)), inv_4clp(1 / (4 * cell_ * lp_)) {}
};

/// Undeformed GIMP (uGIMP, Bardenhagen & Kober 2004): the particle is a box of half-width `lp`
/// that never deforms; the weight is the box average of the linear hat of each node. Needs
/// 0 < lp <= cell/2, so that a particle touches at most three nodes per axis. Smoother than
/// linear MPM weights across cell boundaries, which avoids the cell-crossing noise that spoils
/// stresses and J integrals near a crack.
/// Inline: it runs twice per particle and step.
inline AxisWeights ugimp_weights(double xp, double origin, const UgimpAxis& axis);
inline AxisWeights ugimp_weights(double xp, double origin, double cell, double lp) {
  return ugimp_weights(xp, origin, UgimpAxis(cell, lp));
}

/// Linear hat weights of a point (for crack points, which have no extent): two nodes, the third
/// weight is zero.
AxisWeights linear_weights(double xp, double origin, double cell);

namespace detail {
// uGIMP weight and its derivative for a particle at signed distance r = xp - x_node. All three
// pieces are evaluated and one is selected, without branches, so that the particle loops
// vectorize (the same arithmetic as a branch per piece: the same results to the bit).
inline void ugimp(double r, const UgimpAxis& A, double& S, double& dS) {
  const double a = std::fabs(r);
  const double sign = r < 0 ? -1.0 : 1.0;
  const double S_in = 1 - (r * r + A.lp * A.lp) * A.inv_2clp, dS_in = -r * A.inv_clp;
  const double S_mid = 1 - a * A.inv_cell, dS_mid = -sign * A.inv_cell;
  const double d = A.cell + A.lp - a;
  const double S_out = d * d * A.inv_4clp, dS_out = -sign * d * A.inv_2clp;
  const bool in = a < A.lp, mid = a <= A.cell - A.lp, out = a < A.cell + A.lp;
  S = in ? S_in : mid ? S_mid : out ? S_out : 0.0;
  dS = in ? dS_in : mid ? dS_mid : out ? dS_out : 0.0;
}
} // namespace detail

inline AxisWeights ugimp_weights(double xp, double origin, const UgimpAxis& axis) {
  AxisWeights w;
  // The box [xp - lp, xp + lp] with lp <= cell/2 overlaps at most two cells: nodes first..first+2.
  // (A true division here: a reciprocal could round a box edge on a node into the cell below.)
  w.first = static_cast<int>(std::floor((xp - axis.lp - origin) / axis.cell));
  for (int k = 0; k < 3; ++k)
    detail::ugimp(xp - (origin + (w.first + k) * axis.cell), axis, w.S[k], w.dS[k]);
  return w;
}

} // namespace fiberbridge::mpm
