// The E-wave filling vortex (filling_vortex.h): when it is read (each new largest mitral flow of
// a beat's early filling, kept to the peak), where the ring is read from (the long-axis cut of
// the procedural heart), and its place as a share of the long axis from the mitral plane.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cardiac/anatomy/lv_model.h"
#include "cardiac/blood/filling_vortex.h"

namespace hs::cardiac {
namespace {

EVortexView viewAt(double time) {
  EVortexView view;
  view.sample.time = time;
  view.sample.found = true;
  view.sample.position = time;
  return view;
}

TEST(FillingVortex, ReadsOnEachNewLargestEarlyFillingFlowAndKeepsThePeak) {
  FillingVortex vortex;
  EXPECT_FALSE(vortex.step(false, 0.0));  // ejection: the run has seen a beat's start
  const double flows[] = {1, 3, 5, 4, 2};
  const bool reads[] = {true, true, true, false, false};
  for (int k = 0; k < 5; ++k) {
    EXPECT_EQ(vortex.step(true, flows[k]), reads[k]) << "flow " << flows[k];
    if (reads[k]) vortex.keep(viewAt(flows[k]));
  }
  EXPECT_TRUE(vortex.beats().empty());  // still filling
  EXPECT_FALSE(vortex.step(false, 6.0));  // the atrial kick ends early filling: its flow is the A wave's
  ASSERT_EQ(vortex.beats().size(), 1u);
  EXPECT_EQ(vortex.beats()[0].beat, 1);
  EXPECT_TRUE(vortex.beats()[0].complete);
  EXPECT_EQ(vortex.beats()[0].sample.time, 5.0);
  ASSERT_TRUE(vortex.lastBeatView());
  EXPECT_EQ(vortex.lastBeatView()->sample.time, 5.0);
  // The next beat starts afresh: its first early-filling step is a new peak however small.
  EXPECT_TRUE(vortex.step(true, 0.5));
}

TEST(FillingVortex, ARunThatStartsInEarlyFillingHasAnIncompleteFirstBeat) {
  FillingVortex vortex;
  EXPECT_TRUE(vortex.step(true, 2.0));
  vortex.keep(viewAt(2.0));
  vortex.step(false, 0.0);
  vortex.step(true, 1.0);
  vortex.step(false, 0.0);
  ASSERT_EQ(vortex.beats().size(), 2u);
  EXPECT_FALSE(vortex.beats()[0].complete);
  EXPECT_TRUE(vortex.beats()[1].complete);
  EXPECT_EQ(vortex.beats()[1].beat, 2);
  // A beat read at no step (none was kept) reports no ring.
  EXPECT_FALSE(vortex.beats()[1].sample.found);
}

TEST(FillingVortex, CheckpointKeepsTheBeatsAndTheOpenPeak) {
  FillingVortex vortex;
  vortex.step(false, 0.0);
  vortex.step(true, 3.0);
  vortex.keep(viewAt(3.0));
  vortex.step(false, 0.0);
  vortex.step(true, 4.0);
  vortex.keep(viewAt(4.0));
  pbd::StateWriter w;
  vortex.save(w);
  FillingVortex loaded;
  pbd::StateReader r(w.bytes());
  loaded.load(r);
  ASSERT_EQ(loaded.beats().size(), 1u);
  EXPECT_EQ(loaded.beats()[0].sample.time, 3.0);
  // The open beat's peak survives: a smaller flow is no new peak, and the beat closes with it.
  EXPECT_FALSE(loaded.step(true, 3.5));
  loaded.step(false, 0.0);
  ASSERT_EQ(loaded.beats().size(), 2u);
  EXPECT_EQ(loaded.beats()[1].sample.time, 4.0);
}

// The procedural heart at rest: the cut holds the long axis (y) and the mitral orifice (x < 0),
// so `across` is +x; the long axis runs from the base plane (y = 0) to the endocardial apex
// (y = -endoLongAxis).
TEST(FillingVortex, LongAxisCutOfTheProceduralHeart) {
  const LvModel model = buildLvModel({});
  const LongAxisCut cut = longAxisCut(model, model.flowPath, model.mesh.vertices);
  EXPECT_NEAR(cut.across.x(), 1.0, 1e-9);
  EXPECT_NEAR(cut.down.y(), -1.0, 1e-12);
  EXPECT_NEAR(cut.longAxis, double(model.params.endoLongAxis), 0.02 * double(model.params.endoLongAxis));
  const pbd::PlaneGrid grid = longAxisGrid(cut, model, model.mesh.vertices, 0.05);
  // The grid spans the cavity: from above the mitral plane to below the apex, wall to wall.
  EXPECT_LT(cut.depth(grid.origin), 0);
  EXPECT_GT(cut.depth(grid.node(0, grid.rows - 1)), cut.longAxis);
  EXPECT_LT(grid.origin.x(), -double(model.params.endoRadius) + 0.05);
  EXPECT_GT(grid.node(grid.columns - 1, 0).x(), double(model.params.endoRadius) - 0.05);
}

// Two cores of opposite sign 15 mm below the mitral plane of a 60 mm ventricle: the ring sits at
// a quarter of the long axis; a stronger core above the mitral plane (in the orifice) is not it.
TEST(FillingVortex, RingPositionIsTheCoresDepthOverTheLongAxis) {
  LongAxisCut cut;
  cut.mitralCentre = Vec3d(-0.01, 0, 0);
  cut.axisAtMitralPlane = Vec3d::Zero();
  cut.across = Vec3d::UnitX();
  cut.longAxis = 0.060;
  pbd::PlaneField field;
  pbd::PlaneGrid& g = field.grid;
  g.spacing = 0.001;
  g.u = cut.across;
  g.v = cut.down;
  g.origin = Vec3d(-0.04, 0.01, 0);  // 10 mm above the mitral plane
  g.columns = 81;
  g.rows = 81;
  field.vu.assign(g.size(), 0.0);
  field.vv.assign(g.size(), 0.0);
  field.fill.assign(g.size(), 1.0);
  field.filled.assign(g.size(), 1);
  // Lamb-Oseen cores (rc 4 mm) in the cut's (u, v) coordinates: +0.02 at u = -5 mm, -0.02 at
  // u = +5 mm, both at depth 15 mm; +0.05 at depth -6 mm (above the plane).
  const auto core = [](double gamma, double u0, double v0, double u, double v, double& vu, double& vv) {
    const double du = u - u0, dv = v - v0, r2 = du * du + dv * dv;
    if (r2 < 1e-14) return;
    const double f = gamma / (2 * std::numbers::pi * r2) * (1 - std::exp(-r2 / 16e-6));
    vu += -f * dv;
    vv += f * du;
  };
  for (int j = 0; j < g.rows; ++j)
    for (int i = 0; i < g.columns; ++i) {
      const Vec3d x = g.node(i, j);
      const double u = cut.across.dot(x - cut.mitralCentre), v = cut.depth(x);
      double& vu = field.vu[g.index(i, j)];
      double& vv = field.vv[g.index(i, j)];
      core(0.02, -0.005, 0.015, u, v, vu, vv);
      core(-0.02, 0.005, 0.015, u, v, vu, vv);
      core(0.05, 0.015, -0.006, u, v, vu, vv);
    }
  const EVortexView view = readEVortex(cut, field, 0.4, 500e-6);
  ASSERT_TRUE(view.sample.found);
  ASSERT_GE(view.ring[0], 0);
  ASSERT_GE(view.ring[1], 0);
  EXPECT_NEAR(view.sample.depth, 0.015, 0.001);
  EXPECT_NEAR(view.sample.position, 0.25, 0.02);
  EXPECT_NEAR(view.sample.coreDepth[0], 0.015, 0.001);
  EXPECT_NEAR(view.sample.coreDepth[1], 0.015, 0.001);
  // Half of each core's 0.02 m^2/s (vortex_cores.h).
  EXPECT_NEAR(view.sample.circulation, 0.01, 0.001);
  EXPECT_EQ(view.sample.time, 0.4);
}

// A weak eddy deep in the cavity is not the ring's other side: the ring is the strong core alone.
TEST(FillingVortex, AWeakPartnerIsNotTheRing) {
  LongAxisCut cut;
  cut.mitralCentre = Vec3d::Zero();
  cut.axisAtMitralPlane = Vec3d(0.01, 0, 0);
  cut.longAxis = 0.060;
  pbd::PlaneField field;
  pbd::PlaneGrid& g = field.grid;
  g.spacing = 0.001;
  g.u = cut.across;
  g.v = cut.down;
  g.origin = Vec3d(-0.04, 0.005, 0);
  g.columns = g.rows = 81;
  field.vu.assign(g.size(), 0.0);
  field.vv.assign(g.size(), 0.0);
  field.fill.assign(g.size(), 1.0);
  field.filled.assign(g.size(), 1);
  const auto add = [&](double gamma, double u0, double v0) {
    for (int j = 0; j < g.rows; ++j)
      for (int i = 0; i < g.columns; ++i) {
        const Vec3d x = g.node(i, j);
        const double du = cut.across.dot(x - cut.mitralCentre) - u0, dv = cut.depth(x) - v0, r2 = du * du + dv * dv;
        if (r2 < 1e-14) continue;
        const double f = gamma / (2 * std::numbers::pi * r2) * (1 - std::exp(-r2 / 16e-6));
        field.vu[g.index(i, j)] += -f * dv;
        field.vv[g.index(i, j)] += f * du;
      }
  };
  add(0.02, 0.0, 0.006);     // the ring's core, 6 mm deep
  add(-0.002, 0.01, 0.045);  // an eddy a tenth as strong, 45 mm deep
  const EVortexView view = readEVortex(cut, field, 0.4, 500e-6);
  ASSERT_TRUE(view.sample.found);
  EXPECT_GE(view.ring[0], 0);
  EXPECT_EQ(view.ring[1], -1);
  EXPECT_NEAR(view.sample.depth, 0.006, 0.001);
  EXPECT_NEAR(view.sample.circulation, 0.01, 0.001);
  EXPECT_EQ(view.sample.coreCirculation[1], 0.0);
}

}  // namespace
}  // namespace hs::cardiac
