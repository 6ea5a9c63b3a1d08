#pragma once
// Reducing an extracted law to the trilinear law of seed Fig. 1C (section 3.3).
#include "fiberbridge/law/piecewise_linear_law.h"

#include <vector>

namespace fiberbridge::analysis {

struct TrilinearFit {
  law::TrilinearParameters law; ///< fitted (d1, s1, d2, s2, dc), SI
  double rms_residual = 0;      ///< root-mean-square of sigma_data - sigma_fit [Pa]
  double max_residual = 0;      ///< [Pa]
  double area_constraint = 0;   ///< the G_B the area was constrained to [J/m^2]
  bool d1_d2_free = false;
};

/// d1, d2, dc fixed: the law is linear in (s1, s2), so least squares under the linear constraint
/// J_1 + J_2 = (s1 d2 + s2 (dc - d1))/2 = G_B has a closed form (Lagrange multiplier).
/// Throws InputError for d1 >= d2 >= dc orderings or when fewer than 3 points lie in (0, dc).
/// Negative fitted stresses throw ComputationError naming the cause (data not bridging-shaped).
TrilinearFit fit_trilinear_fixed(const std::vector<double>& delta, const std::vector<double>& sigma,
                                 double d1, double d2, double dc, double G_B);

/// d1 in [d1_min, d1_max], d2 in (d1, d2_max] free as well: variable projection (the closed form
/// above inside a bounded 2-D search over d1, d2).
TrilinearFit fit_trilinear_free(const std::vector<double>& delta, const std::vector<double>& sigma,
                                double dc, double G_B, double d1_min, double d1_max, double d2_max);

} // namespace fiberbridge::analysis
