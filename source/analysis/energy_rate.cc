// Direct-energy rate and its band; monotone smooth crack lengths (energy_rate.h).
#include "fiberbridge/analysis/energy_rate.h"

#include "fiberbridge/analysis/line_fit.h"
#include "fiberbridge/core/median.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace fiberbridge::analysis {

namespace {

/// The band's scatter of neighbouring estimates is taken over this many windows (centred).
constexpr double scatter_windows = 4;
/// Half-width of the intervals the adaptive windows intersect, in standard errors: 2 keeps a
/// window only while the wider slope agrees with every narrower one at about 95 %.
constexpr double ici_width = 2;

/// The readings [begin, end) within w/2 of x. The half-width is widened by 1e-6 of itself (a
/// nanometre on millimetre windows): readings on a regular grid fall exactly on the edges of
/// windows that are whole multiples of their spacing, and an edge reading must stay in whatever
/// the last written digit of the file (9 significant digits of a crack length in metres move it
/// by ~1e-10 m; the same record through another export must give the same R).
std::pair<std::size_t, std::size_t> window_bounds(const std::vector<double>& a, double x,
                                                  double w) {
  const double half = 0.5 * w * (1 + 1e-6);
  return {static_cast<std::size_t>(std::lower_bound(a.begin(), a.end(), x - half) - a.begin()),
          static_cast<std::size_t>(std::upper_bound(a.begin(), a.end(), x + half) - a.begin())};
}

/// Local straight lines of y against x over windows [begin, end) in O(1) each: prefix sums of
/// the samples taken about their overall means, so that window sums far from the origin keep
/// their digits (the dissipated energy grows to a few joules while its noise is ~1e-4 J).
class WindowLines {
public:
  WindowLines(const std::vector<double>& x, const std::vector<double>& y) {
    for (std::size_t i = 0; i < x.size(); ++i) {
      x0_ += x[i] / static_cast<double>(x.size());
      y0_ += y[i] / static_cast<double>(y.size());
    }
    sx_.assign(x.size() + 1, 0.0);
    sy_ = sxx_ = sxy_ = syy_ = sx_;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double u = x[i] - x0_, v = y[i] - y0_;
      sx_[i + 1] = sx_[i] + u;
      sy_[i + 1] = sy_[i] + v;
      sxx_[i + 1] = sxx_[i] + u * u;
      sxy_[i + 1] = sxy_[i] + u * v;
      syy_[i + 1] = syy_[i] + v * v;
    }
  }
  /// Slope over [b, e) and its standard error from the residuals; NaN below 3 points or with
  /// no spread in x.
  std::pair<double, double> slope(std::size_t b, std::size_t e) const {
    const double n = static_cast<double>(e - b);
    if (e - b < 3)
      return {NAN, NAN};
    const double mx = (sx_[e] - sx_[b]) / n, my = (sy_[e] - sy_[b]) / n;
    const double Sxx = sxx_[e] - sxx_[b] - n * mx * mx;
    const double Sxy = sxy_[e] - sxy_[b] - n * mx * my;
    const double Syy = syy_[e] - syy_[b] - n * my * my;
    if (!(Sxx > 0))
      return {NAN, NAN};
    const double k = Sxy / Sxx;
    const double ss = std::max(0.0, Syy - k * Sxy);
    return {k, std::sqrt(ss / (n - 2) / Sxx)};
  }

  /// Sum of squares of x about its mean over [b, e) (0 below 3 points).
  double spread(std::size_t b, std::size_t e) const {
    if (e - b < 3)
      return 0;
    const double n = static_cast<double>(e - b), mx = (sx_[e] - sx_[b]) / n;
    return sxx_[e] - sxx_[b] - n * mx * mx;
  }
  /// Residual standard deviation of the line over [b, e); NaN below 3 points.
  double residual_sd(std::size_t b, std::size_t e) const {
    const auto [k, se] = slope(b, e);
    return std::isfinite(se) ? se * std::sqrt(spread(b, e)) : NAN;
  }

private:
  double x0_ = 0, y0_ = 0;
  std::vector<double> sx_, sy_, sxx_, sxy_, syy_;
};

} // namespace

