// Figures of settled beats: after a restart with the peripheral resistance doubled the lumped
// circulation takes several beats to find its balance (EF 41% in the first beat, 48% once
// settled). The pump panel's `now` averages only the beats from the first whose EDV and ESV are
// both within 1% of the beat before's, so it agrees with the last beat within 2%; an irregular
// rhythm counts its beats from three arterial time constants on.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <thread>

#include "io/scenario/scenario_file.h"
#include "runner_wait.h"
#include "viewer/app/simulation_runner.h"
#include "viewer/plots/run_comparison.h"

namespace hs::viewer {
namespace {

using test_support::waitFor;

cardiac::BeatSummary beat(int index, double startTime, double edvMl, double esvMl) {
  cardiac::BeatSummary b;
  b.index = index;
  b.startTime = startTime;
  b.duration = 0.8;
  b.complete = true;
  b.edv = edvMl * 1e-6;
  b.esv = esvMl * 1e-6;
  return b;
}

TEST(Settling, ARegularBeatSettlesWhenItsVolumesAreWithinOnePercentOfTheBeatBefore) {
  const SettlingRule rule;
  EXPECT_FALSE(beatSettles(rule, beat(1, 0, 127.3, 75.1), std::nullopt)) << "the first beat has none before it";
  EXPECT_FALSE(beatSettles(rule, beat(6, 4.2, 122.9, 65.3), beat(5, 3.3, 123.2, 66.0))) << "ESV 1.02% apart";
  EXPECT_TRUE(beatSettles(rule, beat(7, 5.0, 122.8, 64.8), beat(6, 4.2, 122.9, 65.3)));
  SettlingRule irregular;
  irregular.irregular = true;
  irregular.settledAfter = 4.4;
  EXPECT_FALSE(beatSettles(irregular, beat(5, 3.8, 115.0, 41.5), beat(4, 2.75, 98.2, 42.8)));
  EXPECT_TRUE(beatSettles(irregular, beat(6, 4.5, 102.1, 42.3), beat(5, 3.8, 115.0, 41.5)))
      << "an irregular rhythm's beats differ by design: it settles by time";
}

TEST(Settling, AfterTheResistanceIsDoubledNowLeavesOutTheFirstBeatsAndAgreesWithTheLast) {
  cardiac::Scenario s = io::loadScenario("normal");
  s.blood.enabled = false;  // the lumped heart and its wall: the figures come from them
  s.circulation.lumpedParameters.peripheralResistance *= 2;
  const SettlingRule rule = settlingRuleFor(s);
  EXPECT_FALSE(rule.irregular);
  EXPECT_TRUE(settlingRuleFor(io::loadScenario("irregular")).irregular);
  SimulationRunner runner(1);
  runner.start(s);
  runner.access([](SimulationState& state) { state.speed = 8; });
  ASSERT_TRUE(waitFor(runner, [](SimulationState& state) {
    return state.pump && state.pump->readings().beatsCompleted >= 12;
  }));
  runner.access([](SimulationState& state) { state.playing = false; });
  BeatReadings readings;
  runner.access([&](SimulationState& state) { readings = state.pump->readings(); });
  ASSERT_TRUE(readings.settled);
  ASSERT_FALSE(readings.recent.empty());
  EXPECT_GE(readings.recent.front().index, 4) << "the first beats, still settling, are left out";
  const VolumeScale scale = volumeScaleFor(readings.last->edv);
  const std::optional<BeatMean> now = meanOfLastBeats(readings.recent, RunRecord::kMeanBeats, scale);
  ASSERT_TRUE(now);
  const double last = clinicalFigures(*readings.last, scale).ejectionFraction;
  EXPECT_NEAR(now->figures.ejectionFraction / last, 1.0, 0.02) << now->figures.ejectionFraction << " against " << last;
}

}  // namespace
}  // namespace hs::viewer
