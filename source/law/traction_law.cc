#include "fiberbridge/law/traction_law.h"

#include "fiberbridge/core/numerical_fault.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

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

namespace {
CohesiveResponse respond_unchecked(const TractionLaw& law, double opening, double delta_max,
                                   double contact_stiffness) {
  CohesiveResponse r;
  r.delta_max = delta_max;
  const double dc = law.critical_opening();
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
    r.traction = law.envelope(opening);
    r.tangent = law.envelope_slope(opening);
    return r;
  }
  // Unloading/reloading below the history maximum: secant to the origin (elastic damage).
  if (delta_max >= dc) {
    r.failed = true;
    return r;
  }
  const double secant = law.envelope(delta_max) / delta_max;
  r.traction = secant * opening;
  r.tangent = secant;
  return r;
}
} // namespace

CohesiveResponse TractionLaw::respond(double opening, double delta_max,
                                      double contact_stiffness) const {
  // The law boundary of the numerical-fault checks (core/numerical_fault.h): a NaN opening would
  // fall through every comparison below into the secant branch and come back as a NaN traction.
  if (!std::isfinite(opening) || !std::isfinite(delta_max))
    check_finite(!std::isfinite(opening) ? opening : delta_max,
                 std::string(!std::isfinite(opening) ? "opening" : "history opening delta_max") +
                     " at a cohesive point of the " + name() + " law");
  const CohesiveResponse r = respond_unchecked(*this, opening, delta_max, contact_stiffness);
  if (!std::isfinite(r.traction) || !std::isfinite(r.tangent)) {
    std::ostringstream q;
    q << (!std::isfinite(r.traction) ? "traction" : "tangent") << " of the " << name()
      << " law at opening " << opening / units::mm << " mm";
    check_finite(!std::isfinite(r.traction) ? r.traction : r.tangent, q.str());
  }
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