std::vector<double> dissipated_energy(const TestRecord& rec) {
  const std::size_t n = rec.opening.size();
  std::vector<double> D(n, 0.0);
  double W = 0;
  for (std::size_t i = 1; i < n; ++i) {
    W += 0.5 * (rec.load[i] + rec.load[i - 1]) * (rec.opening[i] - rec.opening[i - 1]);
    D[i] = W - 0.5 * rec.load[i] * rec.opening[i];
  }
  return D;
}

namespace {

/// The band and slopes for a window per point (energy_slopes and energy_slopes_adaptive).
EnergySlopes slopes_with_windows(const WindowLines& lines, const std::vector<double>& a,
                                 const std::vector<double>& window, double se_factor = 1) {
  // Two estimates at every point: the slope over the window w and over 2 w. Where R is locally
  // linear over 2 w both are unbiased, and their difference measures the scatter of the w
  // estimate that the 2 w one averages out: reading noise (then close to the standard error) and
  // tracking errors correlated over a few mm, which the residual-based standard error of one
  // window cannot see because they bend D(a) smoothly inside it.
  auto window_of = [&](double x, double w) { return window_bounds(a, x, w); };
  const std::size_t n = a.size();
  std::vector<double> slope(n, NAN), slope_se(n, NAN);
  std::vector<double> diff2_sum(n + 1, 0.0), diff_count(n + 1, 0.0);
  for (std::size_t j = 0; j < n; ++j) {
    const auto [b, e] = window_of(a[j], window[j]);
    std::tie(slope[j], slope_se[j]) = lines.slope(b, e);
    const auto [b2, e2] = window_of(a[j], 2 * window[j]);
    const double wide = lines.slope(b2, e2).first;
    const bool ok = std::isfinite(slope[j]) && std::isfinite(wide);
    diff2_sum[j + 1] = diff2_sum[j] + (ok ? std::pow(slope[j] - wide, 2) : 0.0);
    diff_count[j + 1] = diff_count[j] + (ok ? 1.0 : 0.0);
  }
  EnergySlopes out;
  out.slope = slope;
  out.window = window;
  out.lo.resize(n);
  out.hi.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    // s: the larger of the slope's standard error (times se_factor, the correlated-noise factor of
    // the data-chosen windows; 1 for a fixed window) and the RMS difference between the w and 2 w
    // estimates within two windows either side, x sqrt(4/3). Why that factor: for reading errors
    // correlated over less than a window the 2 w slope carries a quarter of the w slope's error
    // variance (an end-to-end difference over twice the length), so the difference of the two
    // holds 3/4 of it; for independent reading noise (1/8 of it) the factor overstates s by 7 %.
    // Why two windows: the RMS over one window either side rests on few independent differences
    // when the errors are correlated and scatters with them (docs/verification.md, "Test
    // records": coverage measured both ways).
    const auto [nb, ne] = window_of(a[j], scatter_windows * window[j]);
    const double n_diff = diff_count[ne] - diff_count[nb];
    const double scatter =
        n_diff > 0 ? std::sqrt((diff2_sum[ne] - diff2_sum[nb]) / n_diff * 4.0 / 3.0) : slope_se[j];
    const double half = 2 * std::max(se_factor * slope_se[j], scatter);
    out.lo[j] = slope[j] - half;
    out.hi[j] = slope[j] + half;
  }
  return out;
}

