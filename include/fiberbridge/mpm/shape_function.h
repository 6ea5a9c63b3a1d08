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

/// Undeformed GIMP (uGIMP, Bardenhagen & Kober 2004): the particle is a box of half-width `lp`
/// that never deforms; the weight is the box average of the linear hat of each node. Needs
/// 0 < lp <= cell/2, so that a particle touches at most three nodes per axis. Smoother than
/// linear MPM weights across cell boundaries, which avoids the cell-crossing noise that spoils
/// stresses and J integrals near a crack.
/// Inline: it runs twice per particle and step.
inline AxisWeights ugimp_weights(double xp, double origin, double cell, double lp);

/// Linear hat weights of a point (for crack points, which have no extent): two nodes, the third
/// weight is zero.
AxisWeights linear_weights(double xp, double origin, double cell);

namespace detail {
// uGIMP weight and its derivative for a particle at signed distance r = xp - x_node.
inline void ugimp(double r, double cell, double lp, double& S, double& dS) {
  const double a = std::fabs(r);
  const double sign = r < 0 ? -1.0 : 1.0;
  if (a < lp) {
    S = 1 - (r * r + lp * lp) / (2 * cell * lp);
    dS = -r / (cell * lp);
  } else if (a <= cell - lp) {
    S = 1 - a / cell;
    dS = -sign / cell;
  } else if (a < cell + lp) {
    const double d = cell + lp - a;
    S = d * d / (4 * cell * lp);
    dS = -sign * d / (2 * cell * lp);
  } else {
    S = 0;
    dS = 0;
  }
}
} // namespace detail

inline AxisWeights ugimp_weights(double xp, double origin, double cell, double lp) {
  AxisWeights w;
  // The box [xp - lp, xp + lp] with lp <= cell/2 overlaps at most two cells: nodes first..first+2.
  w.first = static_cast<int>(std::floor((xp - lp - origin) / cell));
  for (int k = 0; k < 3; ++k)
    detail::ugimp(xp - (origin + (w.first + k) * cell), cell, lp, w.S[k], w.dS[k]);
  return w;
}

} // namespace fiberbridge::mpm
