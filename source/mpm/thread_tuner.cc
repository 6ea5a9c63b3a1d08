#include "fiberbridge/mpm/thread_tuner.h"

#include "fiberbridge/core/binary_archive.h"

#include <algorithm>

namespace fiberbridge::mpm {

bool ThreadTuner::begin_step(WorkTeam& team, long step) const {
  const long phase = step % probe_period;
  const bool probing = team.threads() > 1 && phase < 2 * probe_steps;
  if (probing)
    team.set_parallel(phase >= probe_steps);
  return probing;
}

void ThreadTuner::end_step(WorkTeam& team, long step, double seconds) {
  const long phase = step % probe_period;
  const bool parallel = phase >= probe_steps;
  probe_seconds_[parallel][phase % probe_steps] = seconds;
  if (phase == 2 * probe_steps - 1) {
    double median[2];
    for (int way = 0; way < 2; ++way) {
      double* t = probe_seconds_[way];
      std::nth_element(t, t + probe_steps / 2, t + probe_steps);
      median[way] = t[probe_steps / 2];
    }
    team.set_parallel(median[1] < median[0]);
  }
}

void ThreadTuner::save_state(BinaryWriter& out) const {
  out.put(probe_seconds_);
}

void ThreadTuner::load_state(BinaryReader& in) {
  in.get(probe_seconds_);
}

} // namespace fiberbridge::mpm
