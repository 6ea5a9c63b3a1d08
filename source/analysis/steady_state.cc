// J_tip, G_ss and the steady-state onset delta_c of a measured R(delta) curve (seed section 2.3:
// "The first step is to locate the steady state regime, which then determines delta_c").
#include "fiberbridge/analysis/steady_state.h"

#include "fiberbridge/analysis/line_fit.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>

namespace fiberbridge::analysis {

namespace {

// Criterion constants (documented in steady_state.h).
/// J_tip: the hinge fit uses delta below this fraction of the range. Short enough to end before
/// the second kink of R for the seed's laws (d2 = 1 mm of a 6-8 mm range), long enough to hold the
/// flat part plus enough of the rise to fix its slope.
constexpr double initial_fraction = 0.05;
constexpr std::size_t min_points = 3;   ///< J_tip and tail averages, rising-branch fit
constexpr double reach_fraction = 0.05; ///< delta_c: R first reaches G_ss - 5 % G_B
/// The rising-branch line is fitted from where R first reaches G_ss - 20 % G_B up to the 5 %
/// point: close enough to delta_c that one segment of a trilinear law usually holds the whole
/// band (so the extension to G_ss is exact there), wide enough to average measurement noise.
constexpr double branch_fraction = 0.20;

double mean(const std::vector<double>& v, std::size_t begin, std::size_t end) {
  double s = 0;
  for (std::size_t i = begin; i < end; ++i)
    s += v[i];
  return s / static_cast<double>(end - begin);
}

std::string mm(double x) {
  std::ostringstream s;
  s.precision(5);
  s << x / units::mm << " mm";
  return s.str();
}

std::string jm2(double x) {
  std::ostringstream s;
  s.precision(5);
  s << x << " J/m^2";
  return s.str();
}

/// J_tip from the start of the curve. Seed Eq. 2 is exactly flat (R = J_tip) while delta stays
/// on a linear elastic rise (delta <= d1) and rises linearly just after it (R' = (sigma -
/// delta sigma')/2, constant on a linear softening segment). A plain mean over a fixed window
/// is biased high as soon as the window passes d1 (+2.7 J/m^2 on the clean PVA curve to 8 mm
/// with a 2 % window); the hinge model R = c + s max(0, delta - delta_h), fitted by least squares
/// for every data point as hinge, finds the flat level c without knowing d1. With no flat part
/// in the data (a rigid law, or d1 below the first point) the best hinge is the first point and
/// c is the rising line extrapolated to it.
struct InitialFlat {
  double level = 0, hinge = 0, window_end = 0;
  std::size_t n_window = 0;
};

InitialFlat fit_initial_flat(const std::vector<double>& d, const std::vector<double>& R) {
  const std::size_t N = d.size();
  const double range = d.back() - d.front();
  std::size_t n = 0;
  while (n < N && d[n] <= d.front() + initial_fraction * range)
    ++n;
  n = std::min(N, std::max(n, 2 * min_points));
  InitialFlat best;
  best.n_window = n;
  best.window_end = d[n - 1];
  double best_sse = std::numeric_limits<double>::infinity();
  // Hinge at point k: regressors 1 and z_i = max(0, d_i - d_k); the 2x2 normal equations.
  for (std::size_t k = 0; k + 2 < n; ++k) {
    double sz = 0, szz = 0, sy = 0, szy = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double z = std::max(0.0, d[i] - d[k]);
      sz += z;
      szz += z * z;
      sy += R[i];
      szy += z * R[i];
    }
    const double det = n * szz - sz * sz;
    if (!(det > 0))
      continue;
    const double c = (szz * sy - sz * szy) / det;
    const double slope = (n * szy - sz * sy) / det;
    if (slope < 0) // R never falls after the flat part (Eq. 2 with sigma >= 0)
      continue;
    double sse = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double e = R[i] - c - slope * std::max(0.0, d[i] - d[k]);
      sse += e * e;
    }
    if (sse < best_sse) {
      best_sse = sse;
      best.level = c;
      best.hinge = d[k];
    }
  }
  if (!std::isfinite(best_sse)) { // no rise in the window: R is flat there
    best.level = mean(R, 0, n);
    best.hinge = d[n - 1];
  }
  return best;
}

} // namespace

