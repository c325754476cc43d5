// The valves' leaflets (render/valve_leaflets.h): two mitral leaflets and three aortic cusps on
// the annulus; closed they lie across the orifice (within a dome's height of its plane), open
// they reach downstream, leaving the orifice's middle free; and in the scene they follow the
// simulation's valve states.
#include <gtest/gtest.h>

#include <cmath>

#include "cardiac/circulation.h"
#include "cardiac/heart_simulation.h"
#include "render/scene.h"
#include "render/valve_leaflets.h"

namespace {

using hs::render::ValveShape;
using hs::render::Vec3f;

ValveShape unitValve(int leaflets, bool open) {
  ValveShape v;
  v.centre = Vec3f(1, 2, 3);
  v.axis = Vec3f(0, -1, 0);  // downstream is -y, as the mitral valve's
  v.first = Vec3f(1, 0, 0);
  v.radius = 0.5f;
  v.leaflets = leaflets;
  v.open = open;
  return v;
}

// Extent of the leaflets along the axis (downstream positive) and their nearest approach to
// the axis, over all vertices.
struct Extent {
  float upstream = 0, downstream = 0, nearestToAxis = 1e9f;
};
Extent extent(const hs::render::WallMesh& mesh, const ValveShape& v) {
  Extent e;
  for (const Vec3f& p : mesh.positions) {
    const Vec3f d = p - v.centre;
    const float along = d.dot(v.axis);
    e.upstream = std::min(e.upstream, along), e.downstream = std::max(e.downstream, along);
    e.nearestToAxis = std::min(e.nearestToAxis, (d - along * v.axis).norm());
  }
  return e;
}

TEST(ValveLeaflets, ClosedTheyCloseTheOrificeOpenTheyReachDownstream) {
  for (const int leaflets : {2, 3}) {
    SCOPED_TRACE(leaflets);
    hs::render::WallMesh closed, open;
    addLeaflets(unitValve(leaflets, false), closed);
    addLeaflets(unitValve(leaflets, true), open);
    ASSERT_EQ(closed.positions.size(), open.positions.size());
    EXPECT_EQ(closed.positions.size() % (std::size_t(leaflets) * 3), 0u);
    for (const Vec3f& n : closed.normals) EXPECT_NEAR(n.norm(), 1.0f, 1e-4f);
    const Extent c = extent(closed, unitValve(leaflets, false)), o = extent(open, unitValve(leaflets, true));
    // Closed: across the orifice, up to its middle, domed upstream by at most 0.15 R + the slab.
    EXPECT_LT(c.nearestToAxis, 0.05f);
    EXPECT_GT(c.upstream, -0.5f * 0.2f);
    EXPECT_LT(c.downstream, 0.5f * 0.05f);
    // Open: swung 70 degrees downstream, the middle free (the free edge R (1 - cos 70) = 0.66 R
    // from the axis, give or take the slab's half thickness).
    EXPECT_GT(o.downstream, 0.5f * std::sin(70 * float(M_PI) / 180) * 0.95f);
    EXPECT_GT(o.nearestToAxis, 0.5f * 0.62f);
    EXPECT_LT(o.nearestToAxis, 0.5f * 0.68f);
  }
}

// Leaflets the blood meets (model.mitral_leaflet_length) are drawn where the blood meets them:
// open, straight down their length at the annulus's radius.
TEST(ValveLeaflets, HangingLeafletsAreATubeOfTheirLength) {
  ValveShape v = unitValve(2, true);
  v.length = 0.8f, v.openAngleDegrees = 90;
  hs::render::WallMesh mesh;
  addLeaflets(v, mesh);
  const Extent e = extent(mesh, v);
  EXPECT_NEAR(e.downstream, 0.8f, 0.02f);
  EXPECT_GT(e.nearestToAxis, 0.5f * 0.95f);  // the annulus's radius, give or take the slab
  ValveShape closed = v;
  closed.open = false;
  hs::render::WallMesh across;
  addLeaflets(closed, across);
  EXPECT_LT(extent(across, closed).nearestToAxis, 0.05f);  // closed, across the orifice as before
}

TEST(ValveLeaflets, TheSceneFollowsTheValvesStates) {
  hs::cardiac::Scenario scenario;  // thesis-scale heart with blood, valves by timing
  scenario.blood.enabled = true;
  hs::cardiac::HeartSimulation sim(scenario, 1);
  const hs::render::Scene scene = hs::render::buildScene(sim, {});
  ASSERT_NE(sim.circulation(), nullptr);
  const hs::cardiac::ValveStates states = sim.circulation()->valves.states();
  const hs::cardiac::FlowPath& path = sim.model().flowPath;
  // Leaflet vertices that lie downstream of each annulus by more than a third of its radius:
  // only where the valve is open.
  int mitralDown = 0, aorticDown = 0;
  for (const Vec3f& p : scene.valves.positions) {
    const hs::pbd::Vec3 q = p.cast<hs::pbd::Real>();
    if (path.mitral.radial(q) < 1.2 * path.mitral.radius && path.mitral.side(q) > path.mitral.radius / 3) ++mitralDown;
    if (path.aortic.radial(q) < 1.2 * path.aortic.radius && path.aortic.side(q) > path.aortic.radius / 3) ++aorticDown;
  }
  ASSERT_FALSE(scene.valves.positions.empty());
  EXPECT_EQ(mitralDown > 0, states.mitralOpen);
  EXPECT_EQ(aorticDown > 0, states.aorticOpen);
  hs::render::SceneOptions none;
  none.valves = false;
  EXPECT_TRUE(hs::render::buildScene(sim, none).valves.positions.empty());
}

}  // namespace