/// How much larger the slopes' scatter over w_min is than the residuals of the w_min lines say
/// (1 at least). Reading errors correlated over more than w_min (a crack read in steps that
/// lags and catches up, a tip tracked in jumps of the point spacing) bend D(a) smoothly inside
/// the narrow windows: their residuals stay small while their slopes wander, and only the
/// scatter of the slopes themselves shows it. Measured as the difference d of the slopes over
/// w_min and over 2 w_min, which for independent noise holds 7/8 of the w_min slope's variance
/// (nested least squares: the wider slope's variance, 1/8 of it, is also their covariance).
/// Bias is taken out by differencing d at points 2 w_min apart, where the noise of the two is
/// independent and a smooth bias (R curving) nearly cancels; medians (/0.455, the median of
/// chi^2 with one degree of freedom) keep a few wild stretches from setting the record's noise.
/// `nominal_se`: the median standard error of the w_min slopes from the residuals.
double correlated_noise_factor(const WindowLines& lines, const std::vector<double>& a, double w_min,
                               double nominal_se) {
  const std::size_t n = a.size();
  auto slope_over = [&](std::size_t j, double w) {
    const auto [b, e] = window_bounds(a, a[j], w);
    return lines.slope(b, e).first;
  };
  std::vector<double> d(n);
  for (std::size_t j = 0; j < n; ++j)
    d[j] = slope_over(j, w_min) - slope_over(j, 2 * w_min);
  std::vector<double> half_d2;
  for (std::size_t j = 0; j < n; ++j) {
    const auto jj = static_cast<std::size_t>(
        std::lower_bound(a.begin(), a.end(), a[j] + 2 * w_min * (1 - 1e-6)) - a.begin());
    if (jj < n && std::isfinite(d[j]) && std::isfinite(d[jj]))
      half_d2.push_back(std::pow(d[j] - d[jj], 2) / 2);
  }
  if (half_d2.empty() || !(nominal_se > 0))
    return 1;
  const double scatter = std::sqrt(median_upper(half_d2) / 0.455 * 8.0 / 7.0);
  return std::max(1.0, scatter / nominal_se);
}

} // namespace

EnergySlopes energy_slopes(const std::vector<double>& a, const std::vector<double>& D,
                           double window) {
  return slopes_with_windows(WindowLines(a, D), a, std::vector<double>(a.size(), window));
}

EnergySlopes energy_slopes_per_point(const std::vector<double>& a, const std::vector<double>& D,
                                     const std::vector<double>& window) {
  return slopes_with_windows(WindowLines(a, D), a, window);
}

EnergySlopes energy_slopes_adaptive(const std::vector<double>& a, const std::vector<double>& D,
                                    double w_min, double w_max) {
  const WindowLines lines(a, D);
  const std::size_t n = a.size();
  auto bounds = [&](double x, double w) { return window_bounds(a, x, w); };
  // The noise of D about a smooth curve: the median over the points of the residual standard
  // deviation of the narrowest lines. On a clean record it is the curvature left in w_min (and
  // the windows stay narrow); on a noisy one it is the noise, and the windows grow where R is
  // straight enough for the wider slope to agree with the narrower ones.
  std::vector<double> sd, nominal_se;
  for (std::size_t j = 0; j < n; ++j) {
    const auto [b, e] = bounds(a[j], w_min);
    const double s = lines.residual_sd(b, e);
    if (std::isfinite(s)) {
      sd.push_back(s);
      nominal_se.push_back(s / std::sqrt(lines.spread(b, e)));
    }
  }
  std::vector<double> window(n, w_max);
  if (sd.empty())
    return slopes_with_windows(lines, a, window);
  // The same factor widens the band's standard-error term (slopes_with_windows): the windows
  // are now of the order of the errors' correlation length, where the w against 2 w scatter
  // sees only part of them.
  const double noise_factor = correlated_noise_factor(lines, a, w_min, median_upper(nominal_se));
  const double sigma = median_upper(sd) * noise_factor;
  for (std::size_t j = 0; j < n; ++j) {
    // Intersection of confidence intervals over windows growing by sqrt(2): the widest window
    // whose slope +- ici_width standard errors (from sigma) still overlaps every narrower one.
    double lo = -INFINITY, hi = INFINITY;
    double chosen = NAN;
    for (double w = w_min; w <= w_max * (1 + 1e-9); w *= std::sqrt(2.0)) {
      const auto [b, e] = bounds(a[j], w);
      const double k = lines.slope(b, e).first, Sxx = lines.spread(b, e);
      if (!std::isfinite(k) || !(Sxx > 0))
        continue;
      const double se = sigma / std::sqrt(Sxx);
      lo = std::max(lo, k - ici_width * se);
      hi = std::min(hi, k + ici_width * se);
      if (lo > hi)
        break;
      chosen = w;
    }
    window[j] = std::isfinite(chosen) ? chosen : w_max;
  }
  // The chosen window, smoothed: the median of the choices within w_max / 2 either side. The
  // intersection stops at the first narrow slope that a reading error throws out of the
  // intervals, so a lone choice is noisy exactly where the errors are heavy-tailed (a reading
  // that catches up after a stall); where the record needs narrow windows (a knee of R) its
  // neighbours choose them too.
  std::vector<double> smoothed(n);
  for (std::size_t j = 0; j < n; ++j) {
    const auto [b, e] = bounds(a[j], w_max);
    smoothed[j] =
        median_upper(std::vector<double>(window.begin() + static_cast<std::ptrdiff_t>(b),
                                         window.begin() + static_cast<std::ptrdiff_t>(e)));
  }
  return slopes_with_windows(lines, a, smoothed, noise_factor);
}

