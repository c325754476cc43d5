// The cycle state machine against thesis Algorithm 2 / Fig. 4.6, step by step, and the
// physiological and irregular timings.
#include <gtest/gtest.h>

#include "cardiac/circulation/beat_clock.h"
#include "cardiac/circulation/beat_metrics.h"

namespace hs::cardiac {
namespace {

constexpr Real kDt = Real(0.005);

BeatClockSettings thesis() {
  BeatClockSettings s;
  s.systoleSteps = 8;
  s.diastoleSteps = 8;
  s.displacePerStep = Real(0.08);
  return s;
}

TEST(BeatClock, FollowsAlgorithm2StepByStep) {
  BeatClock clock(thesis());
  // Algorithm 2 line 3: steps = 0, state = Systole.
  EXPECT_EQ(clock.phase(), Phase::Systole);
  EXPECT_EQ(clock.stepsInPhase(), 0);
  for (int beat = 0; beat < 3; ++beat) {
    for (int i = 1; i <= 8; ++i) {
      ASSERT_EQ(clock.phase(), Phase::Systole) << "beat " << beat << " step " << i;
      // Lines 7-8: move by BEATING_DISPLACE, steps++.
      EXPECT_NEAR(double(clock.advance(kDt)), 0.08, 1e-7);
      // Lines 9-11: when steps >= BEATING_DURATION, steps = 0 and the state switches.
      if (i < 8) {
        EXPECT_EQ(clock.stepsInPhase(), i);
      }
    }
    EXPECT_EQ(clock.phase(), Phase::Diastole);
    EXPECT_EQ(clock.stepsInPhase(), 0);
    EXPECT_EQ(clock.systolesCompleted(), beat + 1);
    // Fig. 4.6: diastole lasts BEATING_DURATION steps without moving, then systole again.
    for (int i = 1; i <= 8; ++i) {
      ASSERT_EQ(clock.phase(), Phase::Diastole);
      EXPECT_EQ(clock.advance(kDt), 0.0f);
    }
    EXPECT_EQ(clock.phase(), Phase::Systole);
  }
}

TEST(BeatClock, StopsAfterTheRequestedBeatsAndRests) {
  BeatClockSettings s = thesis();
  s.beats = 2;
  BeatClock clock(s);
  Real total = 0;
  for (int i = 0; i < 200; ++i) total += clock.advance(kDt);
  EXPECT_EQ(clock.phase(), Phase::Rest);
  EXPECT_EQ(clock.systolesCompleted(), 2);
  EXPECT_NEAR(total, 2 * 8 * 0.08, 1e-5);
}

TEST(BeatClock, PhysiologicalSystoleIsSmoothAndSumsToTheContraction) {
  BeatClockSettings s;
  s.physiological = true;
  s.period = Real(60.0 / 75.0);  // 75 bpm: 0.8 s
  s.systolicFraction = Real(0.375);  // 0.3 s of systole
  s.contraction = Real(0.01);
  const Real dt = Real(0.001);
  BeatClock clock(s);
  std::vector<Real> perStep;
  while (clock.phase() == Phase::Systole) perStep.push_back(clock.advance(dt));
  ASSERT_EQ(perStep.size(), 300u);
  Real total = 0;
  for (Real d : perStep) total += d;
  EXPECT_NEAR(total, 0.01, 1e-6);
  // Smooth: starts and ends near zero speed, peaks mid-systole, no jumps.
  EXPECT_LT(perStep.front(), Real(1e-3) * perStep[150]);
  EXPECT_LT(perStep.back(), Real(1e-3) * perStep[150]);
  for (std::size_t i = 1; i < perStep.size(); ++i)
    EXPECT_LT(std::abs(perStep[i] - perStep[i - 1]), Real(0.03) * perStep[150]);
  int diastole = 0;
  while (clock.phase() == Phase::Diastole) {
    EXPECT_EQ(clock.advance(dt), 0.0f);
    ++diastole;
  }
  EXPECT_EQ(diastole, 500);
}

TEST(BeatClock, IrregularDiastolesAreShorterAndVary) {
  BeatClockSettings s = thesis();
  s.systoleSteps = 20;
  s.diastoleSteps = 20;
  s.irregularity = Real(0.6);
  auto diastoleLengths = [&s] {
    BeatClock clock(s);
    std::vector<int> lengths;
    for (int i = 0; i < 2000; ++i) {
      const Phase before = clock.phase();
      clock.advance(kDt);
      if (before == Phase::Systole && clock.phase() == Phase::Diastole) lengths.push_back(clock.diastoleLength(kDt));
    }
    return lengths;
  };
  const std::vector<int> lengths = diastoleLengths();
  ASSERT_GT(lengths.size(), 20u);
  int shorter = 0;
  for (int l : lengths) {
    EXPECT_LE(l, 20);
    EXPECT_GE(l, 8);  // at most 60% cut
    if (l < 20) ++shorter;
  }
  EXPECT_GT(shorter, int(lengths.size()) / 2);
  EXPECT_NE(*std::min_element(lengths.begin(), lengths.end()), *std::max_element(lengths.begin(), lengths.end()));
  // Same seed, same rhythm.
  const std::vector<int> repeat = diastoleLengths();
  EXPECT_EQ(lengths, repeat);
}

TEST(BeatClock, DelayedStartShiftsThePhase) {
  BeatClockSettings s = thesis();
  s.startDelay = Real(0.5);  // half of a 16-step cycle: 8 relaxed steps
  BeatClock clock(s);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(clock.advance(kDt), 0.0f);
  EXPECT_EQ(clock.phase(), Phase::Systole);
  EXPECT_GT(clock.advance(kDt), 0.0f);
}

TEST(BeatTracker, MeasuresEdvEsvAndEjectionFraction) {
  BeatTracker tracker(100);
  // Beat 1: contracts to 40 then refills to 100. Beat 2: 100 -> 70.
  const double volumes[] = {80, 60, 40, 70, 100, 85, 70, 90};
  const Phase phases[] = {Phase::Systole, Phase::Systole, Phase::Systole, Phase::Diastole,
                          Phase::Diastole, Phase::Systole, Phase::Systole, Phase::Diastole};
  for (int i = 0; i < 8; ++i) tracker.record(i * 0.1, phases[i], volumes[i]);
  tracker.finish();
  ASSERT_EQ(tracker.beats().size(), 2u);
  EXPECT_DOUBLE_EQ(tracker.beats()[0].edv, 100);
  EXPECT_DOUBLE_EQ(tracker.beats()[0].esv, 40);
  EXPECT_DOUBLE_EQ(tracker.beats()[0].ejectionFraction(), 0.6);
  EXPECT_DOUBLE_EQ(tracker.beats()[1].edv, 100);
  EXPECT_DOUBLE_EQ(tracker.beats()[1].esv, 70);
  EXPECT_NEAR(tracker.meanEjectionFraction(), 0.45, 1e-12);
}

// EDV is the volume when systole starts, not the largest: a wall that overshoots its rest
// volume while refilling does not inflate the next beat's EF. A run that stops mid-systole
// reports no half beat.
TEST(BeatTracker, EdvIsTheVolumeAtSystoleOnsetAndHalfBeatsDoNotCount) {
  BeatTracker tracker(100);
  const double volumes[] = {70, 40, 90, 110, 105, 80};
  const Phase phases[] = {Phase::Systole, Phase::Systole, Phase::Diastole, Phase::Diastole, Phase::Diastole,
                          Phase::Systole};
  for (int i = 0; i < 6; ++i) tracker.record(i * 0.1, phases[i], volumes[i]);
  tracker.finish();
  ASSERT_EQ(tracker.beats().size(), 1u);
  EXPECT_DOUBLE_EQ(tracker.beats()[0].edv, 100);
  EXPECT_DOUBLE_EQ(tracker.beats()[0].esv, 40);
  EXPECT_DOUBLE_EQ(tracker.beats()[0].ejectionFraction(), 0.6);
}

// Cardiac output, regurgitation and the means over complete beats after the first: three
// beats of 0.4 s (2 steps of systole, 2 of diastole, dt 0.1 s), each ejecting 60 of 100 and
// refilling. Mitral flow that goes back in systole is regurgitation; aortic flow that crosses
// forward and back in systole (an open valve) is not.
TEST(BeatTracker, CardiacOutputRegurgitationAndMeansOverCompleteBeats) {
  BeatTracker tracker(100, 0.1);
  const Phase phases[] = {Phase::Systole, Phase::Systole, Phase::Diastole, Phase::Diastole};
  const double volumes[] = {70, 40, 70, 100};
  for (int beat = 0; beat < 3; ++beat) {
    for (int k = 0; k < 4; ++k) {
      ValveFlows f;
      if (phases[k] == Phase::Systole) {
        f.aorticForward = 31, f.aorticBackward = 1;  // net 30 out per systolic step
        f.mitralBackward = beat == 2 ? 2.0 : 0.0;    // the third beat leaks back through the mitral
      } else {
        f.mitralForward = 30;
        f.aorticForward = 0.5, f.aorticBackward = 0.5;  // to and fro at the shut aortic plane
      }
      tracker.record(0.4 * beat + 0.1 * k, phases[k], volumes[k], f);
    }
  }
  tracker.record(1.2, Phase::Systole, 70);  // the next systole closes the third beat
  tracker.finish();
  ASSERT_EQ(tracker.beats().size(), 3u);  // the fourth beat has no end of systole: not counted
  for (const BeatSummary& b : tracker.beats()) {
    EXPECT_TRUE(b.complete);
    EXPECT_NEAR(b.duration, 0.4, 1e-12);
    EXPECT_NEAR(b.strokeVolume(), 60, 1e-12);
    EXPECT_NEAR(b.cardiacOutput(), 150, 1e-9);  // 60 per 0.4 s
  }
  EXPECT_NEAR(tracker.beats()[0].regurgitantVolume(), 0, 1e-12);
  EXPECT_NEAR(tracker.beats()[2].regurgitantVolume(), 4, 1e-12);  // 2 per systolic step
  const BeatMeans m = tracker.means();
  EXPECT_EQ(m.count, 2);  // beats 2 and 3
  EXPECT_NEAR(m.strokeVolume, 60, 1e-12);
  EXPECT_NEAR(m.ejectionFraction, 0.6, 1e-12);
  EXPECT_NEAR(m.regurgitantVolume, 2, 1e-12);
  EXPECT_NEAR(m.aorticNet, 60, 1e-12);
}

}  // namespace
}  // namespace hs::cardiac
