#pragma once
#include "fiberbridge/law/traction_law.h"

namespace fiberbridge::law {

/// Exponential softening truncated at delta_c and shifted so it reaches zero there:
/// sigma = sigma_c (exp(-a x) - exp(-a)) / (1 - exp(-a)), x = delta/delta_c, a = `decay` (default
/// 5). (The seed tried exponential softening first; it is rigid at zero opening like linear
/// softening.)
class ExponentialLaw : public TractionLaw {
public:
  ExponentialLaw(double sigma_c, double delta_c, double decay = 5.0);
  std::string name() const override { return "exponential"; }
  double envelope(double delta) const override;
  double envelope_slope(double delta) const override;
  double envelope_integral(double delta) const override;
  double critical_opening() const override { return delta_c_; }
  std::vector<double> kinks() const override { return {0.0, delta_c_}; }

private:
  double sigma_c_, delta_c_, decay_;
};

/// The no-bridging law ("none"): zero traction, zero area; the LEFM limit. Contact still acts.
class NoBridgingLaw : public TractionLaw {
public:
  std::string name() const override { return "none"; }
  double envelope(double) const override { return 0; }
  double envelope_slope(double) const override { return 0; }
  double envelope_integral(double) const override { return 0; }
  double critical_opening() const override { return 0; }
  std::vector<double> kinks() const override { return {0.0}; }
};

} // namespace fiberbridge::law
