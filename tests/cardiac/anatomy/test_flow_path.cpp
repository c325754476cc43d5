// The flow path's geometry (flow_path.h) on the thesis-scale LV model: the orifices sit where
// the vessels meet the cavity, and classify() puts every point in the region it is in.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <tuple>

#include "cardiac/anatomy/lv_model.h"
#include "cardiac/scenario.h"
#include "thesis_model.h"

namespace hs::cardiac {
namespace {

const LvModel& model() { return testing::thesisModel(); }

const FlowPath& path() { return model().flowPath; }

// The blood's radius and spacing, as the flow meter passes them.
const BloodSettings kBlood{};
FlowRegion regionOf(const Vec3& x) { return path().classify(x, kBlood.radius, kBlood.spacing); }

Vec3 ringCentroid(const std::vector<Index>& ring) {
  Vec3 c = Vec3::Zero();
  for (Index v : ring) c += model().mesh.vertices[v];
  return c / Real(ring.size());
}

TEST(FlowPath, OrificesLieInTheBasePlaneAtTheRingCentroids) {
  const LvGeometryParams g;
  for (const auto& [orifice, ring, radius] :
       {std::tuple{path().mitral, model().mitralRing, g.mitralRadius},
        std::tuple{path().aortic, model().aorticRing, g.aorticRadius}}) {
    EXPECT_NEAR(orifice.centre.y(), 0, 1e-5);  // the base plate's cavity side
    EXPECT_LT((orifice.centre - ringCentroid(ring)).norm(), Real(1e-5));
    EXPECT_FLOAT_EQ(orifice.radius, radius);
    EXPECT_NEAR(orifice.forward.norm(), 1, 1e-6);
    // The ring is the lumen's rim: its vertices lie on the disc's plane, about a radius out.
    for (Index v : ring) {
      const Vec3& x = model().mesh.vertices[v];
      EXPECT_NEAR(orifice.side(x), 0, 1e-4);
      EXPECT_NEAR(orifice.radial(x), radius, Real(0.05) * radius);
    }
  }
  // Blood flows down into the cavity through the mitral disc and up out of it through the
  // aortic; the inflow sits on the viewer's left (-x), and the discs do not overlap.
  EXPECT_LT(path().mitral.forward.y(), Real(-0.999));
  EXPECT_GT(path().aortic.forward.y(), Real(0.999));
  EXPECT_LT(path().mitral.centre.x(), 0);
  EXPECT_GT(path().aortic.centre.x(), 0);
  EXPECT_GT((path().mitral.centre - path().aortic.centre).norm(), g.mitralRadius + g.aorticRadius);
}

TEST(FlowPath, VesselEndsAreTheBasePlateAndVesselLengthsAbove) {
  const LvGeometryParams g;
  EXPECT_NEAR(path().inflowTop, g.baseThickness + g.inflowVesselLength, 1e-5);
  EXPECT_NEAR(path().outflowTop, g.baseThickness + g.outflowVesselLength, 1e-5);
  EXPECT_NEAR(path().inflowLength, path().inflowTop - path().mitral.centre.y(), 1e-5);
  EXPECT_GT(path().inflowLength, 0);
  // The far rings of the vessels are pinned at their ends.
  Real pinnedTop = 0;
  for (Index v : model().pinned) pinnedTop = std::max(pinnedTop, model().mesh.vertices[v].y());
  EXPECT_NEAR(pinnedTop, std::max(path().inflowTop, path().outflowTop), 1e-4);
}

TEST(FlowPath, JustBelowAndAboveTheDiscs) {
  const Vec3 up = Vec3::UnitY();
  const Real d = Real(0.05);
  EXPECT_EQ(regionOf(path().mitral.centre - d * up), FlowRegion::Ventricle);
  EXPECT_EQ(regionOf(path().mitral.centre + d * up), FlowRegion::InflowVessel);
  EXPECT_EQ(regionOf(path().aortic.centre - d * up), FlowRegion::Ventricle);
  EXPECT_EQ(regionOf(path().aortic.centre + d * up), FlowRegion::OutflowVessel);
}

TEST(FlowPath, AlongEachVesselAxisUpToItsEnd) {
  const Vec3 up = Vec3::UnitY();
  for (Real y = Real(0.02); y < path().inflowTop; y += Real(0.1))
    EXPECT_EQ(regionOf(path().mitral.centre + y * up), FlowRegion::InflowVessel) << "y " << y;
  for (Real y = Real(0.02); y < path().outflowTop; y += Real(0.1))
    EXPECT_EQ(regionOf(path().aortic.centre + y * up), FlowRegion::OutflowVessel) << "y " << y;
  // Within endSlack past the far end still inside; beyond it outside.
  const Vec3 inflowEnd(path().mitral.centre.x(), path().inflowTop, path().mitral.centre.z());
  EXPECT_EQ(regionOf(inflowEnd + Real(0.5) * kBlood.spacing * up), FlowRegion::InflowVessel);
  EXPECT_EQ(regionOf(inflowEnd + 2 * kBlood.spacing * up), FlowRegion::Outside);
}

TEST(FlowPath, LumenSlackCountsParticlesTouchingTheVesselWall) {
  const Orifice& m = path().mitral;
  const Vec3 sideways = Vec3::UnitZ();  // across the lumen, away from the other vessel
  const Vec3 mid = m.centre + Real(1.0) * Vec3::UnitY();
  EXPECT_EQ(regionOf(mid + (m.radius + Real(0.5) * kBlood.radius) * sideways), FlowRegion::InflowVessel);
  EXPECT_EQ(regionOf(mid + (m.radius + 2 * kBlood.radius) * sideways), FlowRegion::Outside);
  // Without slack the same point is outside.
  EXPECT_EQ(path().classify(mid + (m.radius + Real(0.5) * kBlood.radius) * sideways, 0, 0),
            FlowRegion::Outside);
}

TEST(FlowPath, BeyondTheWallAndFarAwayIsOutside) {
  const LvGeometryParams g;
  const Real epi = g.endoRadius + g.wallThickness;
  const Real epiApex = g.endoLongAxis + g.wallThickness;
  EXPECT_EQ(regionOf(Vec3(0, -g.endoLongAxis + Real(0.1), 0)), FlowRegion::Ventricle);  // inside the apex
  EXPECT_EQ(regionOf(Vec3(0, -epiApex - Real(0.1), 0)), FlowRegion::Outside);           // below it
  EXPECT_EQ(regionOf(Vec3(epi + Real(0.1), Real(-0.5), 0)), FlowRegion::Outside);       // beside it
  EXPECT_EQ(regionOf(Vec3(0, Real(-0.5), -epi - Real(0.1))), FlowRegion::Outside);
  // In the base plate between the orifices, and between the vessels above it.
  const Real between = Real(0.5) * (path().mitral.centre.x() + path().mitral.radius +
                                    path().aortic.centre.x() - path().aortic.radius);
  EXPECT_EQ(regionOf(Vec3(between, Real(0.25), 0)), FlowRegion::Outside);
  EXPECT_EQ(regionOf(Vec3(between, Real(1.0), 0)), FlowRegion::Outside);
  EXPECT_EQ(regionOf(Vec3(100, 100, 100)), FlowRegion::Outside);
  EXPECT_EQ(regionOf(Vec3(0, -100, 0)), FlowRegion::Outside);
}

TEST(FlowPath, NonFinitePointsAreOutside) {
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  const Real inf = std::numeric_limits<Real>::infinity();
  EXPECT_EQ(regionOf(Vec3(nan, nan, nan)), FlowRegion::Outside);
  EXPECT_EQ(regionOf(Vec3(path().mitral.centre.x(), nan, path().mitral.centre.z())), FlowRegion::Outside);
  EXPECT_EQ(regionOf(Vec3(0, -inf, 0)), FlowRegion::Outside);
}

// The mid-wall surface separates the wall's two layers: the endocardial vertices (inner
// layer, 2i) of the myocardium are in the ventricle, the epicardial ones (2i+1) outside.
TEST(FlowPath, MyocardiumInnerLayerIsInsideOuterLayerOutside) {
  std::size_t checked = 0;
  for (std::size_t v = 0; v < model().mesh.vertices.size(); ++v) {
    if (model().region[v] != Region::Myocardium) continue;
    const FlowRegion expected = v % 2 == 0 ? FlowRegion::Ventricle : FlowRegion::Outside;
    EXPECT_EQ(path().classify(model().mesh.vertices[v], 0, 0), expected) << "vertex " << v;
    ++checked;
  }
  EXPECT_GT(checked, 100u);
}

TEST(FlowPath, NeverParked) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(-6, 6);
  std::size_t seen[kFlowRegionCount] = {};
  for (int k = 0; k < 20000; ++k) {
    const FlowRegion r = regionOf(Vec3(u(rng), u(rng), u(rng)));
    ASSERT_NE(r, FlowRegion::Parked);
    ++seen[std::size_t(r)];
  }
  // The random points reached every other region.
  EXPECT_GT(seen[std::size_t(FlowRegion::Ventricle)], 0u);
  EXPECT_GT(seen[std::size_t(FlowRegion::InflowVessel)], 0u);
  EXPECT_GT(seen[std::size_t(FlowRegion::OutflowVessel)], 0u);
  EXPECT_GT(seen[std::size_t(FlowRegion::Outside)], 0u);
}

TEST(FlowPath, PastTheVesselEnds) {
  const Real slack = kBlood.spacing;
  const Vec3 up = Vec3::UnitY();
  const Vec3 inflowEnd(path().mitral.centre.x(), path().inflowTop, path().mitral.centre.z());
  const Vec3 outflowEnd(path().aortic.centre.x(), path().outflowTop, path().aortic.centre.z());
  EXPECT_TRUE(path().pastInflowEnd(inflowEnd + Real(0.01) * up, slack));
  EXPECT_FALSE(path().pastInflowEnd(inflowEnd - Real(0.01) * up, slack));
  EXPECT_FALSE(path().pastOutflowEnd(inflowEnd + Real(0.01) * up, slack));
  EXPECT_TRUE(path().pastOutflowEnd(outflowEnd + Real(0.01) * up, slack));
  EXPECT_FALSE(path().pastOutflowEnd(outflowEnd - Real(0.01) * up, slack));
  EXPECT_FALSE(path().pastInflowEnd(outflowEnd + Real(0.01) * up, slack));
  // Within the slack of the lumen's cylinder, not beyond it.
  const Vec3 across = Vec3::UnitZ();
  const Vec3 rim = inflowEnd + Real(0.5) * up + path().mitral.radius * across;
  EXPECT_TRUE(path().pastInflowEnd(rim + Real(0.5) * slack * across, slack));
  EXPECT_FALSE(path().pastInflowEnd(rim + 2 * slack * across, slack));
}

}  // namespace
}  // namespace hs::cardiac
