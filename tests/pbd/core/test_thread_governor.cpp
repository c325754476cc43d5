#include <gtest/gtest.h>

#include "pbd/core/thread_governor.h"

namespace hs::pbd {
namespace {

// Steps of `seconds` each on many threads and `oneSeconds` on one, until `steps` are taken.
void run(ThreadGovernor& governor, int steps, double manySeconds, double oneSeconds) {
  for (int k = 0; k < steps; ++k) governor.record(governor.threads() == 1 ? oneSeconds : manySeconds);
}

TEST(ThreadGovernor, OneThreadAllowedIsOneThreadAlways) {
  ThreadGovernor governor(1);
  run(governor, 100, 1e-3, 1e-3);
  EXPECT_EQ(governor.threads(), 1);
  EXPECT_EQ(governor.reducedSteps(), 0);
}

TEST(ThreadGovernor, ProbesManyThenOneAndHoldsTheFaster) {
  const ThreadGovernorSettings settings{.probeSteps = 4, .holdSteps = 10, .holdSeconds = 0};
  ThreadGovernor idle(2, settings);
  EXPECT_EQ(idle.threads(), 2);  // a probe starts on all the threads
  run(idle, 4, 1e-3, 2e-3);
  EXPECT_EQ(idle.threads(), 1);  // then as many steps on one
  run(idle, 4, 1e-3, 2e-3);
  EXPECT_EQ(idle.threads(), 2);  // two threads were faster: held
  run(idle, 9, 1e-3, 2e-3);
  EXPECT_EQ(idle.threads(), 2);
  EXPECT_EQ(idle.reducedSteps(), 4);  // only the probe's

  ThreadGovernor busy(2, settings);
  run(busy, 8, 4e-3, 1e-3);
  EXPECT_EQ(busy.threads(), 1);  // one thread was faster: held
  run(busy, 9, 4e-3, 1e-3);
  EXPECT_EQ(busy.threads(), 1);
}

// The first step after a change pays for waking threads and is not counted: a slow first step
// on two threads does not decide against them.
TEST(ThreadGovernor, TheFirstStepAfterAChangeIsNotTimed) {
  ThreadGovernor governor(2, {.probeSteps = 3, .holdSteps = 10, .holdSeconds = 0});
  governor.record(1.0);  // waking
  governor.record(1e-3);
  governor.record(1e-3);
  ASSERT_EQ(governor.threads(), 1);
  run(governor, 3, 1e-3, 2e-3);
  EXPECT_EQ(governor.threads(), 2);
}

// A hold ends after both its steps and its seconds; the next probe follows a machine that has
// become busy.
TEST(ThreadGovernor, AHoldEndsAfterItsStepsAndSecondsAndProbesAgain) {
  ThreadGovernor governor(2, {.probeSteps = 2, .holdSteps = 5, .holdSeconds = 0.1});
  run(governor, 4, 1e-3, 2e-3);
  ASSERT_EQ(governor.threads(), 2);
  run(governor, 5, 1e-3, 2e-3);  // 5 steps but only 5 ms: still held
  EXPECT_EQ(governor.threads(), 2);
  run(governor, 1, 0.2, 2e-3);  // the seconds are reached: a new probe on two threads
  EXPECT_EQ(governor.threads(), 2);
  run(governor, 2, 5e-3, 1e-3);  // the machine is busy now
  EXPECT_EQ(governor.threads(), 1);
  run(governor, 2, 5e-3, 1e-3);
  EXPECT_EQ(governor.threads(), 1);  // held on one
}

// A probe that confirms the count held doubles the next hold, up to maxHoldScale; a probe that
// changes it starts again from one hold.
TEST(ThreadGovernor, ConfirmedCountsAreHeldLonger) {
  ThreadGovernor governor(2, {.probeSteps = 2, .holdSteps = 10, .holdSeconds = 0, .maxHoldScale = 4});
  const auto holdLength = [&](double manySeconds, double oneSeconds) {
    run(governor, 4, manySeconds, oneSeconds);  // the probe
    int held = 0;
    const int count = governor.threads();
    while (governor.threads() == count && held < 1000) {
      governor.record(count == 1 ? oneSeconds : manySeconds);
      ++held;
    }
    return held;
  };
  // A busy machine: one thread is faster. A hold on one thread ends when the next probe puts
  // both threads back to work.
  EXPECT_EQ(holdLength(4e-3, 1e-3), 10);  // the first choice: one hold
  EXPECT_EQ(holdLength(4e-3, 1e-3), 20);  // confirmed: twice as long
  EXPECT_EQ(holdLength(4e-3, 1e-3), 40);
  EXPECT_EQ(holdLength(4e-3, 1e-3), 40);  // at most maxHoldScale holds
  // Idle again: two threads are faster, one hold again (counted to the next probe's switch to
  // one thread: its two steps on both threads follow the hold).
  EXPECT_EQ(holdLength(1e-3, 2e-3), 10 + 2);
}

TEST(ThreadGovernor, NotAdaptiveUsesAllTheThreadsAlways) {
  ThreadGovernor governor(2, {.adaptive = false});
  run(governor, 100, 1.0, 1e-3);
  EXPECT_EQ(governor.threads(), 2);
  EXPECT_EQ(governor.reducedSteps(), 0);
}

}  // namespace
}  // namespace hs::pbd
