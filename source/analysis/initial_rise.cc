// R at initiation fitted to the dissipated energy (initial_rise.h).
#include "fiberbridge/analysis/initial_rise.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace fiberbridge::analysis {

namespace {

/// The fit's readings span delta_root from the onset's to a fraction of its range past it, at
/// least 6 readings. The fraction is chosen from the data (below): from 5 % (steady_state.cc's
/// J_tip window, short of the second kink of the seed's laws) up to 20 % by factors sqrt(2).
constexpr double first_fraction = 0.05, last_fraction = 0.2;
constexpr std::size_t min_points = 6;
/// Readings after the hinge's at least: two readings fit any rise to noise.
constexpr std::size_t min_after_hinge = 3;
/// Hinge positions tried per reading step.
constexpr std::size_t hinge_steps = 4;
/// Half-width of the intervals the windows intersect, in standard errors (as energy_rate.cc).
constexpr double ici_width = 2;

double dot(const std::vector<double>& u, const std::vector<double>& v) {
  return std::inner_product(u.begin(), u.end(), v.begin(), 0.0);
}

/// The hinge model fitted to readings [s, e): J, s, delta_h and the standard errors of J and s
/// (from the residuals, for the chosen hinge).
struct RangeFit {
  double j = NAN, slope = 0, hinge = 0, se_j = NAN, se_slope = NAN;
};

RangeFit fit_range(const std::vector<double>& x, const std::vector<double>& d,
                   const std::vector<double>& y, std::size_t s, std::size_t e, double width) {
  const std::size_t n = e - s;
  // Centred least squares for (J, s) with the intercept c eliminated: x1 = B (a - a_s),
  // x2 = B int max(0, delta - delta_h) da (trapezoid along the readings).
  auto centred = [n](std::vector<double> v) {
    double m = 0;
    for (double t : v)
      m += t / static_cast<double>(n);
    for (double& t : v)
      t -= m;
    return v;
  };
  std::vector<double> x1(n), yy(n);
  for (std::size_t i = 0; i < n; ++i) {
    x1[i] = width * (x[s + i] - x[s]);
    yy[i] = y[s + i];
  }
  x1 = centred(x1);
  yy = centred(yy);
  const double S11 = dot(x1, x1), S1y = dot(x1, yy), Syy = dot(yy, yy);
  RangeFit fit;
  if (!(S11 > 0))
    return fit;
  // No rise in the window: R flat at J.
  fit.j = S1y / S11;
  fit.hinge = d[e - 1];
  fit.se_j = std::sqrt(std::max(0.0, Syy - fit.j * S1y) / double(n - 2) / S11);
  fit.se_slope = 0;
  double best_sse = std::numeric_limits<double>::infinity();
  // Hinges on the readings and at quarter steps between them: the law's first kink lies between
  // two readings, and a hinge held on the nearer one moves J by up to half a step's rise.
  for (std::size_t m = 0; s + m / hinge_steps + min_after_hinge < e; ++m) {
    const std::size_t k = s + m / hinge_steps;
    const double h = d[k] + double(m % hinge_steps) / hinge_steps * (d[k + 1] - d[k]);
    std::vector<double> x2(n, 0.0);
    for (std::size_t i = 1; i < n; ++i) {
      const double z0 = std::max(0.0, d[s + i - 1] - h), z1 = std::max(0.0, d[s + i] - h);
      x2[i] = x2[i - 1] + width * 0.5 * (z0 + z1) * (x[s + i] - x[s + i - 1]);
    }
    x2 = centred(x2);
    const double S12 = dot(x1, x2), S22 = dot(x2, x2), S2y = dot(x2, yy);
    const double det = S11 * S22 - S12 * S12;
    if (!(det > 0))
      continue;
    const double p1 = (S22 * S1y - S12 * S2y) / det, p2 = (S11 * S2y - S12 * S1y) / det;
    if (p2 < 0) // R does not fall after initiation (Eq. 2 with sigma >= 0)
      continue;
    const double sse = std::max(0.0, Syy - p1 * S1y - p2 * S2y);
    if (sse < best_sse) {
      best_sse = sse;
      const double var = sse / double(n - 3);
      fit.j = p1;
      fit.slope = p2;
      fit.hinge = h;
      fit.se_j = std::sqrt(var * S22 / det);
      fit.se_slope = std::sqrt(var * S11 / det);
    }
  }
  return fit;
}

} // namespace

