#include "fiberbridge/law/elastic_rise_law.h"

namespace fiberbridge::law {

ElasticRiseLaw::ElasticRiseLaw(const TractionLaw& base, double delta_e)
    : base_(base), delta_e_(delta_e), sigma_e_(base.envelope(delta_e)) {}

double ElasticRiseLaw::rise_end_for_slope(const TractionLaw& base, double k) {
  double d = base.envelope(0) / k;
  for (int i = 0; i < 20; ++i) // converges fast: k is large against the softening slope
    d = base.envelope(d) / k;
  return d;
}

double ElasticRiseLaw::envelope_integral(double d) const {
  if (d <= 0)
    return 0;
  if (d < delta_e_)
    return 0.5 * sigma_e_ * d * d / delta_e_;
  return 0.5 * sigma_e_ * delta_e_ + base_.envelope_integral(d) - base_.envelope_integral(delta_e_);
}

std::vector<double> ElasticRiseLaw::kinks() const {
  std::vector<double> k{0.0, delta_e_};
  for (double b : base_.kinks())
    if (b > delta_e_)
      k.push_back(b);
  return k;
}

} // namespace fiberbridge::law
