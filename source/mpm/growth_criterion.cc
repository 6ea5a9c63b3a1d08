#include "fiberbridge/mpm/growth_criterion.h"

#include "fiberbridge/core/binary_archive.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/mpm/dcb.h"

#include <algorithm>
#include <cmath>

namespace fiberbridge::mpm {

GrowthCriterion::GrowthCriterion(const specimen::Specimen& s, const specimen::Material& m,
                                 double j_tip, double window_periods, double step,
                                 double check_interval)
    : spec_(s), mat_(m), j_tip_(j_tip), window_periods_(window_periods), step_(step),
      check_interval_(check_interval) {}

void GrowthCriterion::set_window(double a, double opening, double rate, bool count) {
  // What rings after an advance is the arm at its current length: average over a fixed fraction
  // of that period. (A window fixed at the a0 period averaged less and less of the ringing as
  // the crack grew: near the end of the linear-softening verification run the tip advanced
  // twice within one period and J_ff at the second advance read 15 % low.)
  double window = window_periods_ * arm_vibration_period(spec_, mat_, a);
  // The tip advances at most once per window, so the window must stay shorter than the time the
  // loading needs to drive the tip one step quasi-statically, or the tip falls behind and J
  // overshoots J_tip. That time, from corrected beam theory at constant G (opening ~ (a + chi h)^2
  // in LEFM; a rising R curve needs more): opening * (Delta(a + da)/Delta(a) - 1) / rate. The
  // window takes at most 0.7 of it (0.5 rode the ringing's peaks: -4.9 % on G_ss in the linear-
  // softening run at 8 loading periods; uncapped, the tip lagged at the end of the PVA run).
  auto lefm_opening = [&](double x) {
    return specimen::cbt_opening(spec_, mat_,
                                 specimen::cbt_load_at_crack_length(spec_, mat_, 1.0, x), x);
  };
  const double step_time = opening * (lefm_opening(a + step_) / lefm_opening(a) - 1) / rate;
  if (window > 0.7 * step_time) {
    window = 0.7 * step_time;
    if (count)
      ++shortened_;
  }
  length_ = static_cast<std::size_t>(std::max(1.0, std::round(window / check_interval_)));
}

bool GrowthCriterion::advance_due(double j, double& mean) {
  // A sliding window that restarts at every advance: the waves an advance releases and the
  // arm's ringing then cannot push the tip on their peaks, which made the far-field J fall
  // 20-30 % below J_tip on average. The window bounds the tip speed at one step per window.
  window_.push_back(j);
  if (window_.size() > length_)
    window_.pop_front();
  if (window_.size() < length_)
    return false;
  double sum = 0;
  for (double v : window_)
    sum += v;
  mean = sum / window_.size();
  if (mean < j_tip_)
    return false;
  window_.clear();
  return true;
}

void GrowthCriterion::save_state(BinaryWriter& out) const {
  out.put(static_cast<std::uint64_t>(length_));
  out.put(window_);
  out.put(shortened_);
}

void GrowthCriterion::load_state(BinaryReader& in) {
  const auto length = in.get<std::uint64_t>();
  in.get(window_);
  in.get(shortened_);
  if (length < 1 || window_.size() > length)
    throw InputError(in.source() + ": the growth criterion's J window holds " +
                     std::to_string(window_.size()) + " of " + std::to_string(length) +
                     " evaluations");
  length_ = static_cast<std::size_t>(length);
}

} // namespace fiberbridge::mpm
