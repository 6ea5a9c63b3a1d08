#include "fiberbridge/law/exponential_law.h"

#include "fiberbridge/core/error.h"

#include <cmath>

namespace fiberbridge::law {

ExponentialLaw::ExponentialLaw(double sigma_c, double delta_c, double decay)
    : sigma_c_(sigma_c), delta_c_(delta_c), decay_(decay) {
  if (!(sigma_c > 0) || !(delta_c > 0) || !(decay > 0))
    throw InputError("exponential law: peak stress, delta_c and decay must be positive");
}

double ExponentialLaw::envelope(double delta) const {
  if (delta >= delta_c_)
    return 0;
  const double x = std::max(0.0, delta) / delta_c_;
  return sigma_c_ * (std::exp(-decay_ * x) - std::exp(-decay_)) / (1 - std::exp(-decay_));
}

double ExponentialLaw::envelope_slope(double delta) const {
  if (delta < 0 || delta >= delta_c_)
    return 0;
  const double x = delta / delta_c_;
  return -sigma_c_ * decay_ / delta_c_ * std::exp(-decay_ * x) / (1 - std::exp(-decay_));
}

double ExponentialLaw::envelope_integral(double delta) const {
  const double d = std::min(std::max(0.0, delta), delta_c_);
  const double x = d / delta_c_;
  const double e = std::exp(-decay_);
  return sigma_c_ * delta_c_ * ((1 - std::exp(-decay_ * x)) / decay_ - e * x) / (1 - e);
}

} // namespace fiberbridge::law
