#pragma once
// The paper's new extraction (seed Eqs. 5-6) and the old sigma = R' method beside it.
#include "fiberbridge/analysis/rdelta_data.h"

#include <vector>

namespace fiberbridge::analysis {

/// Smoothed slopes S_i = R'(delta_i) on the grid delta_i = i delta_c / n, i = 0..n (seed section
/// 2.3 step 2): least-squares line through the curve's points with delta in
/// [delta_{i-k}, delta_{i+k}] (window clipped to [0, delta_c]; the curve is interpolated onto the
/// grid first when it is coarser). S_n = 0: R' vanishes beyond delta_c by definition of the
/// steady state, which is what lets Eq. 5's upper limit be delta_c.
std::vector<double> smoothed_slopes(const RDeltaCurve& curve, double delta_c, int n, int k);

/// Eq. 6 in O(n) with a suffix sum: sigma_0 = 0 and for i = 1..n
/// sigma_i = 2 [S_i - (i/n) (S_n - n sum_{m=i}^{n-1} (S_{m+1} - S_m) ln((m+1)/m))].
/// Gives Eq. 7 exactly for linear softening (i < n).
std::vector<double> cohesive_law_eq6(const std::vector<double>& S);

/// The old method: sigma_i = S_i (= R'(delta_i)), sigma_0 = 0 for comparison on the same grid.
std::vector<double> cohesive_law_dRdd(const std::vector<double>& S);

/// Both laws on the grid delta_i = i delta_c / n.
struct ExtractedLaws {
  std::vector<double> delta;          ///< [m]
  std::vector<double> sigma_eq6;      ///< [Pa]
  std::vector<double> sigma_dRdd;     ///< [Pa]
  double area_eq6 = 0, area_dRdd = 0; ///< trapezoid areas [J/m^2] (both should be near G_B)
};

ExtractedLaws extract_cohesive_laws(const RDeltaCurve& curve, double delta_c, int n, int k);

} // namespace fiberbridge::analysis
