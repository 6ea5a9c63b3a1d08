#pragma once
// The exact large-displacement DCB for tests of the beam-theory corrections (ASTM D5528 / ISO
// 15024 F and N): each arm an inextensible Euler elastica, clamped at the crack tip, loaded on
// its mid-plane at the load line by a dead load normal to the crack plane.
#include <cmath>

namespace fiberbridge::exact {
/// One DCB arm as an inextensible Euler elastica: a cantilever of length a clamped at the crack
/// tip and loaded at its free end (on its mid-plane) by a dead load P normal to the crack plane.
/// With tip rotation t, the first integral theta'^2 / 2 = p (sin t - sin theta), p = P a^2/(EI),
/// gives everything by quadrature; with sin(theta) = sin(t) - u^2 the integrands are smooth:
/// I = int_0^sqrt(sin t) 2 du / cos(theta), J = int 2 sin(theta) du / cos(theta); then p = I^2/2,
/// the horizontal reach x/a = 2 sqrt(sin t) / I and the deflection v/a = J / I. (Small t: p = 2t,
/// x = a, v = p a/3, the linear cantilever.)
struct ArmElastica {
  double p, reach, deflection; // P a^2/(EI), x/a, v/a
};

inline ArmElastica arm_elastica(double tip_rotation) {
  const double s = std::sin(tip_rotation), U = std::sqrt(s);
  const int n = 400; // Simpson on smooth integrands: ~1e-12 relative, far below the checks
  double I = 0, J = 0;
  for (int k = 0; k <= n; ++k) {
    const double u = U * k / n, sin_th = s - u * u, cos_th = std::sqrt(1 - sin_th * sin_th);
    const double w = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
    I += w * 2 / cos_th;
    J += w * 2 * sin_th / cos_th;
  }
  I *= U / (3 * n);
  J *= U / (3 * n);
  return {I * I / 2, 2 * U / I, J / I};
}

/// The exact energy release rate of a DCB whose arms are elasticas: the J integral around the
/// crack tip is the two arms' bending energy density at the clamped root, G = 2 M^2 / (2 EI B)
/// with M = P x (the load's lever arm is the deformed arm's reach x, not a).
inline double elastica_G(const ArmElastica& e, double EI, double a, double B) {
  const double P = e.p * EI / (a * a), M = P * e.reach * a;
  return M * M / (EI * B);
}

/// The tip rotation at which an arm of length a releases G = R (bisection: G rises with t).
inline ArmElastica elastica_at_G(double R, double EI, double a, double B) {
  double lo = 1e-9, hi = 1.3;
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    (elastica_G(arm_elastica(mid), EI, a, B) < R ? lo : hi) = mid;
  }
  return arm_elastica(0.5 * (lo + hi));
}

} // namespace fiberbridge::exact