std::vector<double> isotonic(const std::vector<double>& y) {
  // Blocks of pooled values (mean, weight); a new value that falls below the last block's mean
  // is merged with it, and merging repeats backwards while the order is violated.
  std::vector<double> mean, weight;
  std::vector<std::size_t> count;
  for (double v : y) {
    mean.push_back(v);
    weight.push_back(1);
    count.push_back(1);
    while (mean.size() > 1 && mean[mean.size() - 2] > mean.back()) {
      const std::size_t k = mean.size() - 1;
      const double w = weight[k - 1] + weight[k];
      mean[k - 1] = (mean[k - 1] * weight[k - 1] + mean[k] * weight[k]) / w;
      weight[k - 1] = w;
      count[k - 1] += count[k];
      mean.pop_back();
      weight.pop_back();
      count.pop_back();
    }
  }
  std::vector<double> out;
  out.reserve(y.size());
  for (std::size_t k = 0; k < mean.size(); ++k)
    out.insert(out.end(), count[k], mean[k]);
  return out;
}

std::vector<double> monotone_crack(const TestRecord& rec, const std::vector<std::size_t>& readings,
                                   double time_window) {
  auto time_of = [&](std::size_t i) {
    return rec.time.empty() ? static_cast<double>(i) : rec.time[i];
  };
  std::vector<double> t, a;
  for (std::size_t k : readings) {
    t.push_back(time_of(k));
    a.push_back(rec.crack_length[k]);
  }
  const std::vector<double> iso = isotonic(a);
  // Half the window, widened by 1e-4 of itself: on a regular clock the window's edges fall on
  // readings, and a reading on the edge must stay inside whatever the last written digit of its
  // time (a record exported in minutes or ms reads back with round-off of ~1e-9 of the time).
  const double half = 0.5 * time_window * (1 + 1e-4);
  const std::size_t n = rec.opening.size();
  std::vector<double> out(n);
  double running = iso.front();
  for (std::size_t i = 0; i < n; ++i) {
    const double ti = time_of(i);
    double v;
    if (ti <= t.front())
      v = iso.front();
    else if (ti >= t.back())
      v = iso.back();
    else {
      auto b =
          static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), ti - half) - t.begin());
      auto e =
          static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), ti + half) - t.begin());
      // At least the readings either side (and 3 in all): the line then interpolates where the
      // readings are sparse.
      const auto at =
          static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), ti) - t.begin());
      b = std::min(b, at - 1);
      e = std::max(e, std::min(at + 1, t.size()));
      if (e - b < 3) {
        if (b > 0)
          --b;
        else if (e < t.size())
          ++e;
      }
      const LineFit f = fit_line(t, iso, b, e);
      v = f.valid ? f.at(ti) : iso[at - 1];
      v = std::clamp(v, iso.front(), iso.back());
    }
    running = std::max(running, v);
    out[i] = running;
  }
  return out;
}

} // namespace fiberbridge::analysis
