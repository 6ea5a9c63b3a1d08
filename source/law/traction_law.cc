#include "fiberbridge/law/traction_law.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fiberbridge::law {

std::pair<double, double> TractionLaw::peak() const {
  // The envelope is piecewise smooth between kinks; the peak is at a kink or where the slope
  // vanishes. Sampling each segment finely and taking the kinks covers both for our laws.
  double best_sigma = 0, best_delta = 0;
  const auto k = kinks();
  for (std::size_t i = 0; i + 1 < k.size(); ++i) {
    const int n = 64;
    for (int j = 0; j <= n; ++j) {
      const double d = k[i] + (k[i + 1] - k[i]) * j / n;
      const double s = envelope(d);
      if (s > best_sigma) {
        best_sigma = s;
        best_delta = d;
      }
    }
  }
  return {best_sigma, best_delta};
}

double TractionLaw::initial_stiffness() const {
  if (critical_opening() <= 0)
    return 0;
  if (rigid_at_zero_opening())
    return std::numeric_limits<double>::infinity();
  const auto k = kinks();
  const double d1 = k.size() > 1 ? k[1] : critical_opening();
  return envelope(d1) / d1;
}

CohesiveResponse TractionLaw::respond(double opening, double delta_max,
                                      double contact_stiffness) const {
  CohesiveResponse r;
  r.delta_max = delta_max;
  const double dc = critical_opening();
  if (opening < 0) {
    // Closing below zero opening is contact: a penalty, elastic, no damage and no dissipation.
    r.traction = contact_stiffness * opening;
    r.tangent = contact_stiffness;
    r.failed = delta_max >= dc;
    return r;
  }
  if (opening >= delta_max) {
    r.delta_max = opening;
    if (opening >= dc) {
      r.failed = true;
      return r;
    }
    r.traction = envelope(opening);
    r.tangent = envelope_slope(opening);
    return r;
  }
  // Unloading/reloading below the history maximum: secant to the origin (elastic damage).
  if (delta_max >= dc) {
    r.failed = true;
    return r;
  }
  const double secant = envelope(delta_max) / delta_max;
  r.traction = secant * opening;
  r.tangent = secant;
  return r;
}

double j_far_field_eq1(const TractionLaw& law, double j_tip, double delta) {
  return j_tip + law.envelope_integral(std::max(0.0, std::min(delta, law.critical_opening())));
}

double r_curve_eq2(const TractionLaw& law, double j_tip, double delta) {
  const double dc = law.critical_opening();
  if (delta >= dc)
    return j_tip + law.area();
  delta = std::max(0.0, delta);
  return j_tip + law.envelope_integral(delta) - 0.5 * delta * law.envelope(delta);
}

} // namespace fiberbridge::law
