#pragma once
// Whether the explicit solver's helper threads run its steps (split from explicit_solver.cc,
// issue 30 item 7). Helper threads pay only while the cores are free; on cores shared with other
// processes a descheduled helper stalls every step (measured: 1.3x slower than one thread at a
// load of 5.6 on 2 cores). Every probe_period steps the tuner times probe_steps steps without and
// probe_steps with the helpers and runs the rest of the period the faster way. It compares the
// median step of each way, not the sums: on a virtual machine one step in twenty may stall for
// milliseconds (the host runs something else), and with sums such a stall decided (measured: at
// 2.5 mm the sums chose one thread in half the periods while two threads ran the steps
// 1.3-1.45x faster). Both ways compute the same chunks in the same order (work_team.h): the
// results do not depend on the choice.
#include "fiberbridge/mpm/work_team.h"

namespace fiberbridge {
class BinaryWriter;
class BinaryReader;
} // namespace fiberbridge

namespace fiberbridge::mpm {

class ThreadTuner {
public:
  static constexpr long probe_period = 1000, probe_steps = 20;

  /// Before step `step` (the number of steps run so far): during a probe, sets `team` to the way
  /// this step times. Returns whether the step is timed (then call end_step after it).
  bool begin_step(WorkTeam& team, long step) const;
  /// After timed step `step`, which took `seconds` of wall time: keeps the time, and after the
  /// probe's last step sets `team` to the way with the shorter median step.
  void end_step(WorkTeam& team, long step, double seconds);

  /// The step times of the last probe, for checkpoints (the format of mpm::checkpoint_version 2).
  void save_state(BinaryWriter& out) const;
  void load_state(BinaryReader& in);

private:
  /// Each step's wall time of the probe [s]: [0] without, [1] with the helper threads.
  double probe_seconds_[2][probe_steps] = {};
};

} // namespace fiberbridge::mpm
