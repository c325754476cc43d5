// Scene building from a simulation: one triangle per surface face, region colours, unit
// normals, blood coloured by speed, the container as a wireframe, framing bounds.
#include <gtest/gtest.h>

#include <array>
#include <set>

#include "cardiac/heart_simulation.h"
#include "falling_block.h"
#include "render/scene.h"

namespace {

using hs::render::Vec3f;

TEST(Scene, WallHasOneTrianglePerSurfaceFaceWithRegionColoursAndUnitNormals) {
  hs::cardiac::Scenario scenario;  // heart-only, thesis scale
  const hs::cardiac::HeartSimulation sim(scenario, 1);
  const hs::render::Scene scene = hs::render::buildScene(sim, {});
  ASSERT_EQ(scene.wall.triangleCount(), sim.model().surface.size());
  ASSERT_EQ(scene.wall.normals.size(), scene.wall.positions.size());
  ASSERT_EQ(scene.wall.colours.size(), scene.wall.positions.size());
  std::size_t myocardium = 0, vessel = 0;
  for (std::size_t f = 0; f < sim.model().surface.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const auto v = sim.model().surface[f][k];
      const std::size_t i = 3 * f + k;
      EXPECT_NEAR(scene.wall.normals[i].norm(), 1.0f, 1e-4f);
      EXPECT_TRUE(scene.wall.positions[i].isApprox(sim.particles().position[v].cast<float>()));
      EXPECT_EQ(scene.wall.colours[i], hs::render::regionColour(sim.model().region[v]));
      myocardium += sim.model().region[v] == hs::cardiac::Region::Myocardium;
      vessel += sim.model().region[v] == hs::cardiac::Region::OutflowVessel;
    }
  EXPECT_GT(myocardium, 0u);
  EXPECT_GT(vessel, 0u);
  // Myocardium reads red, the vessels lighter.
  const Vec3f red = hs::render::regionColour(hs::cardiac::Region::Myocardium);
  EXPECT_GT(red.x(), red.y() + 0.3f);
  EXPECT_GT(hs::render::regionColour(hs::cardiac::Region::OutflowVessel).sum(), red.sum());
  EXPECT_TRUE(scene.particles.centres.empty());
  EXPECT_TRUE(scene.lines.points.empty());
}

TEST(Scene, NormalsPointOutOfTheWall) {
  hs::cardiac::Scenario scenario;
  const hs::cardiac::HeartSimulation sim(scenario, 1);
  const hs::render::Scene scene = hs::render::buildScene(sim, {});
  // The apex's outer surface (lowest point) faces down.
  std::size_t lowest = 0;
  for (std::size_t i = 0; i < scene.wall.positions.size(); ++i)
    if (scene.wall.positions[i].y() < scene.wall.positions[lowest].y()) lowest = i;
  EXPECT_LT(scene.wall.normals[lowest].y(), -0.8f);
}

TEST(Scene, BloodIsColouredBySpeedAndTheContainerIsAWireframe) {
  // The falling block, resting on the container's floor.
  hs::cardiac::Scenario scenario = hs::testing::fallingBlock();
  scenario.blood.blockMin = hs::pbd::Vec3(0, 0, 0);
  scenario.blood.blockMax = hs::pbd::Vec3(0.02f, 0.02f, 0.02f);
  scenario.container.max = hs::pbd::Vec3(0.04f, 0.04f, 0.04f);
  const hs::cardiac::HeartSimulation sim(scenario, 1);
  hs::render::SceneOptions options;
  options.speedMax = 1.0;
  const hs::render::Scene scene = hs::render::buildScene(sim, options);
  const std::size_t blood = sim.particles().size() - sim.firstBloodParticle();
  ASSERT_GT(blood, 0u);
  EXPECT_EQ(scene.particles.centres.size(), blood);
  EXPECT_FLOAT_EQ(scene.particles.radius, 0.0025f);
  for (const Vec3f& c : scene.particles.colours) EXPECT_EQ(c, hs::render::speedColour(0));  // at rest
  EXPECT_EQ(scene.lines.points.size(), 24u);  // 12 edges
  EXPECT_TRUE(scene.wall.positions.empty());
  EXPECT_TRUE(scene.bounds.max.isApprox(Vec3f(0.04f, 0.04f, 0.04f)));
}

TEST(Scene, SpeedColoursRunFromBlueToYellow) {
  const Vec3f slow = hs::render::speedColour(0), fast = hs::render::speedColour(1);
  EXPECT_GT(slow.z(), slow.x() + 0.5f);
  EXPECT_GT(fast.x(), fast.z() + 0.5f);
  EXPECT_EQ(hs::render::speedColour(-3), slow);
  EXPECT_EQ(hs::render::speedColour(7), fast);
}

TEST(Scene, DefaultSpeedScaleIsTheRoundedFreeFallSpeedOfTheBlock) {
  hs::cardiac::Scenario scenario;
  scenario.heart = false;
  scenario.blood.blockMin = hs::pbd::Vec3(0, 0, 0);
  scenario.blood.blockMax = hs::pbd::Vec3(0.05f, 0.1143f, 0.05f);  // sqrt(2 g H) = 1.50 m/s
  EXPECT_DOUBLE_EQ(hs::render::defaultSpeedScale(scenario), 1.5);
  scenario.blood.blockMax = hs::pbd::Vec3(0.05f, 0.1f, 0.05f);  // 1.40 m/s
  EXPECT_DOUBLE_EQ(hs::render::defaultSpeedScale(scenario), 1.5);
}

// With a heart the blood can fall through the whole model: apex to the vessels' far ends.
TEST(Scene, DefaultSpeedScaleWithAHeartIsTheFreeFallSpeedOfTheModel) {
  hs::cardiac::Scenario scenario;
  auto& g = scenario.geometry;
  g.endoLongAxis = 0.06f, g.wallThickness = 0.01f, g.baseThickness = 0.004f;
  g.inflowVesselLength = g.outflowVesselLength = 0.03f;  // H = 0.104 m: sqrt(2 g H) = 1.43 m/s
  EXPECT_DOUBLE_EQ(hs::render::defaultSpeedScale(scenario), 1.5);
}

// Blood the closed loop has parked outside the model (waiting to re-enter) is not drawn.
TEST(Scene, ParkedBloodIsNotDrawn) {
  hs::cardiac::Scenario scenario;
  scenario.cycle.enabled = false;
  scenario.blood.enabled = true;
  scenario.blood.start = hs::cardiac::BloodSettings::Start::Vessel;
  scenario.blood.particles = 9000;  // more than the inflow vessel and the cavity hold
  const hs::cardiac::HeartSimulation sim(scenario, 1);
  std::size_t active = 0;
  for (std::size_t i = sim.firstBloodParticle(); i < sim.particles().size(); ++i)
    active += sim.bloodActive(hs::pbd::Index(i));
  ASSERT_LT(active, 9000u);
  ASSERT_GT(active, 0u);
  EXPECT_EQ(hs::render::buildScene(sim, {}).particles.centres.size(), active);
}

// Blood coloured by where it started: the vessel start puts some in the inflow vessel and
// the rest in the ventricle; blood beyond the start sites starts outside (not drawn).
TEST(Scene, OriginColoursTellWhereTheBloodStarted) {
  hs::cardiac::Scenario scenario;
  scenario.cycle.enabled = false;
  scenario.blood.enabled = true;
  scenario.blood.start = hs::cardiac::BloodSettings::Start::Vessel;
  scenario.blood.particles = 2000;
  const hs::cardiac::HeartSimulation sim(scenario, 1);
  hs::render::SceneOptions options;
  options.bloodColour = hs::render::BloodColour::Origin;
  const hs::render::Scene scene = hs::render::buildScene(sim, options);
  const Vec3f inflow = hs::render::originColour(hs::cardiac::FlowRegion::InflowVessel);
  const Vec3f ventricle = hs::render::originColour(hs::cardiac::FlowRegion::Ventricle);
  std::size_t nInflow = 0, nVentricle = 0;
  for (const Vec3f& c : scene.particles.colours) nInflow += c == inflow, nVentricle += c == ventricle;
  EXPECT_GT(nInflow, 0u);
  EXPECT_GT(nVentricle, 0u);
  EXPECT_EQ(nInflow + nVentricle, scene.particles.colours.size());
}

// Blood coloured by component: each drawn particle takes its own identity's component (here
// the identity mod 5, every component and None), the scene's order being
// drawnBloodIdentities'; recolouring a built scene gives the same colours; no components (or a
// list of the wrong size) draws all of it neutral.
TEST(Scene, ComponentColoursFollowEachParticlesIdentity) {
  hs::cardiac::Scenario scenario;
  scenario.cycle.enabled = false;
  scenario.blood.enabled = true;
  scenario.blood.start = hs::cardiac::BloodSettings::Start::Vessel;
  scenario.blood.particles = 2000;
  const hs::cardiac::HeartSimulation sim(scenario, 1);
  using hs::cardiac::FlowComponent;
  std::vector<FlowComponent> components(sim.particles().size() - sim.firstBloodParticle());
  for (std::size_t k = 0; k < components.size(); ++k) components[k] = FlowComponent(k % 5);
  hs::render::SceneOptions options;
  options.bloodColour = hs::render::BloodColour::Components;
  options.components = &components;
  const hs::render::Scene scene = hs::render::buildScene(sim, options);
  const std::vector<std::size_t> ids = hs::render::drawnBloodIdentities(sim);
  ASSERT_EQ(ids.size(), scene.particles.colours.size());
  ASSERT_GT(ids.size(), 100u);
  std::set<std::size_t> distinct;
  for (std::size_t k = 0; k < ids.size(); ++k) {
    EXPECT_EQ(scene.particles.colours[k], hs::render::componentColour(components[ids[k]])) << k;
    distinct.insert(ids[k] % 5);
  }
  EXPECT_EQ(distinct.size(), 5u);
  options.components = nullptr;
  hs::render::Scene later = hs::render::buildScene(sim, options);
  const Vec3f none = hs::render::componentColour(FlowComponent::None);
  for (const Vec3f& c : later.particles.colours) EXPECT_EQ(c, none);
  hs::render::colourByComponent(later, ids, components);
  EXPECT_EQ(later.particles.colours, scene.particles.colours);
  std::vector<FlowComponent> tooShort(3, FlowComponent::Direct);
  options.components = &tooShort;
  for (const Vec3f& c : hs::render::buildScene(sim, options).particles.colours) EXPECT_EQ(c, none);
  // The four colours and the neutral one differ.
  std::set<std::array<float, 3>> colours;
  for (int c = 0; c < 5; ++c) {
    const Vec3f v = hs::render::componentColour(FlowComponent(c));
    colours.insert({v.x(), v.y(), v.z()});
  }
  EXPECT_EQ(colours.size(), 5u);
}

// Blood coloured by pressure: resting blood under gravity is compressed at the bottom (top
// colour with a tiny scale) and free at its surface (bottom colour).
TEST(Scene, PressureColoursFollowTheDensitySolve) {
  hs::cardiac::Scenario scenario;
  scenario.cycle.enabled = false;
  scenario.blood.enabled = true;
  scenario.blood.start = hs::cardiac::BloodSettings::Start::Chamber;
  scenario.blood.particles = 1000;
  hs::cardiac::HeartSimulation sim(scenario, 1);
  for (int k = 0; k < 100; ++k) sim.step();  // 0.5 s: the pool settles onto the apex
  hs::render::SceneOptions options;
  options.bloodColour = hs::render::BloodColour::Pressure;
  options.pressureMax = 1e-6;  // any positive pressure is at the top of the scale
  const hs::render::Scene scene = hs::render::buildScene(sim, options);
  const Vec3f top = hs::render::speedColour(1), bottom = hs::render::speedColour(0);
  std::size_t nTop = 0, nBottom = 0;
  for (const Vec3f& c : scene.particles.colours) nTop += c == top, nBottom += c == bottom;
  EXPECT_GT(nTop, 0u);
  EXPECT_GT(nBottom, 0u);
  EXPECT_GT(hs::render::defaultPressureScale(scenario), 0.0);
}

TEST(Scene, TheCutIsMadeOnlyInViewsThatLookAtIt) {
  hs::cardiac::Scenario scenario;
  const hs::cardiac::HeartSimulation sim(scenario, 1);
  hs::render::SceneOptions options;
  options.clip = true;
  hs::render::Scene scene = hs::render::buildScene(sim, options);
  hs::render::applyView(scene, options, hs::render::View::Front);
  EXPECT_TRUE(scene.clip.enabled);
  hs::render::applyView(scene, options, hs::render::View::Left);
  EXPECT_FALSE(scene.clip.enabled);
  EXPECT_EQ(scene.wall.opacity, 1.0f);  // no blood to show through the wall
}

}  // namespace

