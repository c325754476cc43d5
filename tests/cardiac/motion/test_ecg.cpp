// The synthetic ECG (motion/ecg.h): the R peak 25 ms before the ventricle's onset and the
// highest point of the beat, the T wave ending where the systole ends, a P wave only with
// atrial contraction, and a trace without jumps through an onset.
#include <gtest/gtest.h>

#include <cmath>

#include "cardiac/motion/ecg.h"

namespace hs::cardiac {
namespace {

TEST(Ecg, TheWavesSitWhereTheBeatsTimingPutsThem) {
  const BeatTiming timing = beatTimingForRate(72);
  double peak = -1e9, peakAt = 0;
  for (double tau = -0.4; tau <= 0.6; tau += 1e-4) {
    const double v = ecgBeatWaveform(tau, timing, true);
    if (v > peak) peak = v, peakAt = tau;
  }
  EXPECT_NEAR(peakAt, -0.025, 1e-3) << "R, before the mechanical onset";
  EXPECT_GT(peak, 1.0);
  // T: its peak two widths before the systole's end, nearly gone at that end.
  const double tPeak = ecgBeatWaveform(timing.systole - 0.09, timing, true);
  EXPECT_GT(tPeak, 0.25);
  EXPECT_LT(ecgBeatWaveform(timing.systole + 0.01, timing, true), 0.1 * tPeak);
  // P: a PR interval and a little before the onset, only with the atrium contracting.
  const double p = -timing.prInterval - 0.02;
  EXPECT_NEAR(ecgBeatWaveform(p, timing, true), 0.15, 0.01);
  EXPECT_LT(std::abs(ecgBeatWaveform(p, timing, false)), 0.01);
}

TEST(Ecg, TheTraceRunsThroughAnOnsetWithoutAJump) {
  const BeatTiming timing = beatTimingForRate(72);
  const double period = 60.0 / 72, dt = 1e-3;
  // The step before the onset (the onset to come in dt) and the step at it (since = 0).
  const double before = syntheticEcg(0, period - dt, dt, timing, true);
  const double at = syntheticEcg(0, 0, period, timing, true);
  EXPECT_LT(std::abs(at - before), 0.2) << before << " then " << at;
  // Without atrial contraction the baseline carries the f waves.
  double largest = 0;
  for (double t = 0; t < 1; t += 1e-3) largest = std::max(largest, std::abs(syntheticEcg(t, 0.5, 0.3, timing, false)));
  EXPECT_GT(largest, 0.03);
  EXPECT_LT(largest, 0.1);
}

}  // namespace
}  // namespace hs::cardiac
