// Reduction of an extracted law to the trilinear law of seed Fig. 1C (section 3.3): sigma1 and
// sigma2 at fixed d1, d2, dc with the area pinned to G_B, and optionally d1, d2 free as well.
#include "fiberbridge/analysis/trilinear_fit.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace fiberbridge::analysis {

namespace {

std::string mm(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x / units::mm << " mm";
  return s.str();
}

/// The two hat functions of the trilinear law: sigma = s1 phi1 + s2 phi2 on [0, dc].
struct Basis {
  double d1, d2, dc;
  double phi1(double x) const {
    if (x <= 0 || x >= d2)
      return 0;
    return x <= d1 ? x / d1 : (d2 - x) / (d2 - d1);
  }
  double phi2(double x) const {
    if (x <= d1 || x >= dc)
      return 0;
    return x <= d2 ? (x - d1) / (d2 - d1) : (dc - x) / (dc - d2);
  }
};

struct Solution {
  double s1 = 0, s2 = 0;
  double ssr = 0;     ///< sum of squared residuals over the points in [0, dc] [Pa^2]
  double max_abs = 0; ///< [Pa]
  std::size_t n_used = 0;
  bool determined = false; ///< false when the data do not fix the free direction
};

/// Least squares of sum (s1 phi1 + s2 phi2 - sigma)^2 under a.s = G_B, a = (d2/2, (dc-d1)/2)
/// (Eq. 8: J_1 + J_2 = G_B). The Lagrange conditions M s + lambda a = b, a.s = G_B are solved in
/// their null-space form: s = s_p + t v with s_p = G_B a/|a|^2 on the constraint and v = (a2, -a1)
/// along it, t = v.(b - M s_p) / (v.M v). Exact in exact arithmetic; one pass over the data.
Solution solve_constrained(const std::vector<double>& delta, const std::vector<double>& sigma,
                           const Basis& B, double G_B) {
  double m11 = 0, m12 = 0, m22 = 0, b1 = 0, b2 = 0;
  Solution sol;
  for (std::size_t i = 0; i < delta.size(); ++i) {
    const double x = delta[i];
    if (x < 0 || x > B.dc)
      continue;
    const double p = B.phi1(x), q = B.phi2(x);
    m11 += p * p;
    m12 += p * q;
    m22 += q * q;
    b1 += p * sigma[i];
    b2 += q * sigma[i];
    ++sol.n_used;
  }
  const double a1 = 0.5 * B.d2, a2 = 0.5 * (B.dc - B.d1);
  const double aa = a1 * a1 + a2 * a2;
  const double sp1 = G_B * a1 / aa, sp2 = G_B * a2 / aa;
  const double v1 = a2, v2 = -a1;
  const double vMv = v1 * (m11 * v1 + m12 * v2) + v2 * (m12 * v1 + m22 * v2);
  const double r1 = b1 - (m11 * sp1 + m12 * sp2), r2 = b2 - (m12 * sp1 + m22 * sp2);
  const double scale = (m11 + m22) * (v1 * v1 + v2 * v2);
  sol.determined = vMv > 1e-12 * scale;
  const double t = sol.determined ? (v1 * r1 + v2 * r2) / vMv : 0.0;
  sol.s1 = sp1 + t * v1;
  sol.s2 = sp2 + t * v2;
  for (std::size_t i = 0; i < delta.size(); ++i) {
    const double x = delta[i];
    if (x < 0 || x > B.dc)
      continue;
    const double r = sigma[i] - (sol.s1 * B.phi1(x) + sol.s2 * B.phi2(x));
    sol.ssr += r * r;
    sol.max_abs = std::max(sol.max_abs, std::abs(r));
  }
  return sol;
}

void check_data(const std::vector<double>& delta, const std::vector<double>& sigma, double dc,
                double G_B, const std::string& what) {
  if (delta.size() != sigma.size())
    throw InputError(what + ": " + std::to_string(delta.size()) + " openings but " +
                     std::to_string(sigma.size()) + " tractions");
  for (std::size_t i = 0; i < delta.size(); ++i)
    if (!std::isfinite(delta[i]) || !std::isfinite(sigma[i]))
      throw InputError(what + ": point " + std::to_string(i) + " is not finite");
  if (!(dc > 0) || !(G_B > 0) || !std::isfinite(dc) || !std::isfinite(G_B))
    throw InputError(what + ": need delta_c > 0 and G_B > 0");
  std::size_t inside = 0;
  for (double x : delta)
    inside += (x > 0 && x < dc) ? 1 : 0;
  if (inside < 3)
    throw InputError(what + ": only " + std::to_string(inside) + " points lie in (0, " + mm(dc) +
                     "); at least 3 are needed");
}

TrilinearFit make_result(const Solution& sol, const Basis& B, double G_B, bool free) {
  TrilinearFit fit;
  fit.law = {B.d1, sol.s1, B.d2, sol.s2, B.dc};
  fit.rms_residual = std::sqrt(sol.ssr / static_cast<double>(sol.n_used));
  fit.max_residual = sol.max_abs;
  fit.area_constraint = G_B;
  fit.d1_d2_free = free;
  return fit;
}

void check_signs(const Solution& sol, const Basis& B, const std::string& what) {
  if (sol.s1 < 0 || sol.s2 < 0) {
    std::ostringstream s;
    s << what << ": the best trilinear law with d1 = " << mm(B.d1) << ", d2 = " << mm(B.d2)
      << ", dc = " << mm(B.dc) << " has sigma1 = " << sol.s1 / units::kPa
      << " kPa, sigma2 = " << sol.s2 / units::kPa
      << " kPa; a negative traction means the data are not bridging-shaped for these openings "
         "(or G_B does not match their area)";
    throw ComputationError(s.str());
  }
}

} // namespace

