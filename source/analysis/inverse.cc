// The paper's extraction of the bridging law from R(delta) (seed section 2.3, Eqs. 5-6) and the
// old sigma = R'(delta) method beside it.
#include "fiberbridge/analysis/inverse.h"

#include "fiberbridge/analysis/line_fit.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fiberbridge::analysis {

namespace {

void check_curve(const RDeltaCurve& curve, double delta_c, int n, int k) {
  const auto fail = [](const std::string& what) {
    throw InputError("cohesive-law extraction: " + what);
  };
  if (n < 2)
    fail("the grid needs n >= 2 intervals, got n = " + std::to_string(n));
  if (k < 1)
    fail("the smoothing half-width k must be >= 1 (a slope needs two points), got " +
         std::to_string(k));
  if (curve.delta.size() < 2 || curve.delta.size() != curve.R.size())
    fail("the R(delta) curve needs at least 2 points with as many R as delta values");
  for (std::size_t i = 1; i < curve.delta.size(); ++i)
    if (!(curve.delta[i] > curve.delta[i - 1]))
      fail("the R(delta) curve must have strictly increasing delta; point " + std::to_string(i) +
           " is not");
  if (!(delta_c > 0) || !std::isfinite(delta_c))
    fail("delta_c must be a positive opening");
  // delta_c is the upper limit of Eq. 5; the data must reach it (a relative round-off allowance
  // lets delta_c equal the last grid point computed another way).
  if (delta_c > curve.delta.back() * (1 + 1e-12)) {
    std::ostringstream s;
    s << "delta_c = " << delta_c / units::mm << " mm lies beyond the data (last delta "
      << curve.delta.back() / units::mm << " mm)";
    fail(s.str());
  }
}

} // namespace

std::vector<double> smoothed_slopes(const RDeltaCurve& curve, double delta_c, int n, int k) {
  check_curve(curve, delta_c, n, k);
  const std::size_t nn = static_cast<std::size_t>(n);
  std::vector<double> grid(nn + 1);
  for (std::size_t i = 0; i <= nn; ++i)
    grid[i] = delta_c * static_cast<double>(i) / n;
  // Values on the grid: the data of the coarse mode, and the fallback of a dense-mode window
  // that happens to hold too few raw points.
  const std::vector<double> R_grid = resample_linear(curve.delta, curve.R, grid);

  std::size_t n_raw = 0;
  for (double d : curve.delta)
    n_raw += d <= delta_c ? 1 : 0;
  // Dense data carry more information than their interpolant on the grid: fit the raw points.
  const bool dense = n_raw > nn + 1;

  std::vector<double> S(nn + 1, 0.0);
  std::size_t begin = 0, end = 0; // raw points with delta in the window: [begin, end)
  for (std::size_t i = 0; i < nn; ++i) {
    // Step 2 of seed section 2.3: the window [delta_{i-k}, delta_{i+k}], clipped to [0, delta_c].
    const std::size_t lo = i >= static_cast<std::size_t>(k) ? i - k : 0;
    const std::size_t hi = std::min(nn, i + k);
    LineFit fit;
    if (dense) {
      // Both window ends move right with i, so two monotone pointers keep this O(k (n + M)).
      while (begin < curve.delta.size() && curve.delta[begin] < grid[lo])
        ++begin;
      end = std::max(end, begin);
      while (end < curve.delta.size() && curve.delta[end] <= grid[hi])
        ++end;
      if (end - begin >= 3)
        fit = fit_line(curve.delta, curve.R, begin, end);
    }
    if (!fit.valid)
      fit = fit_line(grid, R_grid, lo, hi + 1);
    S[i] = fit.slope;
  }
  // S_n = 0: R' vanishes beyond delta_c (steady state), which is what closes Eq. 5 at delta_c.
  S[nn] = 0.0;
  return S;
}

std::vector<double> cohesive_law_eq6(const std::vector<double>& S) {
  if (S.size() < 2)
    throw InputError("Eq. 6: need slopes S_0..S_n with n >= 1, got " + std::to_string(S.size()) +
                     " values");
  const std::size_t n = S.size() - 1;
  std::vector<double> sigma(n + 1, 0.0);
  // Eq. 6 integrates Eq. 5 exactly for R' piecewise linear through the S_i. The inner sum
  // T_i = sum_{m=i}^{n-1} (S_{m+1} - S_m) ln((m+1)/m) is a suffix sum, built from m = n-1 down,
  // so the whole law costs O(n) instead of the O(n^2) double loop. log1p(1/m) keeps the
  // logarithm accurate for large m, where (m+1)/m rounds.
  // sigma_i = 2 [S_i - (i/n) (S_n - n T_i)] = 2 [S_i - (i/n) S_n + i T_i].
  const double nd = static_cast<double>(n);
  double T = 0;
  for (std::size_t i = n; i-- > 1;) {
    T += (S[i + 1] - S[i]) * std::log1p(1.0 / static_cast<double>(i));
    const double id = static_cast<double>(i);
    sigma[i] = 2.0 * (S[i] - (id / nd) * S[n] + id * T);
  }
  // i = n: T_n = 0 and the bracket is S_n - S_n = 0. i = 0: sigma(0) = 0 by the seed's step 3
  // (the logarithm of m = 0 diverges; the factor delta_0 = 0 wins).
  sigma[n] = 0.0;
  sigma[0] = 0.0;
  return sigma;
}

std::vector<double> cohesive_law_dRdd(const std::vector<double>& S) {
  if (S.empty())
    throw InputError("sigma = R' method: no slopes given");
  std::vector<double> sigma = S;
  sigma[0] = 0.0; // same convention as Eq. 6 so the two laws compare point by point
  return sigma;
}

ExtractedLaws extract_cohesive_laws(const RDeltaCurve& curve, double delta_c, int n, int k) {
  const std::vector<double> S = smoothed_slopes(curve, delta_c, n, k);
  ExtractedLaws laws;
  laws.delta.resize(S.size());
  for (std::size_t i = 0; i < S.size(); ++i)
    laws.delta[i] = delta_c * static_cast<double>(i) / n;
  laws.sigma_eq6 = cohesive_law_eq6(S);
  laws.sigma_dRdd = cohesive_law_dRdd(S);
  // Both areas estimate G_B = G_ss - J_tip (seed section 3.2): not a test of validity, since
  // the two laws have the same area in the continuum limit.
  const double h = delta_c / n;
  for (std::size_t i = 1; i < S.size(); ++i) {
    laws.area_eq6 += 0.5 * h * (laws.sigma_eq6[i] + laws.sigma_eq6[i - 1]);
    laws.area_dRdd += 0.5 * h * (laws.sigma_dRdd[i] + laws.sigma_dRdd[i - 1]);
  }
  return laws;
}

} // namespace fiberbridge::analysis
