// The thread tuner of the explicit solver (include/fiberbridge/mpm/thread_tuner.h): which steps it
// times, and that it keeps the way with the shorter median step whatever one stalled step says.
#include "fiberbridge/mpm/thread_tuner.h"

#include <gtest/gtest.h>

using namespace fiberbridge::mpm;

namespace {
/// Runs one probe of `tuner` on `team` from step `first`, timing a step without the helpers at
/// `serial` s and with them at `parallel` s, and one stalled step of each way at 1 s.
void probe(ThreadTuner& tuner, WorkTeam& team, long first, double serial, double parallel) {
  for (long k = 0; k < 2 * ThreadTuner::probe_steps; ++k) {
    const long step = first + k;
    ASSERT_TRUE(tuner.begin_step(team, step)) << step;
    const bool with_helpers = k >= ThreadTuner::probe_steps;
    EXPECT_EQ(team.parallel(), with_helpers) << step;
    const bool stalled = k % ThreadTuner::probe_steps == 3;
    tuner.end_step(team, step, stalled ? 1.0 : with_helpers ? parallel : serial);
  }
}
} // namespace

TEST(ThreadTuner, KeepsTheWayWithTheShorterMedianStep) {
  WorkTeam team(2);
  ThreadTuner tuner;
  probe(tuner, team, 0, 2e-3, 1e-3);
  EXPECT_TRUE(team.parallel());
  // The rest of the period is not timed and keeps the choice.
  EXPECT_FALSE(tuner.begin_step(team, 2 * ThreadTuner::probe_steps));
  EXPECT_FALSE(tuner.begin_step(team, ThreadTuner::probe_period - 1));
  EXPECT_TRUE(team.parallel());
  // The next period's probe finds the helpers slower (busy cores): one thread from then on.
  probe(tuner, team, ThreadTuner::probe_period, 1e-3, 3e-3);
  EXPECT_FALSE(team.parallel());
}

TEST(ThreadTuner, OneThreadIsNeverTimed) {
  WorkTeam team(1);
  ThreadTuner tuner;
  for (long step = 0; step < 2 * ThreadTuner::probe_steps; ++step)
    EXPECT_FALSE(tuner.begin_step(team, step));
  EXPECT_FALSE(team.parallel());
}