SteadyState find_steady_state(const RDeltaCurve& curve, const SteadyStateOptions& options,
                              const std::string& source) {
  const std::vector<double>& d = curve.delta;
  const std::vector<double>& R = curve.R;
  const std::size_t N = d.size();
  if (N < 2 * min_points + 2 || R.size() != N)
    throw InputError(source + ": the R(delta) curve needs at least " +
                     std::to_string(2 * min_points + 2) + " points to locate a steady state, got " +
                     std::to_string(N));
  for (std::size_t i = 1; i < N; ++i)
    if (!(d[i] > d[i - 1]))
      throw InputError(source + ": the R(delta) curve must have strictly increasing delta");
  if (!(options.tail_fraction > 0 && options.tail_fraction < 1) || !(options.plateau_band > 0))
    throw InputError(source + ": steady-state options need 0 < tail_fraction < 1 and "
                              "plateau_band > 0");
  const double range = d.back() - d.front();
  SteadyState ss;
  std::ostringstream why;

  // J_tip: R is exactly flat below d1 for laws with an elastic rise (seed Eq. 2: all zone work
  // is recoverable there), so the mean of the first points estimates it.
  if (options.j_tip > 0) {
    ss.j_tip = options.j_tip;
    ss.j_tip_automatic = false;
    why << "J_tip = " << jm2(ss.j_tip) << " (given). ";
  } else {
    const InitialFlat flat = fit_initial_flat(d, R);
    ss.j_tip = flat.level;
    why << "J_tip = " << jm2(ss.j_tip) << ": flat level of a hinge fit (R constant, then rising "
        << "linearly) to the " << flat.n_window << " points with delta <= " << mm(flat.window_end)
        << " (" << initial_fraction * 100 << " % of the delta range, at least " << 2 * min_points
        << " points), hinge at delta = " << mm(flat.hinge) << ". ";
  }

  // G_ss: the mean of the last stretch of R that is flat. The tail (the last tail_fraction of
  // the range) must not rise; when it falls (the zone meeting the specimen's far end lengthens,
  // so the tip reading runs ahead of the work done: a measurement's end effect, R(delta) of
  // Eq. 2 never falls) the stretch of the same width is moved back until it is flat, and G_ss
  // is its mean.
  std::size_t t0 = N;
  while (t0 > 0 && d[t0 - 1] >= d.back() - options.tail_fraction * range)
    --t0;
  t0 = std::min(t0, N - min_points);
  std::size_t t1 = N; // the stretch is [t0, t1)
  const double width = options.tail_fraction * range;
  /// Change of the fitted line over the stretch and twice its standard error (noise of R).
  auto stretch_rise = [&](std::size_t b, std::size_t e) {
    const LineFit f = fit_line(d, R, b, e);
    double ss = 0, sxx = 0;
    for (std::size_t i = b; i < e; ++i) {
      ss += std::pow(R[i] - f.at(d[i]), 2);
      sxx += std::pow(d[i] - f.x_mean, 2);
    }
    const double w = d[e - 1] - d[b];
    const double se = e - b > 2 && sxx > 0 ? std::sqrt(ss / double(e - b - 2) / sxx) : 0.0;
    return std::pair<double, double>(f.slope * w, 2 * se * w);
  };
  auto [rise, rise_noise] = stretch_rise(t0, t1);
  const double G_last = mean(R, t0, t1);
  const double G_top = std::max(G_last, ss.j_tip);
  // The band: plateau_band of G_B, or the noise of the fitted change if larger (a noisy record
  // that is flat must not be refused for its scatter).
  auto band_of = [&](double G, double noise) {
    return std::max(options.plateau_band * (G - ss.j_tip), noise);
  };
  double band = band_of(G_top, rise_noise);
  const double last_rise = rise, last_band = band;
  bool falling = false;
  if (rise < -band) {
    // Move the stretch back one point at a time while it falls; stop at the first flat one.
    // It must not reach into the first half of the range (that is no steady state any more).
    falling = true;
    while (t0 > 0 && d[t0 - 1] >= d.front() + 0.5 * range) {
      --t0;
      while (t1 - 1 > t0 && d[t1 - 1] > d[t0] + width)
        --t1;
      if (t1 - t0 < min_points)
        break;
      std::tie(rise, rise_noise) = stretch_rise(t0, t1);
      band = band_of(std::max(mean(R, t0, t1), ss.j_tip), rise_noise);
      if (rise >= -band)
        break;
    }
  }
  const double G_tail = mean(R, t0, t1);
  if (!(ss.j_tip < G_tail))
    throw InputError(
        source + ": J_tip = " + jm2(ss.j_tip) + (ss.j_tip_automatic ? "" : " (given)") +
        " is not below the plateau R = " + jm2(G_tail) + " over delta >= " + mm(d[t0]) +
        "; there is no bridging toughness G_B = G_ss - J_tip > 0");
  const bool flat = std::abs(rise) <= band;
  ss.end_effect = falling;
  std::ostringstream tail_text;
  if (falling)
    tail_text << "R falls over the last " << options.tail_fraction * 100
              << " % of the range (fitted change " << jm2(last_rise) << " beyond the band "
              << jm2(last_band) << "), taken as the specimen's end effect; ";
  tail_text << (falling ? "the last flat stretch" : "tail") << " delta in [" << mm(d[t0]) << ", "
            << mm(d[t1 - 1]) << "] (" << t1 - t0 << " points, " << options.tail_fraction * 100
            << " % of the range): mean R = " << jm2(G_tail)
            << ", fitted slope x width = " << jm2(rise) << " against the plateau band " << jm2(band)
            << " (the larger of " << options.plateau_band * 100
            << " % of G_B and twice the fitted change's standard error)";

  if (options.delta_c > 0) {
    if (!(options.delta_c >= d.front() && options.delta_c <= d.back()))
      throw InputError(source + ": the given delta_c = " + mm(options.delta_c) +
                       " lies outside the data, delta in [" + mm(d.front()) + ", " + mm(d.back()) +
                       "]");
    ss.delta_c = options.delta_c;
    ss.delta_c_automatic = false;
    if (flat) {
      ss.G_ss = G_tail;
      why << "G_ss = " << jm2(ss.G_ss) << ": " << tail_text.str() << ", flat. ";
    } else {
      // Without a plateau (seed: solid wood "does not actually reach G_ss") the user's delta_c
      // closes Eq. 5, whose law then has area R(delta_c) - J_tip: that R is the G_ss used.
      ss.G_ss = interpolate_linear(d, R, ss.delta_c);
      // Relative round-off margin: a J_tip fitted on a flat start equal to R(delta_c) is no
      // bridging toughness, whatever its last digit says.
      if (!(ss.G_ss - ss.j_tip > 1e-9 * std::abs(ss.G_ss)))
        throw InputError(source + ": J_tip = " + jm2(ss.j_tip) + " is not below R(delta_c) = " +
                         jm2(ss.G_ss) + " at the given delta_c = " + mm(ss.delta_c) +
                         "; there is no bridging toughness up to delta_c");
      why << "G_ss = R(delta_c) = " << jm2(ss.G_ss) << " because the tail is not flat ("
          << tail_text.str() << "). ";
    }
    why << "delta_c = " << mm(ss.delta_c) << " (given).";
    ss.criterion = why.str();
    return ss;
  }

  if (!flat)
    throw ComputationError("no steady state in " + source + ": " +
                           (rise > 0
                                ? std::string("R is still rising at the end of the data (")
                                : std::string("R falls over the whole second half of the data (")) +
                           tail_text.str() + "); give delta_c explicitly or measure further");
  ss.G_ss = G_tail;
  why << "G_ss = " << jm2(ss.G_ss) << ": " << tail_text.str() << ", flat. ";

  // delta_c: where the rising branch meets the plateau. The first point reaching
  // G_ss - 5 % G_B is left of the kink of R at delta_c (R' jumps to 0 there for a trilinear law);
  // the line through the branch just before it, extended to G_ss, lands on the kink.
  const double G_B = ss.G_ss - ss.j_tip;
  std::size_t i_reach = 0;
  while (i_reach < N && R[i_reach] < ss.G_ss - reach_fraction * G_B)
    ++i_reach;
  std::size_t i_lo = 0;
  while (i_lo < i_reach && R[i_lo] < ss.G_ss - branch_fraction * G_B)
    ++i_lo;
  if (i_reach + 1 < min_points)
    throw ComputationError("no steady state in " + source + ": R reaches G_ss - 5 % G_B = " +
                           jm2(ss.G_ss - reach_fraction * G_B) + " at the start of the data (" +
                           mm(d[i_reach]) + "), there is no rising branch");
  i_lo = std::min(i_lo, i_reach + 1 - min_points);
  const LineFit branch = fit_line(d, R, i_lo, i_reach + 1);
  if (!branch.valid || !(branch.slope > 0))
    throw ComputationError("no steady state in " + source +
                           ": the rising branch before R reaches G_ss - 5 % G_B (delta in [" +
                           mm(d[i_lo]) + ", " + mm(d[i_reach]) + "]) does not rise");
  ss.delta_c = branch.x_mean + (ss.G_ss - branch.y_mean) / branch.slope;
  if (!(ss.delta_c >= d.front() && ss.delta_c <= d.back()))
    throw ComputationError("no steady state in " + source + ": the rising branch extended to " +
                           "G_ss gives delta_c = " + mm(ss.delta_c) + ", outside the data");
  why << "delta_c = " << mm(ss.delta_c)
      << ": R first reaches G_ss - 5 % G_B = " << jm2(ss.G_ss - reach_fraction * G_B)
      << " at delta = " << mm(d[i_reach]) << "; the least-squares line through the " << branch.n
      << " points with delta in [" << mm(d[i_lo]) << ", " << mm(d[i_reach])
      << "] (R from G_ss - 20 % G_B on), slope " << branch.slope * units::mm
      << " J/m^2 per mm, reaches G_ss there.";
  ss.criterion = why.str();
  return ss;
}

} // namespace fiberbridge::analysis
