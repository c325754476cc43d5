// [motion] (issue 16 item 5): a recorded beat's frames read from files as the scenario is read,
// every bad one refused with the key, and the biv-me ventricle driven by a synthetic recording
// of known volumes.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "cardiac/heart_simulation.h"
#include "cardiac/run_monitor.h"
#include "io/mesh/recorded_frames.h"
#include "io/scenario/scenario_file.h"
#include "recorded_beat_frames.h"
#include "thrown_message.h"

namespace hs::io {
namespace {

using cardiac::Scenario;

const std::string kBivmeEndo = std::string(HS_TEST_DATA_DIR) + "/meshes/bivme_patient1/patient1_LV_ENDOCARDIAL_000.obj";

// biv-me's endocardium as read, scaled into 25 frames ejecting 35% (end-systole at frame 9) and
// written to dir/frames/frame_NNN.obj; frame 0 is the scenario's endocardium.
std::filesystem::path writeBivmeBeat(const std::string& name) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / name;
  std::filesystem::remove_all(dir);
  const Scenario read = parseScenario("[model]\nkind = \"mesh\"\nendocardium = \"" + kBivmeEndo + "\"\n", "x.toml");
  hs::testing::writeFrames(dir / "frames", hs::testing::scaledFrames(read.patient.endocardiumSurface, 25, 0.35, 0.36));
  return dir;
}

std::string motionScenario(const std::string& motion, const std::string& extra = "") {
  return "[simulation]\ndt = 0.002\niterations = 10\n[model]\nkind = \"mesh\"\nendocardium = "
         "\"frames/frame_000.obj\"\nunits = \"mm\"\n" +
         extra + "[motion]\n" + motion;
}

const std::string kGoodMotion = "frames = \"frames/frame_{frame:03d}.obj\"\ncount = 25\nperiod = 0.8\n";

// Written as dir/lesson.toml and read: the ScenarioError's message, or "" when it reads.
std::string readError(const std::filesystem::path& dir, const std::string& text) {
  std::ofstream(dir / "lesson.toml") << text;
  try {
    loadScenario((dir / "lesson.toml").string());
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}

void expectPieces(const std::string& msg, const std::vector<std::string>& pieces) {
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  for (const std::string& p : pieces) EXPECT_NE(msg.find(p), std::string::npos) << "missing '" << p << "' in: " << msg;
}

TEST(ScenarioMotion, FramePatternsNameEachFrame) {
  EXPECT_EQ(framePath("lv_{frame:03d}.obj", 7), "lv_007.obj");
  EXPECT_EQ(framePath("lv_{frame:03d}.obj", 1234), "lv_1234.obj");
  EXPECT_EQ(framePath("a/{frame}/endo.stl", 12), "a/12/endo.stl");
  for (const std::string bad : {"lv.obj", "lv_{frame:3d}.obj", "lv_{frame:03x}.obj", "{frame}_{frame}.obj",
                                "lv_{frame.obj", "lv_{time}.obj"}) {
    const std::string msg = hs::testing::thrownMessage<std::invalid_argument>([&] { framePath(bad, 0); });
    expectPieces(msg, {"\"" + bad + "\": ", "expected one {frame} or {frame:0Nd}"});
  }
}

TEST(ScenarioMotion, FramesAreReadFromTheScenarioFilesFolder) {
  const auto dir = writeBivmeBeat("heartsim_motion_read");
  std::ofstream(dir / "lesson.toml") << motionScenario(kGoodMotion);
  const Scenario s = loadScenario((dir / "lesson.toml").string());
  EXPECT_EQ(s.motion.frames, (dir / "frames" / "frame_{frame:03d}.obj").lexically_normal().string());
  ASSERT_EQ(s.motion.frameSurfaces.size(), 25u);
  EXPECT_EQ(s.motion.frameSurfaces[24].triangles, s.patient.endocardiumSurface.triangles);
  EXPECT_NE(s.motion.frameSurfaces[9].vertices[0], s.patient.endocardiumSurface.vertices[0]);
  // Written out and read back (checkpoints do): the same frames.
  const Scenario back = parseScenario(scenarioToToml(s), "elsewhere/dump.toml");
  EXPECT_EQ(back.motion.frameSurfaces.size(), 25u);
}

TEST(ScenarioMotion, BadRecordingsNameTheKeyAndWhatWasExpected) {
  const auto dir = writeBivmeBeat("heartsim_motion_errors");
  const std::string lesson = (dir / "lesson.toml").string();
  expectPieces(readError(dir, "[motion]\n" + kGoodMotion),
               {lesson + ":2", "motion.frames: a recorded beat drives a patient's heart", "model.kind = \"mesh\""});
  expectPieces(readError(dir, motionScenario("frames = \"frames/frame_{frame:03d}.obj\"\ncount = 1\nperiod = 0.8\n")),
               {lesson + ":10", "motion.count: expected at least 2 frames with motion.frames, got 1"});
  expectPieces(readError(dir, motionScenario("frames = \"frames/frame_{frame:03d}.obj\"\ncount = 25\nperiod = 0.1\n")),
               {lesson + ":11", "motion.period: expected at least 0.24 s (250 bpm)", "got 0.1"});
  expectPieces(readError(dir, motionScenario("frames = \"frames/frame.obj\"\ncount = 25\nperiod = 0.8\n")),
               {lesson + ":9", "motion.frames", "no {frame} in the file name"});
  // Frame 25 does not exist.
  expectPieces(readError(dir, motionScenario("frames = \"frames/frame_{frame:03d}.obj\"\ncount = 26\nperiod = 0.8\n")),
               {lesson + ":9", "motion.frames", "frame_025.obj: no such mesh file"});
  // A frame of another mesh: frame 4 cut to its first 100 triangles.
  {
    std::ifstream in(dir / "frames" / "frame_004.obj");
    std::string line, kept;
    int faces = 0;
    while (std::getline(in, line))
      if (line[0] != 'f' || ++faces <= 100) kept += line + "\n";
    in.close();
    std::ofstream(dir / "frames" / "frame_004.obj") << kept;
  }
  expectPieces(readError(dir, motionScenario(kGoodMotion)),
               {lesson + ":9", "motion.frames", "frame_004.obj: frame 4 has", "expected the endocardium",
                "frame_000.obj moved"});
  // The recording sets the rhythm: a cycle that contradicts it is refused.
  expectPieces(readError(dir, motionScenario(kGoodMotion, "[cycle]\npattern = \"irregular\"\n")),
               {lesson + ":9", "cycle: the recorded beat repeats as recorded", "pattern = \"normal\""});
  expectPieces(readError(dir, motionScenario(kGoodMotion, "[cycle]\nsegments = [1, 2]\n")),
               {lesson + ":9", "cycle: the recorded beat moves the whole endocardium"});
}

TEST(ScenarioMotion, BivmeFollowsARecordedBeatOfKnownVolumes) {
  const auto dir = writeBivmeBeat("heartsim_motion_bivme");
  std::ofstream(dir / "lesson.toml") << motionScenario(kGoodMotion);
  cardiac::HeartSimulation sim(loadScenario((dir / "lesson.toml").string()), 1);
  cardiac::RunMonitor monitor(sim);
  const cardiac::RecordedBeat& recorded = *sim.recordedBeat();
  const double edv = recorded.frameVolumes()[0];
  EXPECT_NEAR(edv * 1e6, 174.5, 0.02 * 174.5);  // frame 0 is biv-me's frame 0
  for (int k = 0; k < 1250; ++k) {  // 2.5 beats of 0.8 s
    sim.step();
    ASSERT_TRUE(monitor.observe().healthy()) << monitor.verdict().message();
    const double rec = recorded.recordedVolume(sim.time());
    ASSERT_LT(std::abs(double(sim.cavityVolume()) - rec) / rec, 0.02) << "t = " << sim.time();
  }
  monitor.finish();
  EXPECT_NEAR(monitor.beats().means().ejectionFraction, 0.35, 0.01);
  EXPECT_EQ(sim.tissueStats().invertedTets, 0u);
  // The epicardium placed by incompressibility keeps the wall's tets near their volumes (left
  // to the constraints it folded, the worst 58% off at 30% ejection; placed, 37% there and 47%
  // here, at 35%, both beside the annuli).
  std::printf("worst tet volume error %.3f, mean %.4f\n", monitor.extremes().volumeErrorMax,
              monitor.extremes().volumeErrorMeanSum / double(monitor.observedSteps()));
  EXPECT_LT(monitor.extremes().volumeErrorMax, 0.5);
  EXPECT_LT(monitor.extremes().volumeErrorMeanSum / double(monitor.observedSteps()), 0.03);
}

// The coarse wall, the resolution for real time, holds its shape through a recorded beat. At
// 8 mm edges the strip of wall between biv-me's two annuli was one sliver wide: on this beat
// (35% ejection) its worst tet lost 76% of its volume and the surface turned 83 degrees; at 6 mm
// 27% and 51 degrees, better than the default 5 mm wall's 47% and 66 (the test above).
TEST(ScenarioMotion, TheCoarseWallHoldsItsShapeBetweenTheAnnuli) {
  const auto dir = writeBivmeBeat("heartsim_motion_bivme_coarse");
  std::ofstream(dir / "lesson.toml") << motionScenario(kGoodMotion, "mesh_resolution = \"coarse\"\n");
  cardiac::HeartSimulation sim(loadScenario((dir / "lesson.toml").string()), 1);
  cardiac::RunMonitor monitor(sim);
  for (int k = 0; k < 400; ++k) {  // one beat of 0.8 s
    sim.step();
    ASSERT_TRUE(monitor.observe().healthy()) << monitor.verdict().message();
  }
  monitor.finish();
  const double turnDeg = monitor.extremes().surfaceTurnMax * 180 / 3.141592653589793;
  std::printf("coarse wall: worst tet volume error %.3f, largest surface turn %.1f deg\n",
              monitor.extremes().volumeErrorMax, turnDeg);
  EXPECT_EQ(sim.tissueStats().invertedTets, 0u);
  EXPECT_LT(monitor.extremes().volumeErrorMax, 0.4);
  EXPECT_LT(turnDeg, 60.0);
}

}  // namespace
}  // namespace hs::io
