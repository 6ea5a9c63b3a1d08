// J_tip, G_ss and the steady-state onset delta_c of a measured R(delta) curve (seed section 2.3:
// "The first step is to locate the steady state regime, which then determines delta_c").
#include "fiberbridge/analysis/steady_state.h"

#include "fiberbridge/analysis/line_fit.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fiberbridge::analysis {

namespace {

// Criterion constants (documented in steady_state.h).
constexpr double initial_fraction = 0.02; ///< J_tip: delta below this fraction of the range
constexpr std::size_t min_points = 3;     ///< J_tip and tail averages, rising-branch fit
constexpr double reach_fraction = 0.05;   ///< delta_c: R first reaches G_ss - 5 % G_B
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
    std::size_t n0 = 0;
    while (n0 < N && d[n0] < d.front() + initial_fraction * range)
      ++n0;
    n0 = std::max(n0, min_points);
    ss.j_tip = mean(R, 0, n0);
    why << "J_tip = " << jm2(ss.j_tip) << ": mean R of the " << n0
        << " points with delta <= " << mm(d[n0 - 1])
        << " (2 % of the delta range, at least 3 points). ";
  }

  // G_ss: the mean of the tail, which must be flat.
  std::size_t t0 = N;
  while (t0 > 0 && d[t0 - 1] >= d.back() - options.tail_fraction * range)
    --t0;
  t0 = std::min(t0, N - min_points);
  const double G_tail = mean(R, t0, N);
  const LineFit tail = fit_line(d, R, t0, N);
  const double rise = tail.slope * (d.back() - d[t0]);
  if (!(ss.j_tip < G_tail))
    throw InputError(
        source + ": J_tip = " + jm2(ss.j_tip) + (ss.j_tip_automatic ? "" : " (given)") +
        " is not below the plateau R = " + jm2(G_tail) + " over delta >= " + mm(d[t0]) +
        "; there is no bridging toughness G_B = G_ss - J_tip > 0");
  const double band = options.plateau_band * (G_tail - ss.j_tip);
  const bool flat = std::abs(rise) < band;
  std::ostringstream tail_text;
  tail_text << "tail delta in [" << mm(d[t0]) << ", " << mm(d.back()) << "] (" << N - t0
            << " points, last " << options.tail_fraction * 100
            << " % of the range): mean R = " << jm2(G_tail)
            << ", fitted slope x width = " << jm2(rise) << " against the plateau band "
            << options.plateau_band * 100 << " % of G_B = " << jm2(band);

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
      if (!(ss.j_tip < ss.G_ss))
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
    throw ComputationError("no steady state in " + source + ": R is still changing at the end " +
                           "of the data (" + tail_text.str() +
                           "); give delta_c explicitly or measure further");
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
