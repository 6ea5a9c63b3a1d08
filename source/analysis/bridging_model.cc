// The fiber-bridging model of seed section 3.4 (Eqs. 9-15). SI units.
//
// Everything below works with u = 1 - r_b = x_b / l_b next to r_b: for small opening slopes k
// the intact-fiber zone ends close to the zone edge (u ~ 5.6 k for tracheids), and forming 1 - r
// from a rounded r would lose the digits that Eq. 11's 1/(1 - r_b)^2 amplifies.
#include "fiberbridge/analysis/bridging_model.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"

#include <boost/math/tools/toms748_solve.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>

namespace fiberbridge::analysis {

namespace {

constexpr double pi = 3.14159265358979323846;

void check_fiber(const BridgingFiber& f) {
  const std::pair<const char*, double> props[] = {{"fiber modulus E_f [Pa]", f.E_f},
                                                  {"fiber radius r_f [m]", f.r_f},
                                                  {"fiber strength sigma_fb [Pa]", f.sigma_fb},
                                                  {"peeling toughness G_c [J/m^2]", f.G_c}};
  for (const auto& [name, value] : props)
    if (!(std::isfinite(value) && value > 0))
      throw InputError(std::string("bridging fiber: ") + name + " is " + num(value) +
                       ", expected a finite positive value");
}

void check_slope(double k) {
  if (!(std::isfinite(k) && k >= 0))
    throw InputError("bridging model: opening slope k = delta/l_b is " + num(k) +
                     ", expected a finite value >= 0");
}

/// Eq. 11's factor from r_b and u = 1 - r_b given separately (see the file comment).
double factor(double r, double u) {
  if (r < 0.1) {
    // r(1+r)/(1-r)^3 = sum_{n>=1} n^2 r^n, so F = (1/r) int_0^r = sum n^2 r^n / (n+1). The closed
    // form subtracts two numbers near 1 to get F ~ r/2: below r = 0.1 the series is the accurate
    // one (ratio of successive terms < 0.2, so ~20 terms reach double precision).
    double sum = 0, power = r;
    for (int n = 1; n < 200; ++n, power *= r) {
      const double term = double(n) * n * power / (n + 1);
      sum += term;
      if (term <= 1e-17 * sum)
        break;
    }
    return sum;
  }
  return (2 * r - 1) / (u * u) - std::log(u) / r;
}

/// Eq. 12 as u = 1 - r_b. r_b is the smaller root of r^2 - 2(1 + phi^2) r + 1 = 0; the roots
/// multiply to 1, so r_b = 1/(1 + phi^2 + phi sqrt(2 + phi^2)), which has no cancellation at any
/// phi (the printed minus form cancels for large phi).
std::pair<double, double> breaking_r_u(double k, const BridgingFiber& f) {
  const double eps_fb = f.sigma_fb / f.E_f;
  const double phi = k / (2 * std::sqrt(eps_fb));
  const double root = phi * std::sqrt(2 + phi * phi);
  const double big = 1 + phi * phi + root;
  return {1 / big, (phi * phi + root) / big};
}

/// Eq. 14 as u = 1 - r_b. With s = k (A_f E_f / (4 W_f G_c))^(1/4), r/(1-r)^4 = s^-4 becomes
/// h(u) = (u/s)^4 + u - 1 = 0: a polynomial without the pole at r = 1, increasing on (0, 1)
/// (h' = 4u^3/s^4 + 1 > 0), so its root is unique. h(s/(1+s)) = (1+s)^-4 - (1+s)^-1 <= 0 and
/// h(min(1, s)) > 0 bracket it tightly; TOMS 748 (bracketing, superlinear) solves it.
std::pair<double, double> peeling_r_u(double k, const BridgingFiber& f) {
  if (k == 0)
    return {1.0, 0.0}; // no opening: no fiber is loaded, all remain attached
  const double s = k * std::pow(f.area() * f.E_f / (4 * f.peel_width() * f.G_c), 0.25);
  const auto h = [s](double u) {
    const double q = u / s;
    return q * q * q * q + u - 1;
  };
  double lo = s / (1 + s), hi = std::min(1.0, s);
  const double h_lo = h(lo), h_hi = h(hi);
  if (h_lo == 0)
    return {1 - lo, lo};
  if (h_hi == 0)
    return {1 - hi, hi};
  std::uintmax_t iterations = 100;
  // Relative bracket width ~ 4 eps: u to full double precision (u is all we need downstream).
  const boost::math::tools::eps_tolerance<double> tol(std::numeric_limits<double>::digits - 2);
  const auto bracket = boost::math::tools::toms748_solve(h, lo, hi, h_lo, h_hi, tol, iterations);
  if (iterations >= 100)
    throw ComputationError("Eq. 14: peeling root for k = " + num(k) +
                           " did not converge in 100 TOMS 748 iterations");
  const double u = 0.5 * (bracket.first + bracket.second);
  return {1 - u, u};
}

std::pair<double, double> r_u(double k, const BridgingFiber& f, BridgingMechanism m) {
  switch (m) {
  case BridgingMechanism::breaking:
    return breaking_r_u(k, f);
  case BridgingMechanism::peeling:
    return peeling_r_u(k, f);
  case BridgingMechanism::governing:
    break;
  }
  // Seed section 3.4: x_b is set by whichever mechanism gives the larger x_b (larger u).
  const auto b = breaking_r_u(k, f);
  const auto p = peeling_r_u(k, f);
  return p.second > b.second ? p : b;
}

void check_stress_args(double delta, double l_b, double rho_b) {
  if (!(std::isfinite(l_b) && l_b > 0))
    throw InputError("bridging model: zone length l_b is " + num(l_b) + " m, expected > 0");
  if (!(std::isfinite(delta) && delta >= 0))
    throw InputError("bridging model: opening delta is " + num(delta) + " m, expected >= 0");
  if (!(std::isfinite(rho_b) && rho_b >= 0))
    throw InputError("bridging model: bridged fiber density rho_b is " + num(rho_b) +
                     " 1/m^2, expected >= 0");
}

} // namespace

double BridgingFiber::area() const {
  return pi * r_f * r_f;
}
double BridgingFiber::peel_width() const {
  return pi * r_f;
}

BridgingFiber seed_tracheid_fiber() {
  return BridgingFiber{40e9, 20e-6, 648e6, 200};
}

BridgingFiber seed_bundle_fiber(double G_c) {
  return BridgingFiber{10e9, 200e-6, 100e6, G_c};
}

double fiber_strain_exact(double delta, double k, double r, double l_b) {
  check_slope(k);
  if (!(std::isfinite(l_b) && l_b > 0))
    throw InputError("Eq. 9: zone length l_b is " + num(l_b) + " m, expected > 0");
  if (!(r >= 0 && r <= 1))
    throw InputError("Eq. 9: r = 1 - x/l_b is " + num(r) + ", expected in [0, 1]");
  if (!(std::isfinite(delta) && delta >= 0))
    throw InputError("Eq. 9: opening delta is " + num(delta) + " m, expected >= 0");
  const double x = l_b * (1 - r);
  const double delta_x = k * l_b * r; // delta(x) = k (l_b - x)
  const double stretched = std::sqrt(x * x + 0.25 * (delta + delta_x) * (delta + delta_x));
  const double initial = std::sqrt(x * x + 0.25 * (delta - delta_x) * (delta - delta_x));
  if (initial == 0)
    throw InputError("Eq. 9: at r = " + num(r) +
                     " the fiber has zero initial length (zone edge); the strain is unbounded");
  // stretched/initial - 1 without cancellation: stretched^2 - initial^2 = delta * delta(x).
  return delta * delta_x / (initial * (stretched + initial));
}

double fiber_strain_small_k(double k, double r) {
  check_slope(k);
  if (!(r >= 0 && r < 1))
    throw InputError("Eq. 9: r = 1 - x/l_b is " + num(r) + ", expected in [0, 1)");
  return k * k * r / (2 * (1 - r) * (1 - r));
}

double eq11_factor(double r_b) {
  if (!(r_b >= 0 && r_b < 1))
    throw InputError("Eq. 11: r_b is " + num(r_b) +
                     ", expected in [0, 1) (r_b = 1 - x_b/l_b; r_b -> 1 diverges)");
  return factor(r_b, 1 - r_b);
}

double r_b_breaking(double k, const BridgingFiber& f) {
  check_fiber(f);
  check_slope(k);
  return breaking_r_u(k, f).first;
}

double r_b_peeling(double k, const BridgingFiber& f) {
  check_fiber(f);
  check_slope(k);
  return peeling_r_u(k, f).first;
}

BridgingMechanism governing_mechanism(double k, const BridgingFiber& f) {
  check_fiber(f);
  check_slope(k);
  return peeling_r_u(k, f).second > breaking_r_u(k, f).second ? BridgingMechanism::peeling
                                                              : BridgingMechanism::breaking;
}

double r_b(double k, const BridgingFiber& f, BridgingMechanism m) {
  check_fiber(f);
  check_slope(k);
  return r_u(k, f, m).first;
}

double bridging_stress_exact(double delta, double l_b, double rho_b, const BridgingFiber& f,
                             BridgingMechanism m) {
  check_fiber(f);
  check_stress_args(delta, l_b, rho_b);
  const double k = delta / l_b;
  if (k == 0)
    return 0;
  const auto [r, u] = r_u(k, f, m);
  // Eq. 11: sigma = E_f A_f rho_b k^3 / 4 * F(r_b).
  return 0.25 * f.E_f * f.area() * rho_b * k * k * k * factor(r, u);
}

double bridging_stress_eq13(double delta, double l_b, double rho_b, const BridgingFiber& f) {
  check_fiber(f);
  check_stress_args(delta, l_b, rho_b);
  return f.area() * rho_b / (2 * l_b) * f.sigma_fb * delta;
}

double bridging_stress_eq15(double delta, double l_b, double rho_b, const BridgingFiber& f) {
  check_fiber(f);
  check_stress_args(delta, l_b, rho_b);
  // sqrt(E_f G_c / r_f) is sqrt(E_f G_c W_f / A_f) for the cylinder A_f = pi r_f^2, W_f = pi r_f.
  return f.area() * rho_b / (2 * l_b) * std::sqrt(f.E_f * f.G_c / f.r_f) * delta;
}

double bridged_density(double sigma, double delta, double l_b, const BridgingFiber& f,
                       BridgingMechanism m, bool small_k) {
  if (!(std::isfinite(sigma) && sigma >= 0))
    throw InputError("bridged density: stress " + num(sigma) + " Pa, expected >= 0");
  if (!(std::isfinite(delta) && delta > 0))
    throw InputError("bridged density: opening " + num(delta) +
                     " m, expected > 0 (no opening carries no stress)");
  // Every form is linear in rho_b: invert through the stress of unit density.
  double per_density = 0;
  if (!small_k) {
    per_density = bridging_stress_exact(delta, l_b, 1.0, f, m);
  } else {
    const double breaking = bridging_stress_eq13(delta, l_b, 1.0, f);
    const double peeling = bridging_stress_eq15(delta, l_b, 1.0, f);
    // Governing = larger x_b. At leading order sigma ~ 1/(1 - r_b)^2 (Eq. 11), so the larger x_b
    // is the smaller of the two small-k stresses.
    per_density = m == BridgingMechanism::breaking  ? breaking
                  : m == BridgingMechanism::peeling ? peeling
                                                    : std::min(breaking, peeling);
  }
  return sigma / per_density;
}

BridgingEstimate estimate_bridging(double sigma, double delta, double zone_length,
                                   const BridgingFiber& f) {
  BridgingEstimate e;
  e.sigma = sigma;
  e.delta = delta;
  e.zone_length = zone_length;
  e.fiber = f;
  e.rho_peeling = bridged_density(sigma, delta, zone_length, f, BridgingMechanism::peeling, true);
  e.rho_breaking = bridged_density(sigma, delta, zone_length, f, BridgingMechanism::breaking, true);
  e.rho_exact = bridged_density(sigma, delta, zone_length, f, BridgingMechanism::governing, false);
  e.peeling_governs = r_b_peeling(delta / zone_length, f) < r_b_breaking(delta / zone_length, f);
  return e;
}

double BridgingEstimate::stress_exact(double d) const {
  return bridging_stress_exact(d, zone_length, rho_exact, fiber, BridgingMechanism::governing);
}

double BridgingEstimate::stress_eq13(double d) const {
  return bridging_stress_eq13(d, zone_length, rho_exact, fiber);
}

double BridgingEstimate::stress_eq15(double d) const {
  return bridging_stress_eq15(d, zone_length, rho_exact, fiber);
}

} // namespace fiberbridge::analysis