TrilinearFit fit_trilinear_fixed(const std::vector<double>& delta, const std::vector<double>& sigma,
                                 double d1, double d2, double dc, double G_B) {
  const std::string what = "trilinear fit";
  check_data(delta, sigma, dc, G_B, what);
  if (!(d1 > 0 && d1 < d2 && d2 < dc))
    throw InputError(what + ": need 0 < d1 < d2 < dc, got d1 = " + mm(d1) + ", d2 = " + mm(d2) +
                     ", dc = " + mm(dc));
  const Basis B{d1, d2, dc};
  const Solution sol = solve_constrained(delta, sigma, B, G_B);
  if (!sol.determined)
    throw InputError(what +
                     ": the data do not determine sigma1 and sigma2 separately (no "
                     "points where the two trilinear segments differ); add points in (0, " +
                     mm(dc) + ")");
  check_signs(sol, B, what);
  return make_result(sol, B, G_B, false);
}

TrilinearFit fit_trilinear_free(const std::vector<double>& delta, const std::vector<double>& sigma,
                                double dc, double G_B, double d1_min, double d1_max,
                                double d2_max) {
  const std::string what = "trilinear fit (d1, d2 free)";
  check_data(delta, sigma, dc, G_B, what);
  if (!(d1_min > 0 && d1_min < d1_max && d1_max < d2_max && d2_max < dc))
    throw InputError(what + ": need 0 < d1_min < d1_max < d2_max < dc, got " + mm(d1_min) + ", " +
                     mm(d1_max) + ", " + mm(d2_max) + ", " + mm(dc));

  // Variable projection: for given (d1, d2) the stresses follow in closed form, so only the two
  // openings are searched. Negative stresses are pushed out by an exterior penalty that keeps
  // the objective continuous (an infinite wall would stall Brent's parabolic steps).
  const double n_pts = static_cast<double>(delta.size());
  const auto objective = [&](double d1, double d2) {
    const Solution s = solve_constrained(delta, sigma, Basis{d1, d2, dc}, G_B);
    if (!s.determined)
      return std::numeric_limits<double>::max() / 4;
    const double neg1 = std::min(s.s1, 0.0), neg2 = std::min(s.s2, 0.0);
    return s.ssr + n_pts * (neg1 * neg1 + neg2 * neg2);
  };
  // d2 must stay strictly above d1 (the middle segment must exist).
  const double gap = 1e-3 * (d2_max - d1_min);

  // 1. Coarse grid over the admissible triangle, so that a local minimum of the non-convex
  //    objective is not mistaken for the global one.
  const int n_coarse = 40;
  const double h1 = (d1_max - d1_min) / (n_coarse - 1);
  double best = std::numeric_limits<double>::max(), best_d1 = d1_min, best_d2 = d2_max;
  for (int i = 0; i < n_coarse; ++i) {
    const double d1 = d1_min + h1 * i;
    for (int j = 0; j < n_coarse; ++j) {
      const double d2 = d1 + gap + (d2_max - d1 - gap) * j / (n_coarse - 1);
      const double f = objective(d1, d2);
      if (f < best) {
        best = f;
        best_d1 = d1;
        best_d2 = d2;
      }
    }
  }

  // 2. Nested Brent searches in the coarse cells around the best node: the inner one over d2
  //    gives the profile g(d1) = min_d2 f(d1, d2), the outer one minimizes g.
  const int bits = std::numeric_limits<double>::digits / 2; // Brent's sqrt(eps) limit
  const double h2 = (d2_max - best_d1) / (n_coarse - 1);
  const double d1_lo = std::max(d1_min, best_d1 - h1), d1_hi = std::min(d1_max, best_d1 + h1);
  const auto inner = [&](double d1) {
    const double lo = std::max(d1 + gap, best_d2 - 2 * h2);
    const double hi = std::min(d2_max, best_d2 + 2 * h2);
    if (!(hi > lo))
      return std::make_pair(lo, objective(d1, lo));
    return boost::math::tools::brent_find_minima([&](double d2) { return objective(d1, d2); }, lo,
                                                 hi, bits);
  };
  const auto outer = boost::math::tools::brent_find_minima(
      [&](double d1) { return inner(d1).second; }, d1_lo, d1_hi, bits);
  double d1 = outer.first, d2 = inner(d1).first;
  if (!(objective(d1, d2) <= best)) {
    d1 = best_d1;
    d2 = best_d2;
  }

  const Basis B{d1, d2, dc};
  const Solution sol = solve_constrained(delta, sigma, B, G_B);
  if (!sol.determined)
    throw InputError(what + ": the data do not determine sigma1 and sigma2 for any d1, d2");
  check_signs(sol, B, what);
  return make_result(sol, B, G_B, true);
}

} // namespace fiberbridge::analysis
