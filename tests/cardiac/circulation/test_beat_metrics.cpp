// BeatTracker on synthetic cavity-volume curves whose beats are known by construction: where
// each beat starts and ends, its EDV and ESV, the stroke volume, EF and cardiac output they
// imply (CO = SV x HR), the regurgitant volume of valves that leak, and the display units.
#include <gtest/gtest.h>

#include <vector>

#include "cardiac/circulation/beat_metrics.h"

namespace hs::cardiac {
namespace {

constexpr double kDt = 0.01;            // s per step
constexpr int kStepsPerBeat = 100;      // 1 s per beat: 60 bpm
constexpr int kSystoleSteps = 30;       // 0.3 s of systole, then 0.7 s of diastole
constexpr double kEdv = 120e-6;         // m^3 (120 mL, an adult LV)
constexpr double kMl = 1e-6;            // m^3 per mL

// One beat of the curve: volume falls linearly from kEdv to `esv` over the systole and rises
// back to kEdv over the diastole. `step` counts from the beat's first step (0-based); the
// volume is the one at the end of that step.
double volumeAfter(int step, double esv) {
  const int done = step + 1;
  if (done <= kSystoleSteps) return kEdv - (kEdv - esv) * done / kSystoleSteps;
  return esv + (kEdv - esv) * (done - kSystoleSteps) / (kStepsPerBeat - kSystoleSteps);
}

Phase phaseOf(int step) { return step < kSystoleSteps ? Phase::Systole : Phase::Diastole; }

// Records `steps` steps of consecutive beats with the given end-systolic volumes (one per
// beat, the last repeated if the run is longer); every step also gets `flows(phase)`.
template <class Flows>
void run(BeatTracker& tracker, const std::vector<double>& esv, int steps, Flows flows) {
  for (int n = 0; n < steps; ++n) {
    const std::size_t beat = std::min(std::size_t(n / kStepsPerBeat), esv.size() - 1);
    const int inBeat = n % kStepsPerBeat;
    tracker.record(n * kDt, phaseOf(inBeat), volumeAfter(inBeat, esv[beat]), flows(phaseOf(inBeat)));
  }
}

void run(BeatTracker& tracker, const std::vector<double>& esv, int steps) {
  run(tracker, esv, steps, [](Phase) { return ValveFlows{}; });
}

TEST(BeatTracker, FindsOneBeatPerSystoleStart) {
  BeatTracker tracker(kEdv, kDt);
  run(tracker, {50 * kMl}, 3 * kStepsPerBeat + 50);  // stops in the fourth beat's diastole
  tracker.finish();
  const std::vector<BeatSummary>& beats = tracker.beats();
  ASSERT_EQ(beats.size(), 4u);
  for (std::size_t b = 0; b < beats.size(); ++b) {
    EXPECT_EQ(beats[b].index, int(b) + 1);
    EXPECT_NEAR(beats[b].startTime, double(b), 1e-9) << "beat " << b + 1;
  }
  // The first three end where the next systole starts; the fourth is cut by the end of the run.
  for (std::size_t b = 0; b < 3; ++b) {
    EXPECT_TRUE(beats[b].complete);
    EXPECT_NEAR(beats[b].duration, 1.0, 1e-9);
  }
  EXPECT_FALSE(beats[3].complete);
  EXPECT_NEAR(beats[3].duration, 0.5, 1e-9);
}

TEST(BeatTracker, EdvIsTheVolumeBeforeSystoleAndEsvTheSmallest) {
  BeatTracker tracker(kEdv, kDt);
  run(tracker, {50 * kMl, 40 * kMl, 60 * kMl}, 3 * kStepsPerBeat);
  tracker.finish();
  const std::vector<BeatSummary>& beats = tracker.beats();
  ASSERT_EQ(beats.size(), 3u);
  const double esv[] = {50 * kMl, 40 * kMl, 60 * kMl};
  for (std::size_t b = 0; b < 3; ++b) {
    // The first systolic step already ejects, so EDV must come from before it.
    EXPECT_NEAR(beats[b].edv, kEdv, 1e-12) << "beat " << b + 1;
    EXPECT_NEAR(beats[b].esv, esv[b], 1e-12) << "beat " << b + 1;
    EXPECT_NEAR(beats[b].strokeVolume(), kEdv - esv[b], 1e-12);
    EXPECT_NEAR(beats[b].ejectionFraction(), (kEdv - esv[b]) / kEdv, 1e-9);
  }
  // 120 mL -> 50 mL: SV 70 mL, EF 58%.
  EXPECT_NEAR(beats[0].ejectionFraction(), 70.0 / 120.0, 1e-9);
}

TEST(BeatTracker, CardiacOutputIsStrokeVolumeTimesHeartRate) {
  BeatTracker tracker(kEdv, kDt);
  run(tracker, {50 * kMl}, 3 * kStepsPerBeat);
  tracker.finish();
  ASSERT_FALSE(tracker.beats().empty());
  // SV 70 mL at 60 bpm: 4.2 L/min.
  const BeatSummary& beat = tracker.beats().front();
  const VolumeScale clinical = volumeScaleFor(kEdv);
  EXPECT_NEAR(beat.cardiacOutput() * clinical.output, 70.0 * 60 / 1000, 1e-6);
  EXPECT_STREQ(clinical.outputUnit, "L/min");
}

TEST(BeatTracker, MeansSkipTheFirstBeatAndIncompleteOnes) {
  BeatTracker tracker(kEdv, kDt);
  // Beat 1 (from the initial state) and beat 4 (cut off) must not count.
  run(tracker, {10 * kMl, 40 * kMl, 60 * kMl, 100 * kMl}, 3 * kStepsPerBeat + 60);
  tracker.finish();
  ASSERT_EQ(tracker.beats().size(), 4u);
  const BeatMeans means = tracker.means();
  EXPECT_EQ(means.count, 2);
  EXPECT_NEAR(means.edv, kEdv, 1e-12);
  EXPECT_NEAR(means.esv, 50 * kMl, 1e-12);
  EXPECT_NEAR(means.strokeVolume, 70 * kMl, 1e-12);
  EXPECT_NEAR(means.ejectionFraction, (80.0 / 120.0 + 60.0 / 120.0) / 2, 1e-9);
  EXPECT_NEAR(means.cardiacOutput, 70 * kMl / 1.0, 1e-9);
  // meanEjectionFraction is over every recorded beat, the first and the cut one included.
  const double all = (110.0 + 80.0 + 60.0 + 20.0) / 120.0 / 4;
  EXPECT_NEAR(tracker.meanEjectionFraction(), all, 1e-9);
}

TEST(BeatTracker, RunStoppedInSystoleReportsNoHalfBeat) {
  BeatTracker tracker(kEdv, kDt);
  run(tracker, {50 * kMl}, kStepsPerBeat + kSystoleSteps / 2);
  tracker.finish();
  ASSERT_EQ(tracker.beats().size(), 1u);
  EXPECT_TRUE(tracker.beats()[0].complete);
}

TEST(BeatTracker, NoCompleteBeatGivesNoFigures) {
  BeatTracker resting(kEdv, kDt);
  for (int n = 0; n < 200; ++n) resting.record(n * kDt, Phase::Rest, kEdv);
  resting.finish();
  EXPECT_TRUE(resting.beats().empty());
  EXPECT_EQ(resting.means().count, 0);
  EXPECT_EQ(resting.means().ejectionFraction, 0);
  EXPECT_EQ(resting.meanEjectionFraction(), 0);

  // One beat only, the one from the initial state: recorded, but no means.
  BeatTracker single(kEdv, kDt);
  run(single, {50 * kMl}, kStepsPerBeat);
  single.finish();
  EXPECT_EQ(single.beats().size(), 1u);
  EXPECT_EQ(single.means().count, 0);
  EXPECT_EQ(single.means().strokeVolume, 0);
}

TEST(BeatTracker, RegurgitationIsBackflowThroughAShutValve) {
  // Per step: in systole the mitral valve leaks 1 mL back and 0.2 mL forward; in diastole the
  // aortic valve leaks 0.5 mL back, and the mitral valve fills 2 mL.
  const auto leaky = [](Phase phase) {
    ValveFlows f;
    if (phase == Phase::Systole) {
      f.mitralBackward = 1 * kMl, f.mitralForward = 0.2 * kMl, f.aorticForward = 3 * kMl;
    } else {
      f.aorticBackward = 0.5 * kMl, f.mitralForward = 2 * kMl;
    }
    return f;
  };
  BeatTracker tracker(kEdv, kDt);
  run(tracker, {50 * kMl}, 3 * kStepsPerBeat, leaky);
  tracker.finish();
  ASSERT_EQ(tracker.beats().size(), 3u);
  const BeatSummary& beat = tracker.beats()[0];
  const int diastole = kStepsPerBeat - kSystoleSteps;
  EXPECT_NEAR(beat.mitralNetInSystole, -0.8 * kMl * kSystoleSteps, 1e-12);
  EXPECT_NEAR(beat.aorticNetInDiastole, -0.5 * kMl * diastole, 1e-12);
  EXPECT_NEAR(beat.regurgitantVolume(), (0.8 * kSystoleSteps + 0.5 * diastole) * kMl, 1e-12);
  EXPECT_NEAR(beat.flows.aorticForward, 3 * kMl * kSystoleSteps, 1e-12);
  EXPECT_NEAR(beat.flows.mitralForward, (0.2 * kSystoleSteps + 2.0 * diastole) * kMl, 1e-12);
  // The means count beat 2 alone (beat 1 starts from the initial state, beat 3 is cut off).
  EXPECT_EQ(tracker.means().count, 1);
  EXPECT_NEAR(tracker.means().aorticNet, (3.0 * kSystoleSteps - 0.5 * diastole) * kMl, 1e-12);
}

TEST(BeatTracker, FlowToAndFroThroughAShutValveIsNoRegurgitation) {
  // Particles crossing the valve plane back and forth count both ways and cancel; net forward
  // flow through a valve that should be shut is not a negative regurgitation either.
  const auto toAndFro = [](Phase phase) {
    ValveFlows f;
    if (phase == Phase::Systole) f.mitralForward = f.mitralBackward = 1 * kMl;
    else f.aorticForward = 0.3 * kMl;
    return f;
  };
  BeatTracker tracker(kEdv, kDt);
  run(tracker, {50 * kMl}, 2 * kStepsPerBeat, toAndFro);
  tracker.finish();
  ASSERT_FALSE(tracker.beats().empty());
  EXPECT_EQ(tracker.beats()[0].regurgitantVolume(), 0);
}

TEST(VolumeScale, ClinicalUnitsForARealHeartAndCubicMetresAtThesisScale) {
  const VolumeScale heart = volumeScaleFor(kEdv);
  EXPECT_FALSE(heart.thesis);
  EXPECT_STREQ(heart.volumeUnit, "mL");
  EXPECT_NEAR(kEdv * heart.volume, 120, 1e-9);
  EXPECT_NEAR(1e-3 * heart.output, 60, 1e-9);  // 1 L/s = 60 L/min
  // The thesis's cavity is metres across: ~7 m^3.
  const VolumeScale thesis = volumeScaleFor(7.0);
  EXPECT_TRUE(thesis.thesis);
  EXPECT_STREQ(thesis.volumeUnit, "m^3");
  EXPECT_EQ(7.0 * thesis.volume, 7.0);
  EXPECT_STREQ(thesis.outputUnit, "m^3/min");
  EXPECT_EQ(thesis.output, 60.0);
  // The threshold: 10 L and more is not a heart.
  EXPECT_TRUE(volumeScaleFor(kThesisScaleVolume).thesis);
  EXPECT_FALSE(volumeScaleFor(0.5 * kThesisScaleVolume).thesis);
}

}  // namespace
}  // namespace hs::cardiac
