#pragma once
// When the DCB's crack tip advances (the role of NairnMPM's propagation task): the tip J,
// evaluated every few steps, is averaged over a window that restarts at each advance and
// compared with J_tip. The window is a fraction of the first-mode period of the arm at the
// current crack length, capped so that the tip keeps up with the loading.
#include "fiberbridge/specimen/specimen.h"

#include <cstddef>
#include <deque>

namespace fiberbridge {
class BinaryWriter;
class BinaryReader;
} // namespace fiberbridge

namespace fiberbridge::mpm {

class GrowthCriterion {
public:
  /// A window-mean tip J above this multiple of J_tip at an advance: the tip lagged the loading
  /// (the mean overshoots by the J rise within one check interval, well below 1 %, otherwise).
  static constexpr double lag_tolerance = 1.02;

  /// `window_periods` arm periods per window (MPM/J window periods), `step` the tip advance [m],
  /// `check_interval` the time between two tip-J evaluations [s].
  GrowthCriterion(const specimen::Specimen& specimen, const specimen::Material& material,
                  double j_tip, double window_periods, double step, double check_interval);

  /// Sizes the window for the tip at `a`, the load line opened by `opening` [m] and opening at
  /// `rate` [m/s]; a window the loading cuts short is counted when `count` is set.
  void set_window(double a, double opening, double rate, bool count);
  /// Adds one tip-J evaluation [J/m^2]; true when the window is full and its mean (returned in
  /// `mean`) reaches J_tip, and the window then restarts.
  bool advance_due(double j, double& mean);
  /// Did an advance at window-mean J lag the loading?
  bool lagged(double j) const { return j > lag_tolerance * j_tip_; }
  int shortened_windows() const { return shortened_; }

  /// The window (length and the evaluations in it) and the count of shortened windows
  /// (checkpoints, mpm/checkpoint.h).
  void save_state(BinaryWriter& out) const;
  void load_state(BinaryReader& in);

private:
  specimen::Specimen spec_;
  specimen::Material mat_;
  double j_tip_, window_periods_, step_, check_interval_;
  std::size_t length_ = 1; ///< evaluations averaged
  std::deque<double> window_;
  int shortened_ = 0;
};

} // namespace fiberbridge::mpm
