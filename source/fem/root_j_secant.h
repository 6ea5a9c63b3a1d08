#pragma once
// The search that loads the FEM DCB to criticality (docs/design.md section 2, "Growth"): find
// the value x of the control (the load-point opening, or the opening of the node next behind the
// tip under crack-tip control) at which the tip J equals J_tip. Near the tip the opening grows
// as sqrt(J) (the LEFM field), so sqrt(J) is close to linear in either control and a secant on
// it converges in a few trials. Once a trial overshoots, the root is bracketed and every guess
// stays inside the bracket (bisection where the secant leaves it).
#include <algorithm>
#include <cmath>

namespace fiberbridge::fem {

class RootJSecant {
public:
  /// `j_target` = J_tip; (x0, j0) the state the search starts from (j0 = 0 when that state has
  /// no tip J of its own, as right after a release under crack-tip control).
  RootJSecant(double j_target, double x0, double j0)
      : target_(std::sqrt(j_target)), lo_{x0, root(j0)} {}

  /// `next` kept where it can help: inside the bracket once there is one, else beyond the last
  /// sample below J_tip (at least 1.1 times max(that sample, floor)).
  double safeguard(double next, double floor = 0) const {
    if (bracketed_ && !(next > lo_.x && next < hi_.x))
      return 0.5 * (lo_.x + hi_.x);
    if (!bracketed_ && !(next > lo_.x))
      return 1.1 * std::max(lo_.x, floor);
    return next;
  }

  /// Adds the trial (x, J) and returns the next guess: the secant through the bracket, or the
  /// extrapolation of sqrt(J) through the origin before the first overshoot.
  double add(double x, double J) {
    const Sample s{x, root(J)};
    if (s.root_j < target_)
      lo_ = s;
    else {
      hi_ = s;
      bracketed_ = true;
    }
    if (bracketed_)
      return lo_.x + (target_ - lo_.root_j) * (hi_.x - lo_.x) / (hi_.root_j - lo_.root_j);
    return s.root_j > 0 ? x * target_ / s.root_j : 2 * x;
  }

private:
  struct Sample {
    double x, root_j;
  };
  static double root(double J) { return std::sqrt(std::max(J, 0.0)); }

  double target_;
  Sample lo_, hi_{0, 0};
  bool bracketed_ = false;
};

} // namespace fiberbridge::fem
