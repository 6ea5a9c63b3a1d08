// The virtual extensometer at the initial notch root (extensometer.h).
#include "fiberbridge/dic/extensometer.h"

#include "fiberbridge/core/format.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace fiberbridge::dic {

namespace {

struct PointFit {
  bool ok = false;
  double value = NAN, var = NAN;
  int n = 0;
};

/// v at (0, n0) from the k nearest valid points with n on the side of n0, |n| >= spacing/2.
PointFit fit_point(const PlaneFrame& f, double n0, double h, int k) {
  PointFit out;
  std::vector<std::pair<double, std::size_t>> cand;
  const double radius2 = 9 * h * h;
  for (std::size_t i = 0; i < f.s.size(); ++i) {
    // Rows at half a spacing (a plane midway between rows) are kept: the slack absorbs rounding.
    if (!f.valid[i] || !std::isfinite(f.vn[i]) || std::abs(f.n[i]) < 0.5 * h - 1e-3 * h ||
        (f.n[i] > 0) != (n0 > 0))
      continue;
    const double d2 = f.s[i] * f.s[i] + (f.n[i] - n0) * (f.n[i] - n0);
    if (d2 <= radius2)
      cand.emplace_back(d2, i);
  }
  const std::size_t m = std::min<std::size_t>(cand.size(), static_cast<std::size_t>(k));
  out.n = static_cast<int>(m);
  if (m < 4)
    return out;
  std::partial_sort(cand.begin(), cand.begin() + m, cand.end());
  // Normal equations of v = a + b s + c (n - n0); a is v at the material point.
  std::array<double, 9> M{};
  std::array<double, 3> rhs{};
  for (std::size_t k2 = 0; k2 < m; ++k2) {
    const std::size_t i = cand[k2].second;
    const double row[3] = {1, f.s[i], f.n[i] - n0};
    for (int r = 0; r < 3; ++r) {
      rhs[r] += row[r] * f.vn[i];
      for (int c = 0; c < 3; ++c)
        M[3 * r + c] += row[r] * row[c];
    }
  }
  const double c00 = M[4] * M[8] - M[5] * M[7], c01 = M[5] * M[6] - M[3] * M[8],
               c02 = M[3] * M[7] - M[4] * M[6];
  const double det = M[0] * c00 + M[1] * c01 + M[2] * c02;
  const double scale = M[0] * M[4] * M[8];
  if (!(std::abs(det) > 1e-12 * std::abs(scale))) {
    // Points on one line (a single row or column): the mean, its standard error.
    double sum = 0, sum2 = 0;
    for (std::size_t k2 = 0; k2 < m; ++k2) {
      sum += f.vn[cand[k2].second];
      sum2 += f.vn[cand[k2].second] * f.vn[cand[k2].second];
    }
    out.value = sum / m;
    out.var = std::max(0.0, sum2 / m - out.value * out.value) / (m - 1);
    out.ok = true;
    return out;
  }
  const double c11 = M[0] * M[8] - M[2] * M[6], c12 = M[2] * M[3] - M[0] * M[5],
               c22 = M[0] * M[4] - M[1] * M[3];
  // Inverse = adjugate / det (M symmetric: cofactor matrix symmetric).
  const double inv[9] = {c00 / det, c01 / det, c02 / det, c01 / det, c11 / det,
                         c12 / det, c02 / det, c12 / det, c22 / det};
  double coef[3];
  for (int r = 0; r < 3; ++r)
    coef[r] = inv[3 * r] * rhs[0] + inv[3 * r + 1] * rhs[1] + inv[3 * r + 2] * rhs[2];
  double ssr = 0;
  for (std::size_t k2 = 0; k2 < m; ++k2) {
    const std::size_t i = cand[k2].second;
    const double res = f.vn[i] - (coef[0] + coef[1] * f.s[i] + coef[2] * (f.n[i] - n0));
    ssr += res * res;
  }
  out.value = coef[0];
  out.var = ssr / static_cast<double>(m - 3) * inv[0];
  out.ok = true;
  return out;
}

} // namespace

ExtensometerReading read_extensometer(const PlaneFrame& f, double gauge, double h, int k) {
  ExtensometerReading r;
  const PointFit up = fit_point(f, 0.5 * gauge, h, k), down = fit_point(f, -0.5 * gauge, h, k);
  r.n_upper = up.n;
  r.n_lower = down.n;
  if (!up.ok || !down.ok) {
    r.note = "extensometer: fewer than 4 valid points within 3 spacings of the " +
             std::string(!up.ok ? "upper" : "lower") + " point (" +
             std::to_string(!up.ok ? up.n : down.n) + " found)";
    return r;
  }
  r.ok = true;
  r.upper = up.value;
  r.lower = down.value;
  r.opening = up.value - down.value;
  r.sd = std::sqrt(up.var + down.var);
  return r;
}

} // namespace fiberbridge::dic
