// The lumped circulation alone (no 3D heart): its valves, its relations, and the periodic beat
// of a normal heart against the textbook ranges (docs/physiology.md), Frank-Starling, afterload
// and heart rate.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "cardiac/circulation/lumped_beat.h"
#include "cardiac/circulation/lumped_circulation.h"

namespace hs::cardiac {
namespace {

constexpr double kDt = 1e-3;
constexpr double mmHg = kPascalPerMmHg;
constexpr double mL = kCubicMetresPerMl;

struct Beat {
  LumpedBeatFigures figures;
  double period = 0;
};

// Beats of a regular rhythm with the activation the 3D heart's clocks would give
// (heart_activation.h): the ventricle from each onset, the atrium a PR interval before it.
Beat lastOfBeats(LumpedParameters p, double heartRate, int beats = 12, bool atrialKick = true) {
  LumpedCirculation c(p);
  c.startFrom(120 * mL);
  const BeatTiming t = beatTimingForRate(heartRate);
  const double period = 60.0 / heartRate;
  const int steps = int(std::lround(period / kDt));
  Beat out;
  out.period = period;
  for (int beat = 0; beat < beats; ++beat) {
    std::vector<CirculationSample> samples;
    for (int k = 0; k < steps; ++k) {
      const double tau = (k + 0.5) * kDt;
      Activation a;
      a.ventricle = ventricularActivationCurve(tau, t.contraction, t.relaxation);
      if (atrialKick)
        a.atrium = std::max(activationCurve(tau + t.prInterval, t.atrialContraction, t.atrialRelaxation),
                            activationCurve(tau - (period - t.prInterval), t.atrialContraction, t.atrialRelaxation));
      samples.push_back(c.advance(beat * period + (k + 1) * kDt, kDt, a));
    }
    const std::optional<double> onset =
        atrialKick ? std::optional<double>(beat * period + period - t.prInterval) : std::nullopt;
    out.figures = analyseLumpedBeat(samples, kDt, onset);
  }
  return out;
}

double cardiacOutput(const Beat& b) { return b.figures.forwardStrokeVolume / b.period; }

TEST(LumpedCirculation, ValveOpensForwardOnlyAndLeaksThroughARegurgitantOrifice) {
  LumpedParameters p;
  LumpedCirculation c(p);
  EXPECT_GT(c.valveFlow(10 * mmHg, p.mitralArea, 0, 0, p.valveResistance), 0);
  EXPECT_EQ(c.valveFlow(-10 * mmHg, p.mitralArea, 0, 0, p.valveResistance), 0);
  EXPECT_LT(c.valveFlow(-10 * mmHg, p.mitralArea, 0, 0.2e-4, p.valveResistance), 0);
  // dp = R Q + rho/2 (Q/A)^2 holds for the returned flow.
  const double q = c.valveFlow(10 * mmHg, p.mitralArea, 0, 0, p.valveResistance);
  const double dp = p.valveResistance * q + 0.5 * p.bloodDensity * (q / p.mitralArea) * (q / p.mitralArea);
  EXPECT_NEAR(dp, 10 * mmHg, 1e-6 * 10 * mmHg);
  // A valve as wide as the lumen after it loses only R Q (Borda-Carnot: no expansion).
  EXPECT_NEAR(c.valveFlow(1 * mmHg, p.aorticArea, p.aorticArea, 0, p.valveResistance), 1 * mmHg / p.valveResistance,
              1e-9);
}

TEST(LumpedCirculation, PressureVolumeRelationsBoundTheVentricle) {
  LumpedParameters p;
  LumpedCirculation c(p);
  const double v = 100 * mL;
  EXPECT_NEAR(c.lvPressure(v, 1), p.contractility * (v - p.unstressedVolume), 1e-9);
  EXPECT_NEAR(c.lvPressure(v, 0), p.diastolicScale * (std::exp(p.diastolicExponent * (v - p.unstressedVolume)) - 1),
              1e-9);
  const PressureVolumeRelations half = c.relations(0.5);
  EXPECT_DOUBLE_EQ(half.endSystolicElastance, 0.5 * p.contractility);
}

TEST(LumpedCirculation, ActivationCurvesRiseAndFallWithinTheirTimes) {
  EXPECT_EQ(activationCurve(-0.01, 0.1, 0.1), 0);
  EXPECT_NEAR(activationCurve(0.1, 0.1, 0.1), 1, 1e-12);
  EXPECT_EQ(activationCurve(0.21, 0.1, 0.1), 0);
  // The ventricle's rises at once (slope pi / 2 Tc at the onset), not from a standstill.
  EXPECT_GT(ventricularActivationCurve(0.01, 0.3, 0.1), 4 * activationCurve(0.01, 0.3, 0.1));
  // Weissler: the ejection time shortens with heart rate.
  EXPECT_GT(beatTimingForRate(60).systole, beatTimingForRate(150).systole);
}

TEST(LumpedCirculation, NormalBeatIsInTheTextbookRanges) {
  const Beat b = lastOfBeats({}, 72);
  const LumpedBeatFigures& f = b.figures;
  EXPECT_GE(f.aorticSystolic / mmHg, 110);
  EXPECT_LE(f.aorticSystolic / mmHg, 130);
  EXPECT_GE(f.aorticDiastolic / mmHg, 70);
  EXPECT_LE(f.aorticDiastolic / mmHg, 85);
  EXPECT_GE(f.lvPeak / mmHg, 110);
  EXPECT_LE(f.lvPeak / mmHg, 135);
  EXPECT_GE(f.lvEndDiastolic / mmHg, 4);
  EXPECT_LE(f.lvEndDiastolic / mmHg, 12);
  EXPECT_GE(f.isovolumicContraction, 0.030);
  EXPECT_LE(f.isovolumicContraction, 0.070);
  EXPECT_GE(f.isovolumicRelaxation, 0.050);
  EXPECT_LE(f.isovolumicRelaxation, 0.110);
  EXPECT_EQ(f.bothValvesOpenSamples, 0u);
  const double ef = f.totalStrokeVolume() / f.edv;
  EXPECT_GE(ef, 0.55);
  EXPECT_LE(ef, 0.70);
  EXPECT_GE(f.totalStrokeVolume() / mL, 60);
  EXPECT_LE(f.totalStrokeVolume() / mL, 100);
  EXPECT_GE(cardiacOutput(b) * 60e3, 4.5);
  EXPECT_LE(cardiacOutput(b) * 60e3, 7);
  ASSERT_TRUE(f.eToA.has_value());
  EXPECT_GE(*f.eToA, 1);
  EXPECT_LE(*f.eToA, 2);
}

TEST(LumpedCirculation, FrankStarlingAfterloadAndHeartRate) {
  LumpedParameters p;
  p.pulmonaryVenousPressure = 8 * mmHg;
  const Beat low = lastOfBeats(p, 72);
  p.pulmonaryVenousPressure = 16 * mmHg;
  const Beat high = lastOfBeats(p, 72);
  EXPECT_GE(high.figures.forwardStrokeVolume, 1.1 * low.figures.forwardStrokeVolume);

  LumpedParameters stiff;
  stiff.peripheralResistance *= 2;
  const Beat afterload = lastOfBeats(stiff, 72);
  EXPECT_GT(afterload.figures.aorticSystolic, low.figures.aorticSystolic);
  EXPECT_LT(afterload.figures.forwardStrokeVolume, low.figures.forwardStrokeVolume);

  const Beat fast = lastOfBeats({}, 150);
  EXPECT_LT(fast.figures.forwardStrokeVolume, low.figures.forwardStrokeVolume);
  EXPECT_LT(cardiacOutput(fast), 1.8 * cardiacOutput(low));
}

TEST(LumpedCirculation, NoAtrialKickNoAWaveAndLessOutput) {
  const Beat kick = lastOfBeats({}, 72);
  const Beat none = lastOfBeats({}, 72, 12, false);
  EXPECT_FALSE(none.figures.eToA.has_value());
  EXPECT_LT(none.figures.forwardStrokeVolume, kick.figures.forwardStrokeVolume);
}

TEST(LumpedCirculation, StenosisRegurgitationAndStiffnessShowTheirSigns) {
  LumpedParameters stenosis;
  stenosis.aorticArea = 0.6e-4;
  const Beat as = lastOfBeats(stenosis, 72);
  EXPECT_GE(as.figures.aorticMeanGradient / mmHg, 40);

  LumpedParameters leak;
  leak.mitralRegurgitantArea = 0.3e-4;
  const Beat mr = lastOfBeats(leak, 72);
  EXPECT_GT(mr.figures.regurgitantFraction(), 0.2);
  EXPECT_LT(mr.figures.forwardStrokeVolume, lastOfBeats({}, 72).figures.forwardStrokeVolume);
}

TEST(LumpedCirculation, BadParametersNameTheKeyAndTheRange) {
  auto message = [](LumpedParameters p) {
    try {
      LumpedCirculation c(p);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  LumpedParameters p;
  p.arterialCompliance = -1e-9;
  EXPECT_NE(message(p).find("circulation.arterial_compliance_ml_per_mmhg"), std::string::npos);
  EXPECT_NE(message(p).find("> 0 and <= 20 mL/mmHg"), std::string::npos);
  p = {};
  p.peripheralResistance = 0;
  EXPECT_NE(message(p).find("circulation.peripheral_resistance_mmhg_s_per_ml"), std::string::npos);
  p = {};
  p.contractility = 0;
  EXPECT_NE(message(p).find("circulation.contractility_mmhg_per_ml"), std::string::npos);
}

}  // namespace
}  // namespace hs::cardiac
