// A recorded beat that moves as a left ventricle does (lv_beat_frames.h: the base descending
// toward a fixed apex, the wall moving in, a twist, the annuli narrowing; issue 41 item 1) on
// patient-biv-me's default wall: the frames are what a cine MRI recording of a healthy ventricle
// shows, and the wall follows them beat after beat; a frame with a segment folded through the
// cavity is refused before the first step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "cardiac/heart_simulation.h"
#include "cardiac/run_monitor.h"
#include "io/scenario/scenario_file.h"
#include "lv_beat_frames.h"
#include "thrown_message.h"

namespace hs::io {
namespace {

using hs::testing::LvBeat;
using hs::testing::LongAxis;
using pbd::Vec3d;

cardiac::Scenario bivmeWithBeat(const std::vector<cardiac::Surface>& frames, const std::vector<std::string>& set) {
  cardiac::Scenario s = loadScenario("patient-biv-me", set);
  s.motion.frames = "frame_{frame:03d}.obj";
  s.motion.count = int(frames.size());
  s.motion.period = pbd::Real(0.8);
  s.motion.frameSurfaces = frames;
  return s;
}

double cappedVolume(const cardiac::Surface& s) { return std::abs(pbd::cappedSignedVolume(s.vertices, s.triangles)); }

// Mean turn (degrees, counter-clockwise seen from the apex) about the long axis of the vertices
// whose height share lies in [low, high), from frame a to frame b.
double meanTwistDeg(const cardiac::Surface& a, const cardiac::Surface& b, const LongAxis& axis, double low, double high) {
  double sum = 0;
  int n = 0;
  for (std::size_t i = 0; i < a.vertices.size(); ++i) {
    const Vec3d p = a.vertices[i].cast<double>() - axis.apex, q = b.vertices[i].cast<double>() - axis.apex;
    const double share = p.dot(axis.toBase) / axis.length;
    if (share < low || share >= high) continue;
    const Vec3d rp = p - p.dot(axis.toBase) * axis.toBase, rq = q - q.dot(axis.toBase) * axis.toBase;
    sum += std::atan2(rp.cross(rq).dot(axis.toBase), rp.dot(rq)) * 180 / std::numbers::pi;
    ++n;
  }
  return sum / n;
}

TEST(RecordedLvBeat, TheTestRecordingMovesAsAVentricleDoes) {
  const cardiac::Surface endo = loadScenario("patient-biv-me").patient.endocardiumSurface;
  const std::vector<cardiac::Surface> frames = hs::testing::lvBeatFrames(endo);
  ASSERT_EQ(frames.size(), 25u);
  const LongAxis axis = hs::testing::findLongAxis(endo);
  std::vector<double> volume;
  for (const cardiac::Surface& f : frames) volume.push_back(cappedVolume(f));
  const std::size_t es = std::size_t(std::min_element(volume.begin(), volume.end()) - volume.begin());
  EXPECT_EQ(es, 9u);  // 0.36 of 25 frames
  const double ef = 1 - volume[es] / volume[0];
  EXPECT_NEAR(ef, 0.60, 0.005);
  // The annuli: their centroid descends 13 mm along the long axis, each ring's flat cap narrows.
  const auto loops = pbd::boundaryLoopVertices(endo.triangles);
  ASSERT_EQ(loops.size(), 2u);
  Vec3d descent = Vec3d::Zero();
  std::size_t ringVertices = 0;
  for (const auto& loop : loops) {
    const auto capArea = [&](const cardiac::Surface& s) {
      Vec3d c = Vec3d::Zero(), twice = Vec3d::Zero();
      for (pbd::Index v : loop) c += s.vertices[v].cast<double>();
      c /= double(loop.size());
      for (std::size_t k = 0; k < loop.size(); ++k)
        twice += (s.vertices[loop[k]].cast<double>() - c).cross(s.vertices[loop[(k + 1) % loop.size()]].cast<double>() - c);
      return 0.5 * twice.norm();
    };
    const double narrowing = capArea(frames[es]) / capArea(endo);
    std::printf("annulus of %zu vertices: its flat cap %.3f of its area at end-systole\n", loop.size(), narrowing);
    EXPECT_GT(narrowing, 0.75) << "loop of " << loop.size();
    EXPECT_LT(narrowing, 0.9) << "loop of " << loop.size();
    for (pbd::Index v : loop) descent += (frames[es].vertices[v] - endo.vertices[v]).cast<double>();
    ringVertices += loop.size();
  }
  const double baseDescentMm = -descent.dot(axis.toBase) / double(ringVertices);
  EXPECT_GE(baseDescentMm, 12.0);
  EXPECT_LE(baseDescentMm, 15.0);
  // A few degrees of twist, the apex one way and the base the other.
  const double apexTwist = meanTwistDeg(endo, frames[es], axis, 0, 0.25);
  const double baseTwist = meanTwistDeg(endo, frames[es], axis, 0.75, 2);
  EXPECT_GT(apexTwist, 2.0);
  EXPECT_LT(apexTwist, 10.0);
  EXPECT_LT(baseTwist, -1.0);
  EXPECT_GT(baseTwist, -6.0);
  std::printf("EF %.4f, base descent %.2f mm, twist apex %.2f / base %.2f deg\n", ef, baseDescentMm, apexTwist, baseTwist);
}

// Five beats on the built-in's default wall, without blood: every step's cavity within 2% of
// the recorded volume, no tet inverted, the ejection fraction the recording's within a point.
// Before, the epicardium was placed along the endocardium's raw normals (and the rims of the
// annuli left to the constraints): on this recording a tet of AHA segment 1 inverted at 0.243 s.
TEST(RecordedLvBeat, TheDefaultWallFollowsARecordedVentricleForFiveBeats) {
  const cardiac::Scenario read = loadScenario("patient-biv-me");
  cardiac::HeartSimulation sim(bivmeWithBeat(hs::testing::lvBeatFrames(read.patient.endocardiumSurface),
                                             {"blood.enabled=false"}),
                               1);
  cardiac::RunMonitor monitor(sim);
  const cardiac::RecordedBeat& recorded = *sim.recordedBeat();
  // Decided before the first step: the whole wall is driven, no tet or triangle turns over.
  const cardiac::RecordedFold fold = recorded.findFold(0.001);
  EXPECT_EQ(fold.tets, 0);
  EXPECT_EQ(fold.triangles, 0);
  std::printf("the least share of a tet's rest volume over the beat %.3f\n", fold.smallestShare);
  const std::vector<double>& v = recorded.frameVolumes();
  const double recordedEf = 1 - *std::min_element(v.begin(), v.end()) / v[0];
  double worst = 0;
  for (int k = 0; k < 4000; ++k) {  // 5 beats of 0.8 s at 1 ms
    sim.step();
    ASSERT_TRUE(monitor.observe().healthy()) << monitor.verdict().message();
    const double rec = recorded.recordedVolume(sim.time());
    worst = std::max(worst, std::abs(double(sim.cavityVolume()) - rec) / rec);
    ASSERT_LT(std::abs(double(sim.cavityVolume()) - rec) / rec, 0.02) << "t = " << sim.time();
  }
  monitor.finish();
  EXPECT_EQ(sim.tissueStats().invertedTets, 0u);
  ASSERT_EQ(monitor.beats().beats().size(), 5u);
  for (const cardiac::BeatSummary& beat : monitor.beats().beats())
    EXPECT_NEAR(beat.ejectionFraction(), recordedEf, 0.01) << "beat " << beat.index;
  EXPECT_NEAR(monitor.beats().means().ejectionFraction, recordedEf, 0.01);
  std::printf("recorded EF %.4f, 3D EF %.4f, worst step %.4f%%, worst tet volume error %.3f\n", recordedEf,
              monitor.beats().means().ejectionFraction, 100 * worst, monitor.extremes().volumeErrorMax);
}

// A frame whose mid-ventricular patch is pushed through the cavity turns the wall's tets there
// inside out at every resolution: refused as the simulation is built, with one line naming the
// frames, the segment and that no resolution follows it.
TEST(RecordedLvBeat, AFoldedFrameIsRefusedBeforeTheFirstStep) {
  const cardiac::Scenario read = loadScenario("patient-biv-me");
  const std::vector<cardiac::Surface> frames =
      hs::testing::foldedFrames(hs::testing::lvBeatFrames(read.patient.endocardiumSurface), 9, 25);
  const std::string message = hs::testing::thrownMessage<std::invalid_argument>(
      [&] { cardiac::HeartSimulation sim(bivmeWithBeat(frames, {"blood.enabled=false"}), 1); });
  std::printf("%s\n", message.c_str());
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  for (const std::string piece : {"motion.frames: the default wall (5 mm edges) cannot follow frames ",
                                  "endocardial triangles turn over (the surface folds)", " in AHA segment",
                                  "no wall resolution (coarse, default, fine) follows it"})
    EXPECT_NE(message.find(piece), std::string::npos) << "missing '" << piece << "' in: " << message;
  // The frames named are those around frame 9, which the spline between frames 8 and 10 uses.
  const std::size_t at = message.find("cannot follow frames ");
  ASSERT_NE(at, std::string::npos) << message;
  int first = -1, last = -1;
  ASSERT_EQ(std::sscanf(message.c_str() + at, "cannot follow frames %d-%d", &first, &last), 2) << message;
  EXPECT_LE(first, 9);
  EXPECT_GE(last, 9);
  EXPECT_GE(first, 7);
  EXPECT_LE(last, 11);
}

}  // namespace
}  // namespace hs::io