// Thesis 4.3.3 / Fig. 4.7: the region the scenario chose to beat is drawn orange; the default
// (the whole myocardium beats) singles nothing out, and an explicit highlight overrides both.
TEST(Scene, RenderTintsTheChosenBeatingRegion) {
  hs::cardiac::Scenario scenario;
  scenario.cycle.segments = {1, 2, 7};
  const hs::cardiac::HeartSimulation sim(scenario, 1);
  const auto& model = sim.model();
  const auto colourOf = [&](const hs::render::Scene& scene, std::size_t f, int k) {
    return scene.wall.colours[3 * f + k];
  };
  const hs::render::Scene chosen = hs::render::buildScene(sim, {});
  std::size_t tinted = 0;
  for (std::size_t f = 0; f < model.surface.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const auto v = model.surface[f][k];
      const Vec3f base = hs::render::regionColour(model.region[v]);
      const bool beats = model.region[v] == hs::cardiac::Region::Myocardium &&
                         (model.segment[v] == 1 || model.segment[v] == 2 || model.segment[v] == 7);
      EXPECT_EQ(colourOf(chosen, f, k), beats ? hs::render::beatingColour(base) : base) << "vertex " << v;
      tinted += beats;
    }
  EXPECT_GT(tinted, 0u);
  // Orange: clearly apart from the red myocardium, redder than green, little blue.
  const Vec3f red = hs::render::regionColour(hs::cardiac::Region::Myocardium);
  const Vec3f orange = hs::render::beatingColour(red);
  EXPECT_GT((orange - red).norm(), 0.25f);
  EXPECT_GT(orange.x(), orange.y());
  EXPECT_GT(orange.y(), orange.z() + 0.2f);

  hs::render::SceneOptions none;
  none.beating = std::vector<std::uint8_t>{};
  const hs::render::Scene plain = hs::render::buildScene(sim, none);
  for (std::size_t i = 0; i < plain.wall.colours.size(); ++i)
    EXPECT_EQ(plain.wall.colours[i], hs::render::regionColour(model.region[model.surface[i / 3][i % 3]]));

  scenario.cycle.enabled = false;  // nothing beats: nothing tinted
  const hs::cardiac::HeartSimulation resting(scenario, 1);
  EXPECT_TRUE(hs::render::chosenBeatingRegion(resting).empty());
  EXPECT_TRUE(
      hs::render::chosenBeatingRegion(hs::cardiac::HeartSimulation(hs::cardiac::Scenario{}, 1)).empty());
}

