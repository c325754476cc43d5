// Before and after: the mean of the last complete beats (fewer when fewer exist, none without
// one), a restart moving the run going on to "before" with its label, its last beat's curve and
// its loop, and where the grey curve of the run before is laid under this run's beats.
#include <gtest/gtest.h>

#include <vector>

#include "viewer/plots/run_comparison.h"

namespace hs::viewer {
namespace {

using cardiac::Phase;
constexpr double kMl = 1e-6;

cardiac::BeatSummary beat(double edvMl, double esvMl, bool complete = true, double duration = 0.8) {
  cardiac::BeatSummary b;
  b.edv = edvMl * kMl, b.esv = esvMl * kMl, b.duration = duration, b.complete = complete;
  return b;
}
const VolumeScale kReal = volumeScaleFor(120 * kMl);

TEST(BeatMean, TheLastFiveCompleteBeats) {
  std::vector<cardiac::BeatSummary> beats;
  for (int k = 0; k < 7; ++k) beats.push_back(beat(120, 40 + 2 * k));  // ESV 40, 42, ... 52
  const std::optional<BeatMean> m = meanOfLastBeats(beats, 5, kReal);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->count, 5);
  EXPECT_NEAR(m->figures.esv, (44 + 46 + 48 + 50 + 52) / 5.0, 1e-9) << "the last five, not the first";
  EXPECT_NEAR(m->figures.strokeVolume, 120 - 48, 1e-9);
  EXPECT_NEAR(m->figures.heartRate, 75, 1e-9);
  EXPECT_TRUE(m->figures.complete);
}

TEST(BeatMean, FewerWhenFewerExistAndNoneWithoutABeat) {
  std::vector<cardiac::BeatSummary> beats = {beat(120, 50), beat(120, 60)};
  std::optional<BeatMean> m = meanOfLastBeats(beats, 5, kReal);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->count, 2);
  EXPECT_NEAR(m->figures.esv, 55, 1e-9);
  EXPECT_FALSE(meanOfLastBeats({}, 5, kReal)) << "no beat: no value, not a mean of 0";
  // A beat still in progress does not count.
  beats = {beat(120, 50, false)};
  EXPECT_FALSE(meanOfLastBeats(beats, 5, kReal));
}

TEST(BeatMean, SteadiesAnAlternatingRhythm) {
  // irregular's last beat alternates between an EF of about 40.6% and 53.97%.
  std::vector<cardiac::BeatSummary> beats;
  for (int k = 0; k < 6; ++k) beats.push_back(k % 2 ? beat(126, 74.844) : beat(126, 58.0));
  const std::optional<BeatMean> m = meanOfLastBeats(beats, 5, kReal);
  ASSERT_TRUE(m);
  const double a = 100 * (126 - 74.844) / 126, b = 100 * (126 - 58.0) / 126;
  EXPECT_NEAR(m->figures.ejectionFraction, (3 * a + 2 * b) / 5, 1e-9);
  EXPECT_GT(m->figures.ejectionFraction, a);
  EXPECT_LT(m->figures.ejectionFraction, b);
}

// A history of beats of 10 steps of 0.1 s: 4 systolic, 6 diastolic, volume by step.
PlotHistory beats(int count, double esvMl) {
  PlotHistory h(100);
  int step = 0;
  for (int k = 0; k < count; ++k)
    for (int i = 0; i < 10; ++i) {
      PumpSample s;
      s.time = 0.1 * ++step;
      s.phase = i < 4 ? Phase::Systole : Phase::Diastole;
      s.cavity = (i < 4 ? 120 - (120 - esvMl) * (i + 1) / 4 : esvMl + (120 - esvMl) * (i - 3) / 6) * kMl;
      h.push(s);
    }
  return h;
}

