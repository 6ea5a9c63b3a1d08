// The crack-plane strain profile and the paper's threshold rule (crack_tip.h).
#include "fiberbridge/dic/crack_tip.h"

#include "fiberbridge/core/format.h"
#include "fiberbridge/core/median.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace fiberbridge::dic {

PlaneProfile crack_plane_profile(const PlaneFrame& f, double h) {
  // Rows of a grid sit at whole and half spacings from the plane; the estimated spacing and the
  // coordinates carry rounding, so the limits get a thousandth of a spacing of slack.
  const double slack = 1e-3 * h;
  std::vector<std::size_t> near;
  for (std::size_t i = 0; i < f.s.size(); ++i)
    if (std::isfinite(f.s[i]) && std::isfinite(f.n[i]) && std::abs(f.n[i]) <= 1.5 * h + slack)
      near.push_back(i);
  std::sort(near.begin(), near.end(),
            [&](std::size_t a, std::size_t b) { return f.s[a] < f.s[b]; });
  PlaneProfile p;
  std::size_t b = 0;
  while (b < near.size()) {
    std::size_t e = b + 1;
    while (e < near.size() && f.s[near[e]] - f.s[near[e - 1]] <= 0.5 * h)
      ++e;
    // One column: the nearest valid point on each side of the plane.
    int above = -1, below = -1;
    double s_sum = 0;
    for (std::size_t k = b; k < e; ++k) {
      const std::size_t i = near[k];
      s_sum += f.s[i];
      if (!f.valid[i] || !std::isfinite(f.eyy[i]))
        continue;
      if (f.n[i] >= 0 && (above < 0 || f.n[i] < f.n[above]))
        above = static_cast<int>(i);
      if (f.n[i] < 0 && (below < 0 || f.n[i] > f.n[below]))
        below = static_cast<int>(i);
    }
    double e_plane = NAN;
    if (above >= 0 && below >= 0) {
      const double w = (0 - f.n[below]) / (f.n[above] - f.n[below]);
      e_plane = f.eyy[below] + w * (f.eyy[above] - f.eyy[below]);
    } else if (above >= 0 && f.n[above] <= 0.5 * h + slack) {
      e_plane = f.eyy[above];
    } else if (below >= 0 && -f.n[below] <= 0.5 * h + slack) {
      e_plane = f.eyy[below];
    }
    p.s.push_back(s_sum / static_cast<double>(e - b));
    p.eyy.push_back(e_plane);
    b = e;
  }
  return p;
}

namespace {

/// Robust strain noise from second differences of consecutive valid stations with s > from.
double noise_ahead(const PlaneProfile& p, double from) {
  std::vector<double> v;
  for (std::size_t i = 0; i < p.s.size(); ++i)
    if (p.s[i] > from && std::isfinite(p.eyy[i]))
      v.push_back(p.eyy[i]);
  if (v.size() < 7)
    return NAN;
  std::vector<double> d2;
  for (std::size_t i = 1; i + 1 < v.size(); ++i)
    d2.push_back(v[i - 1] - 2 * v[i] + v[i + 1]);
  const double m = median_upper(d2);
  for (auto& d : d2)
    d = std::abs(d - m);
  // Var(e[i-1] - 2 e[i] + e[i+1]) = 6 sigma^2 for white noise; 1.4826 MAD estimates a std.
  return 1.4826 * median_upper(d2) / std::sqrt(6.0);
}

} // namespace

TipReading locate_tip(const PlaneProfile& p, const TipRule& rule, double h) {
  TipReading r;
  const std::size_t n = p.s.size();
  const bool any_valid =
      std::any_of(p.eyy.begin(), p.eyy.end(), [](double e) { return std::isfinite(e); });
  if (n == 0 || !any_valid) {
    r.note = "no valid point on the crack plane (every point within 1.5 spacings of it failed or "
             "none lies there)";
    return r;
  }
  std::size_t i0 = 0;
  while (i0 < n && p.s[i0] < -0.5 * h)
    ++i0;
  if (i0 == n) {
    r.note = "no point on the crack plane ahead of the notch root";
    return r;
  }
  long last_open = -1;
  int dips = 0;
  // A failed station (NaN) extends the open run only straight after an open one: correlation is
  // lost where the crack has opened, not ahead of a station already below the threshold.
  const auto open = [&](std::size_t j) {
    return p.eyy[j] >= rule.threshold || (std::isnan(p.eyy[j]) && dips == 0);
  };
  for (std::size_t j = i0; j < n; ++j) {
    if (open(j)) {
      last_open = static_cast<long>(j);
      dips = 0;
    } else if (++dips > rule.bridged_dips) {
      break;
    }
  }
  r.found = true;
  double gap = h;
  if (last_open < 0) {
    r.s = 0; // not open to the threshold at the notch root: no growth
  } else if (static_cast<std::size_t>(last_open) == n - 1) {
    r.beyond_view = true;
    r.s = std::max(0.0, p.s[n - 1]);
    r.note = "the strain is at or above the threshold up to the end of the field of view (s = " +
             fmt(p.s[n - 1] * 1e3) + " mm): the tip has left the view";
  } else {
    const std::size_t o = static_cast<std::size_t>(last_open), c = o + 1;
    gap = p.s[c] - p.s[o];
    if (std::isfinite(p.eyy[o]))
      r.s = p.s[o] + (p.eyy[o] - rule.threshold) / (p.eyy[o] - p.eyy[c]) * gap;
    else
      r.s = 0.5 * (p.s[o] + p.s[c]); // failed stations up to here: midway to the first below
    r.s = std::max(0.0, r.s);
  }
  r.noise = noise_ahead(p, r.s + 2 * h);
  if (!std::isfinite(r.noise))
    r.noise = noise_ahead(p, -0.5 * h);
  // Slope of the profile at the crossing: a straight line through the valid stations within two
  // spacings of it.
  double sw = 0, ss = 0, se = 0, sss = 0, sse = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (std::isfinite(p.eyy[i]) && std::abs(p.s[i] - r.s) <= 2 * h) {
      sw += 1;
      ss += p.s[i];
      se += p.eyy[i];
      sss += p.s[i] * p.s[i];
      sse += p.s[i] * p.eyy[i];
    }
  const double det = sw * sss - ss * ss;
  if (sw >= 2 && det > 0)
    r.slope = (sw * sse - ss * se) / det;
  double var = gap * gap / 12;
  // The noise moves a crossing along the profile's slope; with none (closed at the root, or the
  // last station open) only the station spacing counts.
  const bool crossing = last_open >= 0 && !r.beyond_view;
  if (crossing && std::isfinite(r.noise) && std::isfinite(r.slope) && r.slope < 0)
    var += (r.noise / r.slope) * (r.noise / r.slope);
  r.sd = std::sqrt(var);
  return r;
}

} // namespace fiberbridge::dic
