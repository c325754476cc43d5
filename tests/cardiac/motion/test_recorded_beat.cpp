// A recorded beat driving a patient's wall (cardiac/motion/recorded_beat.h, issue 16 item 5): the
// periodic spline, and a synthetic beat of known volume curve replayed on a two-annuli
// ventricle placed in a scanner frame.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cardiac/heart_simulation.h"
#include "cardiac/patient/patient_lv_model.h"
#include "cardiac/run_monitor.h"
#include "patient_test_hearts.h"
#include "recorded_beat_frames.h"
#include "thrown_message.h"

namespace hs::cardiac {
namespace {

using namespace testing;  // the synthetic ventricles (patient_test_hearts.h)
using hs::testing::scaledFrames;
using hs::testing::thrownMessage;
using hs::testing::volumeRatio;

TEST(RecordedBeat, CatmullRomPassesThroughEveryKnotAndWrapsAround) {
  const int count = 5;
  const double period = 0.8;
  for (int f = 0; f < count; ++f) {
    for (double beat : {0.0, 1.0, 3.0, -2.0}) {
      // At a knot's time the spline of any values is that knot's value (here 10 + k^2).
      const SplineWeights s = periodicCatmullRom((beat + double(f) / count) * period, period, count);
      double value = 0;
      for (int k = 0; k < 4; ++k) value += s.weight[k] * (10 + s.knot[k] * s.knot[k]);
      EXPECT_NEAR(value, 10 + f * f, 1e-9) << f << " in beat " << beat;
    }
  }
  // The knots around the last interval wrap to the first frames.
  const SplineWeights end = periodicCatmullRom(0.99 * period, period, count);
  EXPECT_EQ(end.knot[0], 3);
  EXPECT_EQ(end.knot[1], 4);
  EXPECT_EQ(end.knot[2], 0);
  EXPECT_EQ(end.knot[3], 1);
  EXPECT_NEAR(end.weight[0] + end.weight[1] + end.weight[2] + end.weight[3], 1.0, 1e-12);
}

TEST(RecordedBeat, CatmullRomFollowsASmoothPeriodicCurve) {
  // 25 samples of cos(2 pi t): the spline between them is within 2e-3 of the curve, and its
  // slope has no jump at a knot.
  const int count = 25;
  const double period = 1.0;
  const auto spline = [&](double t) {
    const SplineWeights s = periodicCatmullRom(t, period, count);
    double y = 0;
    for (int k = 0; k < 4; ++k) y += s.weight[k] * std::cos(2 * std::numbers::pi * s.knot[k] / count);
    return y;
  };
  for (int i = 0; i <= 1000; ++i) {
    const double t = i / 1000.0;
    EXPECT_NEAR(spline(t), std::cos(2 * std::numbers::pi * t), 2e-3) << t;
  }
  const double h = 1e-6, knot = 7.0 / count;
  const double left = (spline(knot) - spline(knot - h)) / h, right = (spline(knot + h) - spline(knot)) / h;
  EXPECT_NEAR(left, right, 1e-3 * std::abs(left) + 1e-4);
}

// The two-annuli ventricle in a scanner frame, its wall in one layer, and a recorded beat of
// 25 frames ejecting `ejection` of its volume with end-systole at 36% of the beat.
struct SyntheticBeat {
  Surface endocardium = inScannerFrame(twoAnnuliVentricle());
  std::vector<Surface> frames = scaledFrames(endocardium, 25, 0.4, 0.36);
};

PatientModelSettings syntheticPatient(const Surface& endocardium) {
  PatientModelSettings p;
  p.kind = ModelKind::Mesh;
  p.endocardium = "synthetic.obj";
  p.units = LengthUnit::Millimetre;
  p.endocardiumSurface = endocardium;
  return p;
}

TEST(RecordedBeat, FramesVolumesAreTheAnalyticCurveInCubicMetres) {
  const SyntheticBeat beat;
  const PatientWall wall = buildPatientShell(syntheticPatient(beat.endocardium), Real(0.008));
  const LvModel model = lvModelFromPatientWall(wall);
  const RecordedBeat recorded(model, wall, beat.frames, 0.8, 0);
  const double v0 = std::abs(pbd::cappedSignedVolume(beat.endocardium.vertices, beat.endocardium.triangles)) * 1e-9;
  ASSERT_EQ(recorded.frameCount(), 25);
  for (int f = 0; f < 25; ++f)
    EXPECT_NEAR(recorded.frameVolumes()[f], v0 * volumeRatio(f / 25.0, 0.4, 0.36), 1e-5 * v0) << f;
  EXPECT_NEAR(recorded.systolicFraction(), 9.0 / 25.0, 1e-12);  // frame 9 is the smallest
  // Every endocardial vertex off a base plate is driven (this ventricle's base is in the file),
  EXPECT_GT(recorded.drivenVertices().size(), wall.endoVertices);  // and most of their epicardial partners
  // At t = 0 the wall is where it rests.
  std::vector<Vec3> predicted(model.mesh.vertices.size(), Vec3::Zero());
  recorded.drive(0.0, predicted);
  for (Index v : recorded.drivenVertices()) EXPECT_LT((predicted[v] - model.mesh.vertices[v]).norm(), 1e-6);
}

TEST(RecordedBeat, TheWallFollowsTheRecordingAndEjectsItsFraction) {
  const SyntheticBeat beat;
  Scenario s;
  s.patient = syntheticPatient(beat.endocardium);
  s.geometry.wallThickness = Real(0.008);
  s.simulation.dt = Real(0.002);
  s.simulation.iterations = 10;
  s.motion.frames = "synthetic_{frame:03d}.obj";
  s.motion.count = 25;
  s.motion.period = Real(0.8);
  s.motion.frameSurfaces = beat.frames;
  HeartSimulation sim(s, 1);
  ASSERT_NE(sim.recordedBeat(), nullptr);
  RunMonitor monitor(sim);
  const RecordedBeat& recorded = *sim.recordedBeat();
  double worst = 0;
  for (int k = 0; k < 1250; ++k) {  // 2.5 beats
    sim.step();
    ASSERT_TRUE(monitor.observe().healthy()) << monitor.verdict().message();
    const double rec = recorded.recordedVolume(sim.time());
    worst = std::max(worst, std::abs(double(sim.cavityVolume()) - rec) / rec);
  }
  monitor.finish();
  // The 3D cavity within 2% of the recorded volume at every step, and the run's own record of it.
  EXPECT_LT(worst, 0.02);
  EXPECT_NEAR(recorded.volumeErrorMax(), worst, 1e-12);
  // Its beats: the recording's rhythm (0.8 s, systole to frame 9) and EF within 1 point.
  const BeatMeans m = monitor.beats().means();
  ASSERT_GE(m.count, 1);
  EXPECT_NEAR(m.ejectionFraction, 0.4, 0.01);
  EXPECT_NEAR(monitor.beats().beats()[1].startTime, 0.8, 0.0021);  // within a step
  EXPECT_EQ(sim.tissueStats().invertedTets, 0u);
}

TEST(RecordedBeat, FramesThatAreNotTheSameMeshOrTooFewAreRefused) {
  const SyntheticBeat beat;
  const PatientWall wall = buildPatientShell(syntheticPatient(beat.endocardium), Real(0.008));
  const LvModel model = lvModelFromPatientWall(wall);
  std::vector<Surface> frames = beat.frames;
  frames[3].triangles.pop_back();
  EXPECT_EQ(thrownMessage<std::invalid_argument>([&] { RecordedBeat(model, wall, frames, 0.8, 0); }),
            "motion.frames: frame 3 has other vertices or triangles than frame 0; expected the same mesh moved");
  const std::vector<Surface> one(1, beat.endocardium);
  EXPECT_EQ(thrownMessage<std::invalid_argument>([&] { RecordedBeat(model, wall, one, 0.8, 0); }),
            "motion.count: a recorded beat needs at least 2 frames, got 1");
  // A recording whose smallest volume is frame 0 has no end-diastole to start from.
  Scenario s;
  s.patient = syntheticPatient(beat.endocardium);
  s.geometry.wallThickness = Real(0.008);
  s.motion.count = 25;
  s.motion.period = Real(0.8);
  s.motion.frameSurfaces = beat.frames;
  std::rotate(s.motion.frameSurfaces.begin(), s.motion.frameSurfaces.begin() + 9, s.motion.frameSurfaces.end());
  EXPECT_EQ(thrownMessage<std::invalid_argument>([&] { HeartSimulation(s, 1); }),
            "motion.frames: the smallest recorded volume is at frame 0 of 25; expected frame 0 at end-diastole and "
            "end-systole between 5% and 95% of the beat");
}

}  // namespace
}  // namespace hs::cardiac
