// The viewer's pump readout on a synthetic sequence of steps: the figures of the beat in
// progress and of the last complete beat, in clinical units, agree with a plain
// cardiac::BeatTracker fed the same steps (as `heartsim run` feeds it) and with the numbers
// worked out by hand.
#include <gtest/gtest.h>

#include <vector>

#include "cardiac/circulation/beat_metrics.h"
#include "viewer/plots/pump_readout.h"

namespace hs::viewer {
namespace {

using cardiac::Phase;

constexpr double kMl = 1e-6;  // m^3
constexpr double kDt = 0.1;   // s: 4 systolic + 6 diastolic steps = a beat of 1 s, 60 bpm

struct Step {
  Phase phase;
  double volumeMl;  // at the end of the step
  cardiac::ValveFlows flows;
};

// One beat from an EDV of 120 mL: systole ejects 70 mL through the aortic valve while 2 mL go
// back through the mitral valve (mitral regurgitation); diastole refills through the mitral.
std::vector<Step> beat(double esvMl) {
  const double sv = 120 - esvMl;
  std::vector<Step> steps;
  for (int i = 1; i <= 4; ++i) {
    cardiac::ValveFlows f;
    f.aorticForward = sv / 4 * kMl;
    if (i == 2) f.mitralBackward = 2 * kMl;
    steps.push_back({Phase::Systole, 120 - sv * i / 4, f});
  }
  for (int i = 1; i <= 6; ++i) {
    cardiac::ValveFlows f;
    f.mitralForward = sv / 6 * kMl;
    steps.push_back({Phase::Diastole, esvMl + sv * i / 6, f});
  }
  return steps;
}

// Feeds both the readout and a reference tracker; returns the time reached.
double feed(const std::vector<Step>& steps, double time, PumpReadout& readout,
            cardiac::BeatTracker& reference) {
  for (const Step& s : steps) {
    readout.record(time, s.phase, s.volumeMl * kMl, s.flows);
    reference.record(time, s.phase, s.volumeMl * kMl, s.flows);
    time += kDt;
  }
  return time;
}

TEST(PumpReadout, LastCompleteBeatInClinicalUnits) {
  PumpReadout readout(120 * kMl, kDt);
  cardiac::BeatTracker reference(120 * kMl, kDt);
  double t = feed(beat(50), 0, readout, reference);
  EXPECT_FALSE(readout.readings().last) << "a beat is complete only when the next systole starts";
  t = feed({beat(40).front()}, t, readout, reference);
  const BeatReadings r = readout.readings();
  ASSERT_TRUE(r.last);
  EXPECT_EQ(r.beatsCompleted, 1);
  EXPECT_EQ(r.last->index, 1);
  EXPECT_TRUE(r.last->complete);

  const ClinicalFigures f = clinicalFigures(*r.last, volumeScaleFor(120 * kMl));
  EXPECT_NEAR(f.edv, 120, 1e-9);
  EXPECT_NEAR(f.esv, 50, 1e-9);
  EXPECT_NEAR(f.strokeVolume, 70, 1e-9);
  EXPECT_NEAR(f.ejectionFraction, 100.0 * 70 / 120, 1e-9);
  EXPECT_NEAR(f.heartRate, 60, 1e-9);              // a beat of 10 steps of 0.1 s
  EXPECT_NEAR(f.cardiacOutput, 70e-3 * 60, 1e-9);  // 70 mL x 60 bpm = 4.2 L/min
  EXPECT_NEAR(f.regurgitantVolume, 2, 1e-9);       // back through the mitral valve in systole

  // The same beat as the tracker `heartsim run` keeps for the whole run.
  ASSERT_GE(reference.beats().size(), 1u);
  const cardiac::BeatSummary& b = reference.beats().front();
  EXPECT_DOUBLE_EQ(r.last->edv, b.edv);
  EXPECT_DOUBLE_EQ(r.last->esv, b.esv);
  EXPECT_DOUBLE_EQ(r.last->duration, b.duration);
  EXPECT_DOUBLE_EQ(r.last->regurgitantVolume(), b.regurgitantVolume());
}

TEST(PumpReadout, BeatInProgressIsShownOnceItsSystoleHasEnded) {
  PumpReadout readout(120 * kMl, kDt);
  cardiac::BeatTracker reference(120 * kMl, kDt);
  const std::vector<Step> second = beat(40);
  double t = feed(beat(50), 0, readout, reference);
  t = feed({second.begin(), second.begin() + 3}, t, readout, reference);  // mid-systole
  BeatReadings r = readout.readings();
  EXPECT_TRUE(r.beating);
  EXPECT_FALSE(r.current) << "ESV is not known before systole ends";
  EXPECT_NEAR(r.currentEdv / kMl, 120, 1e-9);
  EXPECT_NEAR(r.currentStart, 1.0, 1e-9);

  t = feed({second.begin() + 3, second.begin() + 6}, t, readout, reference);  // into diastole
  r = readout.readings();
  ASSERT_TRUE(r.current);
  EXPECT_EQ(r.current->index, 2);
  EXPECT_FALSE(r.current->complete);
  const ClinicalFigures f = clinicalFigures(*r.current, volumeScaleFor(120 * kMl));
  EXPECT_NEAR(f.edv, 120, 1e-9);
  EXPECT_NEAR(f.esv, 40, 1e-9);
  EXPECT_NEAR(f.ejectionFraction, 100.0 * 80 / 120, 1e-9);
  EXPECT_EQ(f.heartRate, 0) << "an unfinished beat has no length yet";
  EXPECT_EQ(f.cardiacOutput, 0);
  // The last complete beat is still the first one.
  ASSERT_TRUE(r.last);
  EXPECT_NEAR(r.last->esv / kMl, 50, 1e-9);
}

TEST(PumpReadout, ManyBeatsKeepCountingLikeTheRunsTracker) {
  PumpReadout readout(120 * kMl, kDt);
  cardiac::BeatTracker reference(120 * kMl, kDt);
  double t = 0;
  for (int k = 0; k < 6; ++k) t = feed(beat(30 + 5 * k), t, readout, reference);
  t = feed({beat(50).front()}, t, readout, reference);
  const BeatReadings r = readout.readings();
  ASSERT_EQ(reference.beats().size(), 6u);
  EXPECT_EQ(r.beatsCompleted, 6);
  ASSERT_TRUE(r.last);
  EXPECT_DOUBLE_EQ(r.last->esv, reference.beats().back().esv);
  EXPECT_DOUBLE_EQ(r.last->startTime, reference.beats().back().startTime);
  EXPECT_NEAR(r.last->esv / kMl, 55, 1e-9);
}

TEST(PumpReadout, NoBeatWhileTheWallRests) {
  PumpReadout readout(120 * kMl, kDt);
  for (int i = 0; i < 20; ++i) readout.record(i * kDt, Phase::Rest, 120 * kMl, {});
  const BeatReadings r = readout.readings();
  EXPECT_FALSE(r.beating);
  EXPECT_FALSE(r.current);
  EXPECT_FALSE(r.last);
}

TEST(PumpReadout, ThesisScaleModelsAreShownInCubicMetres) {
  const VolumeScale real = volumeScaleFor(120 * kMl);
  EXPECT_FALSE(real.thesis);
  EXPECT_STREQ(real.volumeUnit, "mL");
  EXPECT_STREQ(real.outputUnit, "L/min");
  EXPECT_DOUBLE_EQ(real.volume, 1e6);
  const VolumeScale thesis = volumeScaleFor(7.4);  // paper-chamber: 7.4 m^3
  EXPECT_TRUE(thesis.thesis);
  EXPECT_STREQ(thesis.volumeUnit, "m^3");
  EXPECT_STREQ(thesis.flowUnit, "m^3/s");
  EXPECT_DOUBLE_EQ(thesis.volume, 1);
  // CO = SV x HR per minute in both: a thesis beat of 0.08 s ejecting 1.5 m^3.
  cardiac::BeatSummary b;
  b.edv = 7, b.esv = 5.5, b.duration = 0.08, b.complete = true;
  const ClinicalFigures f = clinicalFigures(b, thesis);
  EXPECT_NEAR(f.heartRate, 750, 1e-9);
  EXPECT_NEAR(f.cardiacOutput, 1.5 * 750, 1e-9);
}

TEST(PumpReadout, FlowRatesAreNetVolumePerSecond) {
  cardiac::ValveFlows flows;
  flows.mitralForward = 3 * kMl, flows.mitralBackward = 1 * kMl;
  flows.aorticForward = 0, flows.aorticBackward = 0.5 * kMl;
  PumpSample sample;
  setFlowRates(sample, flows, 0.01);
  EXPECT_NEAR(sample.mitralRate / kMl, 200, 1e-9);  // 2 mL in 10 ms
  EXPECT_NEAR(sample.aorticRate / kMl, -50, 1e-9);  // backward
}

}  // namespace
}  // namespace hs::viewer
