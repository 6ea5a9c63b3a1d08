#include "fiberbridge/beam/elastica.h"

#include "fiberbridge/core/error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace fiberbridge::beam {

namespace {

/// (theta, x, w, M, energy) along the arm; V is constant over one integration segment.
using State = std::array<double, 5>;

State rate(const State& y, double V, double EI, double S) {
  const double c = std::cos(y[0]), s = std::sin(y[0]);
  const double Q = -V * c;
  const double gamma = std::isfinite(S) ? Q / S : 0.0;
  const double dx = c - gamma * s;
  return {y[3] / EI, dx, s + gamma * c, V * dx,
          y[3] * y[3] / (2 * EI) + (std::isfinite(S) ? Q * Q / (2 * S) : 0.0)};
}

/// Integrates from the load point with theta(0) = theta0 to the root.
State integrate(double EI, double S, double length, double theta0, double load,
                const std::vector<ArmPointLoad>& loads, int steps) {
  State y = {theta0, 0, 0, 0, 0};
  double V = load, s = 0;
  const double h_max = length / steps;
  std::size_t next = 0;
  while (s < length) {
    // Integrate up to the next point load (where V jumps) or the root.
    const double end = next < loads.size() ? std::min(loads[next].s, length) : length;
    const int n = std::max(1, int(std::ceil((end - s) / h_max - 1e-9)));
    const double h = (end - s) / n;
    for (int i = 0; i < n; ++i) {
      const State k1 = rate(y, V, EI, S);
      State t;
      for (int j = 0; j < 5; ++j)
        t[j] = y[j] + 0.5 * h * k1[j];
      const State k2 = rate(t, V, EI, S);
      for (int j = 0; j < 5; ++j)
        t[j] = y[j] + 0.5 * h * k2[j];
      const State k3 = rate(t, V, EI, S);
      for (int j = 0; j < 5; ++j)
        t[j] = y[j] + h * k3[j];
      const State k4 = rate(t, V, EI, S);
      for (int j = 0; j < 5; ++j)
        y[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    }
    s = end;
    if (next < loads.size() && loads[next].s <= length) {
      V += loads[next].force;
      ++next;
    } else
      break;
  }
  return y;
}

} // namespace

ElasticaState free_arm_elastica(double EI, double S, double length, double theta_root, double load,
                                const std::vector<ArmPointLoad>& given, int steps) {
  std::vector<ArmPointLoad> loads = given;
  std::sort(loads.begin(), loads.end(),
            [](const ArmPointLoad& a, const ArmPointLoad& b) { return a.s < b.s; });
  // Newton on theta(0) with the derivative by a central difference: theta(length) is smooth
  // and monotone in theta(0) below the buckling-like loads a DCB arm never sees. The start is
  // the small-rotation answer theta0 = theta_root - (moment area)/EI of the load alone.
  double theta0 = theta_root - load * length * length / (2 * EI);
  for (int it = 0; it < 60; ++it) {
    const State y = integrate(EI, S, length, theta0, load, loads, steps);
    const double f = y[0] - theta_root;
    if (std::abs(f) <= 1e-14 * (1 + std::abs(theta_root) + std::abs(theta0))) {
      ElasticaState r;
      r.theta_load = theta0;
      r.rise = y[2];
      r.projection = y[1];
      r.root_moment = y[3];
      r.energy = y[4];
      return r;
    }
    const double d = 1e-7 * (1 + std::abs(theta0));
    const double fp = integrate(EI, S, length, theta0 + d, load, loads, steps)[0];
    const double fm = integrate(EI, S, length, theta0 - d, load, loads, steps)[0];
    const double slope = (fp - fm) / (2 * d);
    if (!(slope != 0) || !std::isfinite(slope))
      break;
    // Rotations beyond a quarter turn per step are not a DCB arm's: damp the step.
    theta0 -= std::clamp(f / slope, -0.5, 0.5);
  }
  throw ComputationError("Beam: the finite-rotation (elastica) solution of the free arm did not "
                         "converge (load " +
                         std::to_string(load) + " N, arm " + std::to_string(length) + " m)");
}

} // namespace fiberbridge::beam