TEST(RunComparison, ARestartMovesTheRunToBefore) {
  RunComparison runs;
  runs.restart("normal", PlotHistory(), CirculationHistory());
  EXPECT_FALSE(runs.previous()) << "the first run has nothing before it";
  EXPECT_EQ(runs.current().label, "normal");
  const std::vector<cardiac::BeatSummary> done = {beat(120, 50), beat(120, 52), beat(120, 54)};
  runs.update(done, kReal, true);
  const PlotHistory history = beats(4, 50);
  runs.restart("normal, region applied", history, CirculationHistory());
  ASSERT_TRUE(runs.previous());
  EXPECT_EQ(runs.previous()->label, "normal");
  EXPECT_EQ(runs.current().label, "normal, region applied");
  EXPECT_TRUE(runs.current().beats.empty()) << "the new run starts with no beat";
  const std::optional<BeatMean> before = runs.previous()->mean();
  ASSERT_TRUE(before);
  EXPECT_EQ(before->count, 3);
  EXPECT_NEAR(before->figures.esv, 52, 1e-9);
  // The last complete beat's curve, its times from the beat's start.
  const std::vector<PumpSample>& curve = runs.previous()->beatCurve;
  ASSERT_EQ(curve.size(), 10u);
  EXPECT_NEAR(curve.front().time, 0.1, 1e-9);
  EXPECT_NEAR(curve.back().time, 1.0, 1e-9);
  EXPECT_NEAR(curve[3].cavity / kMl, 50, 1e-9) << "ESV at the end of systole";
  EXPECT_FALSE(runs.previousCurve().empty());

  // A run restarted before its first beat ended has nothing to compare: "before" stays.
  runs.update({}, kReal, true);
  runs.restart("normal, Reset", beats(0, 50), CirculationHistory());
  ASSERT_TRUE(runs.previous());
  EXPECT_EQ(runs.previous()->label, "normal");
  EXPECT_EQ(runs.current().label, "normal, Reset");
  // The next run with beats replaces it.
  runs.update(std::vector{beat(120, 70)}, kReal, true);
  runs.restart("anterior-infarct", beats(3, 70), CirculationHistory());
  EXPECT_EQ(runs.previous()->label, "normal, Reset");
  EXPECT_NEAR(runs.previous()->mean()->figures.esv, 70, 1e-9);
}

// The pump panel's share bar: the run's last flow components go to "before" with it.
TEST(RunComparison, TheFlowComponentsGoToBeforeWithTheRun) {
  RunComparison runs;
  runs.restart("normal", PlotHistory(), CirculationHistory());
  cardiac::FlowComponents shares;
  shares.direct = 0.4, shares.retainedInflow = 0.2, shares.delayedEjection = 0.2, shares.residual = 0.2;
  shares.particles = 100;
  runs.update(std::vector{beat(120, 50)}, kReal, true, shares);
  EXPECT_TRUE(runs.current().flowComponents);
  runs.restart("dilated-cardiomyopathy", beats(2, 50), CirculationHistory());
  ASSERT_TRUE(runs.previous() && runs.previous()->flowComponents);
  EXPECT_DOUBLE_EQ(runs.previous()->flowComponents->direct, 0.4);
  EXPECT_FALSE(runs.current().flowComponents) << "the new run has no beat yet";
}

TEST(RunComparison, RunsAtAnotherScaleAreNotDrawnOnTheSameAxes) {
  RunComparison runs;
  runs.update(std::vector{beat(120, 50)}, kReal, true);
  runs.restart("paper-chamber-beating", beats(3, 50), CirculationHistory());
  runs.update({}, volumeScaleFor(7.4), false);
  EXPECT_TRUE(runs.previous());
  EXPECT_FALSE(runs.comparable());
  EXPECT_TRUE(runs.previousCurve().empty());
}

TEST(RunComparison, TheLastWholeBeatNeedsItsStartInTheHistory) {
  EXPECT_TRUE(lastBeatCurve(beats(1, 50)).empty()) << "one beat, not ended";
  EXPECT_EQ(lastBeatCurve(beats(2, 50)).size(), 10u);
  const std::vector<double> onsets = beatOnsets(beats(3, 50));
  ASSERT_EQ(onsets.size(), 3u);
  EXPECT_NEAR(onsets[0], 0.0, 1e-9);
  EXPECT_NEAR(onsets[1], 1.0, 1e-9);
  EXPECT_NEAR(onsets[2], 2.0, 1e-9);
}

TEST(Overlay, OneBeatUnderEachOfThisRunsBeats) {
  const std::vector<double> onsets = {0.0, 0.8, 1.7};
  const std::vector<OverlaySpan> spans = overlaySpans(onsets, 1.0, 0.5, 2.5);
  ASSERT_EQ(spans.size(), 3u);
  EXPECT_DOUBLE_EQ(spans[0].end, 0.8) << "cut at the next beat's start";
  EXPECT_DOUBLE_EQ(spans[1].end, 1.7);
  EXPECT_DOUBLE_EQ(spans[2].start, 1.7);
  EXPECT_DOUBLE_EQ(spans[2].end, 2.7) << "the beat in progress: the whole beat before";
  // Only those in the window.
  EXPECT_EQ(overlaySpans(onsets, 1.0, 1.75, 2.5).size(), 1u);
  // The cycle off: one beat after another from t = 0.
  const std::vector<OverlaySpan> resting = overlaySpans({}, 0.8, 1.0, 3.0);
  ASSERT_EQ(resting.size(), 3u);
  EXPECT_DOUBLE_EQ(resting[0].start, 0.8);
  EXPECT_DOUBLE_EQ(resting[2].start, 2.4);
  EXPECT_TRUE(overlaySpans(onsets, 0, 0, 1).empty());
}

}  // namespace
}  // namespace hs::viewer