// The inconsistent pattern's out-of-step segments are drawn violet, only they, and only when
// that pattern beats; see-through blood is passed to the renderer as asked.
TEST(Scene, OutOfStepSegmentsAreVioletOnlyInTheInconsistentPattern) {
  hs::cardiac::Scenario scenario;  // thesis scale, the whole myocardium beats
  scenario.cycle.pattern = hs::cardiac::BeatPattern::Inconsistent;
  scenario.cycle.inconsistentSegments = {7, 13};
  const hs::cardiac::HeartSimulation sim(scenario, 1);
  const std::vector<std::uint8_t> flags = hs::render::outOfStepRegion(sim);
  ASSERT_EQ(flags.size(), sim.model().mesh.vertices.size());
  std::size_t marked = 0;
  for (std::size_t v = 0; v < flags.size(); ++v) {
    const int segment = sim.model().segment[v];
    EXPECT_EQ(bool(flags[v]), segment == 7 || segment == 13) << "vertex " << v;
    marked += flags[v];
  }
  EXPECT_GT(marked, 0u);
  hs::render::SceneOptions options;
  options.bloodOpacity = 0.3f;
  const hs::render::Scene scene = hs::render::buildScene(sim, options);
  const Vec3f violet = hs::render::outOfStepColour(hs::render::regionColour(hs::cardiac::Region::Myocardium));
  for (std::size_t f = 0; f < sim.model().surface.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const auto v = sim.model().surface[f][k];
      EXPECT_EQ(scene.wall.colours[3 * f + std::size_t(k)] == violet, bool(flags[v]));
    }
  options.markOutOfStep = false;
  for (const Vec3f& c : hs::render::buildScene(sim, options).wall.colours) EXPECT_NE(c, violet);

  hs::cardiac::Scenario regular = scenario;
  regular.cycle.pattern = hs::cardiac::BeatPattern::Normal;
  EXPECT_TRUE(hs::render::outOfStepRegion(hs::cardiac::HeartSimulation(regular, 1)).empty());
}

TEST(Scene, SeeThroughBloodIsPassedToTheRenderer) {
  hs::cardiac::Scenario scenario;
  scenario.blood.enabled = true;
  const hs::cardiac::HeartSimulation sim(scenario, 1);
  hs::render::SceneOptions options;
  EXPECT_EQ(hs::render::buildScene(sim, options).particles.opacity, 1.0f);
  options.bloodOpacity = 0.3f;
  const hs::render::Scene scene = hs::render::buildScene(sim, options);
  ASSERT_FALSE(scene.particles.centres.empty());
  EXPECT_EQ(scene.particles.opacity, 0.3f);
}