InitialRise fit_initial_rise(const std::vector<double>& a, const std::vector<double>& delta_root,
                             const std::vector<double>& D, double D_before, double D_noise,
                             double width) {
  InitialRise fit;
  // Readings with a finite opening and D; delta held at its running maximum, as the R(delta)
  // table holds it (record_reduction.cc, to_rdelta).
  std::vector<double> x, d, y;
  std::vector<std::size_t> index;
  double running = 0, D_max = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!std::isfinite(a[i]) || !std::isfinite(delta_root[i]) || !std::isfinite(D[i]))
      continue;
    running = std::max(running, delta_root[i]);
    x.push_back(a[i]);
    d.push_back(running);
    y.push_back(D[i]);
    index.push_back(i);
    D_max = std::max(D_max, std::abs(D[i]));
  }
  const double threshold = std::max(3 * D_noise, 1e-4 * D_max);
  std::size_t s = 0;
  while (s < y.size() && !(y[s] - D_before > threshold))
    ++s;
  if (s == y.size() || d.empty()) {
    fit.why = "no growth reading with dissipation beyond the noise of D";
    return fit;
  }
  auto end_at = [&](double fraction) {
    std::size_t e = s;
    while (e < y.size() && d[e] <= d[s] + fraction * d.back())
      ++e;
    return std::max(e, std::min(y.size(), s + min_points));
  };
  if (end_at(first_fraction) - s < min_points) {
    fit.why = "only " + std::to_string(y.size() - s) + " growth readings with dissipation, " +
              std::to_string(min_points) + " needed";
    return fit;
  }
  // The window: intersection of confidence intervals (as the energy slopes' windows,
  // energy_rate.h). Wider windows average the noise of D out of J and s while one hinge still
  // describes R; past a second kink of the law (or the zone's end) J and s leave the narrower
  // windows' intervals, and the last window that agreed is kept.
  double lo_j = -INFINITY, hi_j = INFINITY, lo_s = -INFINITY, hi_s = INFINITY;
  std::size_t e_chosen = 0, e_last = 0;
  RangeFit chosen;
  for (double f = first_fraction; f <= last_fraction * (1 + 1e-9); f *= std::sqrt(2.0)) {
    const std::size_t e = end_at(f);
    if (e == e_last)
      continue;
    e_last = e;
    const RangeFit r = fit_range(x, d, y, s, e, width);
    if (!std::isfinite(r.j) || !std::isfinite(r.se_j))
      break;
    lo_j = std::max(lo_j, r.j - ici_width * r.se_j);
    hi_j = std::min(hi_j, r.j + ici_width * r.se_j);
    lo_s = std::max(lo_s, r.slope - ici_width * r.se_slope);
    hi_s = std::min(hi_s, r.slope + ici_width * r.se_slope);
    if (e_chosen && (lo_j > hi_j || lo_s > hi_s))
      break;
    chosen = r;
    e_chosen = e;
  }
  if (!e_chosen) {
    fit.why = "the fitted readings do not advance the crack";
    return fit;
  }
  fit.fitted = true;
  fit.j_tip = chosen.j;
  fit.slope = chosen.slope;
  fit.hinge = chosen.hinge;
  fit.onset = index[s];
  fit.end = index[e_chosen - 1] + 1;
  fit.delta_end = d[e_chosen - 1];
  return fit;
}

} // namespace fiberbridge::analysis
