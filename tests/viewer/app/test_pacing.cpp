// Real-time pacing of the viewer's simulation thread: simulated time follows wall time x
// speed, what cannot be done is dropped (not made up in a burst) and reported, and the pace
// shown is measured over half-second windows.
#include <gtest/gtest.h>

#include "viewer/app/pacing.h"

namespace hs::viewer {
namespace {

constexpr double kDt = 0.005;

// The thread's loop with a clock given by hand: `wall` seconds between its wake-ups, and as
// many steps as are due each time (or at most `maxSteps`, a simulation too slow to do more).
long run(Pacer& pacer, double wall, int wakeUps, double speed, int maxSteps, bool* dropped = nullptr) {
  long steps = 0;
  for (int i = 0; i < wakeUps; ++i) {
    const bool d = pacer.elapse(wall, speed, kDt);
    if (dropped) *dropped = *dropped || d;
    for (int k = 0; k < maxSteps && pacer.due(kDt); ++k, ++steps) pacer.stepped(kDt);
  }
  return steps;
}

TEST(ViewerPacing, SimulatedTimeFollowsWallTimeTimesSpeed) {
  for (const double speed : {1.0, 0.25, 3.0}) {
    Pacer pacer;
    bool dropped = false;
    const long steps = run(pacer, 1.0 / 60, 600, speed, 1000, &dropped);
    EXPECT_NEAR(double(steps) * kDt, 10.0 * speed, kDt) << speed;
    EXPECT_FALSE(dropped) << speed;
  }
}

TEST(ViewerPacing, AVerySlowSpeedStillSteps) {
  Pacer pacer;
  const long steps = run(pacer, 0.01, 1000, 0.01, 10);  // 10 s wall at 0.01x: 0.1 s simulated
  EXPECT_NEAR(double(steps) * kDt, 0.1, kDt);
  EXPECT_NEAR(pacer.secondsUntilDue(kDt, 0.01), (kDt - pacer.debt()) / 0.01, 1e-12);
}

TEST(ViewerPacing, WhatCannotBeDoneIsDroppedAndReported) {
  Pacer pacer;
  bool dropped = false;
  // A simulation that manages one step per 20 ms wake-up: 0.25x real time.
  const long steps = run(pacer, 0.02, 100, 1.0, 1, &dropped);
  EXPECT_EQ(steps, 100);
  EXPECT_TRUE(dropped);
  EXPECT_LE(pacer.debt(), Pacer::kMaxLagSeconds + 1e-12) << "owed time is capped, not carried";
  // A long stall (a restart, a dragged window) owes at most the cap, not a burst of steps.
  EXPECT_TRUE(pacer.elapse(5.0, 1.0, kDt));
  EXPECT_DOUBLE_EQ(pacer.debt(), Pacer::kMaxLagSeconds);
}

TEST(ViewerPacing, MeterReportsThePaceOverHalfSecondWindows) {
  PaceMeter meter;
  EXPECT_DOUBLE_EQ(meter.factor(), 1);
  for (int i = 0; i < 4; ++i) meter.add(0.1, 0.04, true);
  EXPECT_DOUBLE_EQ(meter.factor(), 1) << "no complete window yet";
  meter.add(0.1, 0.04, false);
  EXPECT_NEAR(meter.factor(), 0.4, 1e-12);
  EXPECT_TRUE(meter.behind(1.0));  // "running at 0.4x real time"
  EXPECT_FALSE(meter.behind(0.4)) << "the speed asked for is reached";
  // A window without dropped time: slower than asked only because the user asked less.
  for (int i = 0; i < 5; ++i) meter.add(0.1, 0.04, false);
  EXPECT_FALSE(meter.behind(1.0));
  meter.reset();
  EXPECT_DOUBLE_EQ(meter.factor(), 1);
}

TEST(FrameTimeSummary, LeavesOutStartUpAndReportsMeanRateAndP95) {
  // A slow first frame (shader compilation), then 19 frames of 25 ms and one of 50 ms.
  std::vector<double> seconds{0.4};
  for (int i = 0; i < 19; ++i) seconds.push_back(0.025);
  seconds.push_back(0.050);
  const FrameTimeSummary s = summariseFrameTimes(seconds, 1);
  EXPECT_EQ(s.frames, 20);
  EXPECT_NEAR(s.meanMs, (19 * 25.0 + 50.0) / 20, 1e-9);
  EXPECT_NEAR(s.fps, 1000 / s.meanMs, 1e-9);
  EXPECT_NEAR(s.p95Ms, 25.0, 1e-9);  // the 19th of 20 sorted times
  seconds.push_back(0.050);            // two slow frames of 21: the 20th sorted is one of them
  EXPECT_NEAR(summariseFrameTimes(seconds, 1).p95Ms, 50.0, 1e-9);
}

TEST(FrameTimeSummary, KeepsEverythingWhenThereIsNothingAfterStartUp) {
  EXPECT_EQ(summariseFrameTimes({}, 1).frames, 0);
  const FrameTimeSummary one = summariseFrameTimes({0.02}, 1);
  EXPECT_EQ(one.frames, 1);
  EXPECT_NEAR(one.fps, 50.0, 1e-9);
}

}  // namespace
}  // namespace hs::viewer
