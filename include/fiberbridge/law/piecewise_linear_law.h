#pragma once
// Piecewise-linear laws: linear softening, bilinear, trilinear and tabulated laws are all
// polylines from (0, s0) to (delta_c, 0). Integrals and slopes are exact.
#include "fiberbridge/law/traction_law.h"

#include <string>
#include <vector>

namespace fiberbridge::law {

struct LawPoint {
  double delta; ///< opening [m]
  double sigma; ///< traction [Pa]
};

class PiecewiseLinearLaw : public TractionLaw {
public:
  /// Points from delta = 0 to delta_c. Validated: first delta is 0, deltas strictly increasing,
  /// tractions finite and >= 0, last traction 0, at least one positive traction.
  /// `context` names the source in error messages (a file, a scene key).
  PiecewiseLinearLaw(std::vector<LawPoint> points, std::string name,
                     const std::string& context = "cohesive law");

  std::string name() const override { return name_; }
  double envelope(double delta) const override;
  double envelope_slope(double delta) const override;
  double envelope_integral(double delta) const override;
  double critical_opening() const override { return points_.back().delta; }
  std::vector<double> kinks() const override;
  const std::vector<LawPoint>& points() const { return points_; }

  /// For a rigid law (sigma(0) > 0): the same polyline with an elastic rise from (0,0) to
  /// (delta_e, sigma(delta_e)). Changes the area by -sigma(0)*delta_e/2 + O(delta_e^2).
  PiecewiseLinearLaw with_elastic_rise(double delta_e) const;

private:
  std::size_t segment(double delta) const;
  std::vector<LawPoint> points_;
  std::vector<double> cumulative_area_; ///< int_0^{points_[i].delta}
  std::string name_;
};

/// sigma = sigma_c (1 - delta/delta_c). Forward R is J_tip + sigma_c delta / 2 exactly.
PiecewiseLinearLaw make_linear_softening(double sigma_c, double delta_c);
/// (0,0) -> (d1, s1) -> (dc, 0).
PiecewiseLinearLaw make_bilinear(double d1, double s1, double dc);

/// The five numbers of seed Fig. 1C and Table 1.
struct TrilinearParameters {
  double d1 = 0, s1 = 0, d2 = 0, s2 = 0, dc = 0; ///< [m], [Pa]

  /// Seed Table 1 convention: J_1 = (s1 d2 - s2 d1)/2. (The text prints '+'; the table uses '-'
  /// and the two parts then add up to Eq. 8.)
  double j1() const { return 0.5 * (s1 * d2 - s2 * d1); }
  /// J_2 = s2 dc / 2.
  double j2() const { return 0.5 * s2 * dc; }
  /// Eq. 8: J_c = (s1 d2 + s2 (dc - d1))/2 = J_1 + J_2.
  double area() const { return j1() + j2(); }
};

/// (0,0) -> (d1,s1) -> (d2,s2) -> (dc,0); validated like any polyline.
PiecewiseLinearLaw make_trilinear(const TrilinearParameters& p);

/// Reads a tabulated law from CSV columns delta_mm, sigma_kPa (the table must start at
/// delta 0 and end with sigma 0 at delta_c).
PiecewiseLinearLaw read_law_table_csv(const std::string& path);

} // namespace fiberbridge::law
