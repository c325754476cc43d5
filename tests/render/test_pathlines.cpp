// Short pathlines (render/pathlines.h) and the flow lines built from them and from the
// smoothed velocity (render/scene.h): each streak segment joins a seed's recorded positions at
// the speed it covered them, the window is kept, a restart starts afresh; arrows are as long
// as 10 ms of travel and coloured by their speed.
#include <gtest/gtest.h>

#include "cardiac/heart_simulation.h"
#include "falling_block.h"
#include "render/pathlines.h"
#include "render/scene.h"

namespace {

using hs::render::Vec3f;

TEST(Pathlines, SegmentsJoinEachSeedsPositionsAtTheSpeedItMoved) {
  hs::cardiac::HeartSimulation sim(hs::testing::fallingBlock(), 1);
  const double dt = double(sim.scenario().simulation.dt);
  hs::render::PathlineRecorder recorder(4.5 * dt, 3);
  for (int s = 0; s < 8; ++s) {
    recorder.record(sim);
    sim.step();
  }
  // Samples at steps 0..7; the window of 4.5 steps back from step 7 keeps steps 3..7 and the
  // newest one before it, step 2: 6 samples, 5 segments per seed (every third blood particle).
  EXPECT_EQ(recorder.sampleCount(), 6u);
  const std::vector<hs::render::PathlineRecorder::Segment> segments = recorder.segments();
  const std::size_t blood = sim.particles().size() - sim.firstBloodParticle();
  EXPECT_EQ(segments.size(), 5 * ((blood + 2) / 3));
  for (const auto& s : segments) {
    EXPECT_NEAR(double(s.speed), double((s.to - s.from).norm()) / dt, 1e-3 * (1 + double(s.speed)));
    EXPECT_GE(s.age, 0.0f);
    EXPECT_LE(double(s.age), 4.5 * dt + 1e-9);
  }
  // The heads (age 0) are where the seeds are as of the last record.
  recorder.record(sim);
  int heads = 0;
  for (const auto& s : recorder.segments()) {
    if (s.age != 0) continue;
    ++heads;
    bool found = false;
    for (std::size_t i = sim.firstBloodParticle(); i < sim.particles().size() && !found; ++i)
      found = sim.particles().position[i].cast<float>().isApprox(s.to);
    EXPECT_TRUE(found);
  }
  EXPECT_EQ(std::size_t(heads), (blood + 2) / 3);
}

TEST(Pathlines, ATimeEarlierThanTheLastStartsAfresh) {
  hs::cardiac::HeartSimulation sim(hs::testing::fallingBlock(), 1);
  hs::render::PathlineRecorder recorder(1.0, 4);
  for (int s = 0; s < 3; ++s) recorder.record(sim), sim.step();
  EXPECT_EQ(recorder.sampleCount(), 3u);
  hs::cardiac::HeartSimulation restarted(hs::testing::fallingBlock(), 1);
  recorder.record(restarted);
  EXPECT_EQ(recorder.sampleCount(), 1u);
  EXPECT_TRUE(recorder.segments().empty());
}

TEST(FlowLines, ArrowsAreTenMillisecondsOfTravelInTheirSpeedsColour) {
  hs::render::FlowLines lines;
  const std::vector<Vec3f> positions = {Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(2, 0, 0)};
  const std::vector<Vec3f> velocities = {Vec3f(0, 0.5f, 0), Vec3f(0, 0, 0), Vec3f(3, 0, 0)};
  hs::render::addArrows(lines, positions, velocities, 1.5, 2, 1);
  ASSERT_EQ(lines.size(), 4u);  // shaft and head for each moving particle; none for the still one
  EXPECT_TRUE(lines.to[0].isApprox(Vec3f(0, 0.005f, 0)));
  EXPECT_TRUE(lines.colours[0].isApprox(hs::render::speedColour(0.5 / 1.5)));
  // Faster than twice the scale's top: as long as twice the top's 10 ms.
  EXPECT_TRUE(lines.to[2].isApprox(Vec3f(2.03f, 0, 0)));
  EXPECT_TRUE(lines.colours[2].isApprox(hs::render::speedColour(1)));
}

TEST(FlowLines, StreaksTaperTowardTheirTailsAndTheBloodBecomesABackdrop) {
  hs::cardiac::HeartSimulation sim(hs::testing::fallingBlock(), 1);
  hs::render::PathlineRecorder recorder(0.02, 5);
  for (int s = 0; s < 30; ++s) recorder.record(sim), sim.step();
  recorder.record(sim);
  hs::render::SceneOptions options;
  options.flow = hs::render::FlowView::Streaks;
  options.pathlines = &recorder;
  options.flowLineWidth = 3;
  const hs::render::Scene scene = hs::render::buildScene(sim, options);
  ASSERT_EQ(scene.flow.size(), recorder.segments().size());
  ASSERT_GT(scene.flow.size(), 0u);
  for (std::size_t i = 0; i < scene.flow.size(); ++i) {
    EXPECT_LE(scene.flow.widthFrom[i], scene.flow.widthTo[i] + 1e-6f);
    EXPECT_GE(scene.flow.widthFrom[i], 1.0f - 1e-6f);
    EXPECT_LE(scene.flow.widthTo[i], 3.0f + 1e-6f);
  }
  EXPECT_LT(scene.particles.opacity, 1.0f);
  for (const Vec3f& c : scene.particles.colours) EXPECT_EQ(c, hs::render::kFlowBackdropColour);
}

TEST(FlowLines, NamesRoundTripAndUnknownOnesAreRejected) {
  for (const auto flow : {hs::render::FlowView::Off, hs::render::FlowView::Streaks, hs::render::FlowView::Arrows})
    EXPECT_EQ(hs::render::parseFlowView(hs::render::flowViewName(flow)), flow);
  for (const auto look : {hs::render::BloodLook::Liquid, hs::render::BloodLook::Spheres})
    EXPECT_EQ(hs::render::parseBloodLook(hs::render::bloodLookName(look)), look);
  EXPECT_FALSE(hs::render::parseFlowView("streamlines"));
  EXPECT_FALSE(hs::render::parseBloodLook("Liquid"));
}

}  // namespace
