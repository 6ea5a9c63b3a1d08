#pragma once
// A rigid law (sigma(0) > 0: linear or exponential softening) with a short elastic rise: the
// secant from (0, 0) to (delta_e, sigma(delta_e)) below delta_e, the law unchanged above. R then
// changes by -sigma(0) delta_e / 2 + O(delta_e^2) for good. The models insert rigid laws
// extrinsically instead (law/rigid_law.h); this wrapper stays for comparisons with intrinsic-law
// codes (law::with_elastic_rise).
#include "fiberbridge/law/traction_law.h"

#include <vector>

namespace fiberbridge::law {

class ElasticRiseLaw : public TractionLaw {
public:
  /// Refers to `base`, which must outlive this law.
  ElasticRiseLaw(const TractionLaw& base, double delta_e);
  /// Where the line of slope k from the origin meets a decreasing envelope:
  /// delta_e = sigma(delta_e) / k (fixed-point iteration from sigma(0) / k).
  static double rise_end_for_slope(const TractionLaw& base, double k);

  std::string name() const override { return base_.name(); }
  double envelope(double d) const override {
    return d < delta_e_ ? (d > 0 ? sigma_e_ * d / delta_e_ : 0.0) : base_.envelope(d);
  }
  double envelope_slope(double d) const override {
    return d < delta_e_ ? sigma_e_ / delta_e_ : base_.envelope_slope(d);
  }
  double envelope_integral(double d) const override;
  double critical_opening() const override { return base_.critical_opening(); }
  std::vector<double> kinks() const override;
  double delta_e() const { return delta_e_; }

private:
  const TractionLaw& base_;
  double delta_e_, sigma_e_;
};

} // namespace fiberbridge::law
