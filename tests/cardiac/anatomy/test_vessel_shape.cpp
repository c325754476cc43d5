// An anatomical heart's vessels (vessel_shape.h): the aortic root bulging into three sinuses, the
// inflow widening into an atrium, both leaning apart. The mesh, the flow path (which region blood
// is in) and the first sites of blood read the same shape; the anatomy's figures measure it; bad
// sizes are refused with the key and the reason.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "cardiac/anatomy/lv_anatomy.h"
#include "cardiac/anatomy/lv_model.h"
#include "cardiac/blood/vessel_ends.h"
#include "cardiac/heart_sites.h"
#include "cardiac/motion/volume_driven_wall.h"
#include "cardiac/scenario.h"
#include "normal_geometry.h"

namespace hs::cardiac {
namespace {

using testing::normalGeometry;

constexpr double kPi = std::numbers::pi;

// normal's sizes: a 32 mm root, a 40 mm atrium and both vessels leaning 40 degrees.
LvGeometryParams anatomicalGeometry() { return normalGeometry(); }
LvGeometryParams straightGeometry() { return testing::withStraightVessels(normalGeometry()); }

const LvModel& anatomicalModel() {
  static const LvModel model = buildLvModel(anatomicalGeometry());
  return model;
}

// normal's sizes and blood (3.6 mm apart, 1.8 mm radius, 7.2 mm support).
Scenario anatomicalScenario() {
  Scenario scenario;
  scenario.geometry = anatomicalGeometry();
  scenario.blood.radius = Real(0.0018);
  scenario.blood.spacing = Real(0.0036);
  scenario.blood.supportRadius = Real(0.0072);
  return scenario;
}

std::string buildError(const LvGeometryParams& g) {
  try {
    (void)buildLvModel(g);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(VesselShape, StraightWithoutTheShapeKeys) {
  const LvModel model = buildLvModel(straightGeometry());
  EXPECT_TRUE(model.flowPath.inflowShape.straight());
  EXPECT_TRUE(model.flowPath.outflowShape.straight());
  // The far ends' discs are the orifices' own.
  EXPECT_EQ(model.flowPath.inflowEnd().centre, model.flowPath.mitral.centre);
  EXPECT_EQ(model.flowPath.outflowEnd().radius, model.flowPath.aortic.radius);
}

TEST(VesselShape, TheProfileRisesFromTheOrificeAndLeansSmoothly) {
  VesselShape s;
  s.offset = 0.01;
  s.bendFrom = 0.2;
  s.bendEnd = 0.6;
  s.bulgeRadius = 0.02;
  s.bulgeFrom = 0.2;
  s.bulgeTo = 0.8;
  s.lobes = 3;
  EXPECT_EQ(s.shift(0.1), 0);
  EXPECT_NEAR(s.shift(0.4), 0.005, 1e-12);  // halfway through the bend, half the offset
  EXPECT_EQ(s.shift(0.9), 0.01);
  EXPECT_EQ(s.radius(0.1, 0, 0.01), 0.01);           // below the bulge: the orifice's radius
  EXPECT_NEAR(s.radius(0.5, 0, 0.01), 0.02, 1e-12);  // a lobe's centre at the widest
  EXPECT_NEAR(s.radius(0.5, kPi / 3, 0.01), 0.01, 1e-12);  // a commissure
  EXPECT_NEAR(s.maxRadius(0.5, 0.01), 0.02, 1e-12);
  // The lean's slope is continuous: no kink where it begins or ends.
  const double e = 1e-6;
  EXPECT_NEAR((s.shift(0.2 + e) - s.shift(0.2)) / e, 0, 1e-4);
  EXPECT_NEAR((s.shift(0.6) - s.shift(0.6 - e)) / e, 0, 1e-4);
}

TEST(VesselShape, TheRootBulgesIntoThreeSinusesAndTheAtriumWidens) {
  const LvModel& model = anatomicalModel();
  const FlowPath& path = model.flowPath;
  const AnatomyFigures f = measureAnatomy(model);
  ASSERT_TRUE(f.aorticRootDiameter.has_value());
  // The rings sample the lobes: the widest ring vertex lies near, never beyond, the set 32 mm.
  EXPECT_GT(*f.aorticRootDiameter, 0.95 * 0.032);
  EXPECT_LE(*f.aorticRootDiameter, 0.032 * (1 + 1e-5));
  // Each lumen vertex above the orifice lies on its shape: the flow path's section (the axis
  // there) and the shape's radius at its azimuth, for the mesh and the flow path agree.
  double widestAtrium = 0;
  for (std::size_t v = 0; v < model.mesh.vertices.size(); v += 2) {
    const bool inflow = model.region[v] == Region::InflowVessel;
    if (!inflow && model.region[v] != Region::OutflowVessel) continue;
    const Vec3& x = model.mesh.vertices[v];
    const Orifice section = inflow ? path.inflowSection(x.y()) : path.outflowSection(x.y());
    const Orifice& orifice = inflow ? path.mitral : path.aortic;
    const VesselShape& shape = inflow ? path.inflowShape : path.outflowShape;
    const double u = FlowPath::heightShare(orifice, inflow ? path.inflowTop : path.outflowTop, x.y());
    const Vec3 off = x - section.centre;
    const double expected = shape.radius(u, std::atan2(double(off.z()), double(off.x())), double(orifice.radius));
    EXPECT_NEAR(std::hypot(double(off.x()), double(off.z())), expected, 2e-5) << "vertex " << v;
    if (inflow) widestAtrium = std::max(widestAtrium, std::hypot(double(off.x()), double(off.z())));
  }
  EXPECT_GT(widestAtrium, 0.95 * 0.020);
  // The sinuses' commissure faces the mitral side: toward it the root keeps the annulus's radius.
  EXPECT_NEAR(path.outflowShape.radius(0.3, kPi, double(path.aortic.radius)), double(path.aortic.radius), 1e-9);
  // The vessels lean apart: the far ends' axes are each shape's offset farther apart than the
  // orifices', more than a centimetre in all.
  const double spread = double(path.outflowEnd().centre.x() - path.inflowEnd().centre.x()) -
                        double(path.aortic.centre.x() - path.mitral.centre.x());
  EXPECT_NEAR(spread, path.inflowShape.offset + path.outflowShape.offset, 1e-6);
  EXPECT_GT(spread, 0.01);
}

TEST(VesselShape, TheFlowPathFindsBloodInTheSinusesAndTheAtrium) {
  const FlowPath& path = anatomicalModel().flowPath;
  const Real slack = Real(0.0018), endSlack = Real(0.0036);
  // Where each bulge is widest: a point at 90% of its radius there, beyond the orifice's radius.
  auto widest = [](const VesselShape& s) { return 0.5 * (s.bulgeFrom + s.bulgeTo); };
  const double uRoot = widest(path.outflowShape), uAtrium = widest(path.inflowShape);
  const Real yRoot = path.aortic.centre.y() + Real(uRoot) * (path.outflowTop - path.aortic.centre.y());
  const Real yAtrium = path.mitral.centre.y() + Real(uAtrium) * (path.inflowTop - path.mitral.centre.y());
  const Orifice root = path.outflowSection(yRoot), atrium = path.inflowSection(yAtrium);
  const Vec3 inSinus = root.centre + Vec3(Real(0.9) * root.radius, yRoot - root.centre.y(), 0);
  const Vec3 inAtrium = atrium.centre + Vec3(0, yAtrium - atrium.centre.y(), Real(0.9) * atrium.radius);
  ASSERT_GT(path.aortic.radial(inSinus) - path.aortic.radius, Real(0.003)) << "beyond a straight root";
  EXPECT_EQ(path.classify(inSinus, slack, endSlack), FlowRegion::OutflowVessel);
  EXPECT_EQ(path.classify(inAtrium, slack, endSlack), FlowRegion::InflowVessel);
  // Beyond the walls: outside.
  const Vec3 pastRoot = root.centre + Vec3(root.radius + Real(0.006), yRoot - root.centre.y(), 0);
  const Vec3 pastAtrium = atrium.centre + Vec3(0, yAtrium - atrium.centre.y(), atrium.radius + Real(0.006));
  EXPECT_EQ(path.classify(pastRoot, slack, endSlack), FlowRegion::Outside);
  EXPECT_EQ(path.classify(pastAtrium, slack, endSlack), FlowRegion::Outside);
  // Past the far ends, on their own (shifted) axes.
  EXPECT_TRUE(path.pastOutflowEnd(path.outflowEnd().centre + Vec3(0, path.outflowTop + Real(0.001), 0), 0));
  EXPECT_TRUE(path.pastInflowEnd(path.inflowEnd().centre + Vec3(0, path.inflowTop + Real(0.001), 0), 0));
}

TEST(VesselShape, TheFirstBloodFillsTheBulgesInsideTheirWalls) {
  const Scenario scenario = anatomicalScenario();
  const LvModel& model = anatomicalModel();
  const VesselSites shaped = vesselSites(scenario, model);
  Scenario straightScenario = scenario;
  straightScenario.geometry = straightGeometry();
  const VesselSites straight = vesselSites(straightScenario, buildLvModel(straightScenario.geometry));
  // The atrium holds (20 / 12.5)^2 = 2.6 times as much blood where it is widest, a third more over
  // the whole inflow (646 -> 858 sites); the sinuses' lobes a little more than a straight root.
  EXPECT_GT(shaped.inflow.size(), straight.inflow.size() * 6 / 5);
  EXPECT_GT(shaped.outflow.size(), straight.outflow.size() * 51 / 50);
  // Every site a particle radius inside its lumen, at its own azimuth.
  const FlowPath& path = model.flowPath;
  for (const bool inflow : {true, false}) {
    const std::vector<Vec3>& sites = inflow ? shaped.inflow : shaped.outflow;
    const Orifice& orifice = inflow ? path.mitral : path.aortic;
    const VesselShape& shape = inflow ? path.inflowShape : path.outflowShape;
    const Real top = inflow ? path.inflowTop : path.outflowTop;
    for (const Vec3& p : sites) {
      const Orifice section = inflow ? path.inflowSection(p.y()) : path.outflowSection(p.y());
      const Vec3 off = p - section.centre;
      const double lumen = shape.radius(FlowPath::heightShare(orifice, top, p.y()),
                                        std::atan2(double(off.z()), double(off.x())), double(orifice.radius));
      EXPECT_LE(std::hypot(double(off.x()), double(off.z())), lumen - double(scenario.blood.radius) + 1e-6);
      EXPECT_EQ(path.classify(p, 0, 0), inflow ? FlowRegion::InflowVessel : FlowRegion::OutflowVessel);
    }
  }
}

// A vessel stretched by the descending base (its vertices carried by a share 1 - u of the
// descent) gains w A_mean: the shape's mean section, against its closed form. With B = sin^2 over
// a share s of the height (int B = s / 2, int B^2 = 3 s / 8), k = R_bulge / R - 1 and L the lobes'
// weight (a round bulb 1; the sinuses' (1 + cos 3 th) / 2: mean 1/2, mean square 3/8):
//   A_mean / pi R^2 = 1 + 2 k (s / 2) mean(L) + k^2 (3 s / 8) mean(L^2).
TEST(VesselShape, AStretchedVesselTakesInItsMeanSectionTimesTheDescent) {
  const FlowPath& path = anatomicalModel().flowPath;
  auto closedForm = [](const VesselShape& v, double R, double meanL, double meanL2) {
    const double k = v.bulgeRadius / R - 1, share = v.bulgeTo - v.bulgeFrom;
    return 1 + 2 * k * (share / 2) * meanL + k * k * (3 * share / 8) * meanL2;
  };
  const double atrium = path.inflowShape.meanAreaShare(double(path.mitral.radius));
  const double root = path.outflowShape.meanAreaShare(double(path.aortic.radius));
  EXPECT_NEAR(atrium, closedForm(path.inflowShape, double(path.mitral.radius), 1, 1), 1e-4);
  EXPECT_NEAR(root, closedForm(path.outflowShape, double(path.aortic.radius), 0.5, 0.375), 1e-4);
  EXPECT_GT(atrium, 1.3);
  EXPECT_EQ(buildLvModel(straightGeometry()).flowPath.inflowShape.meanAreaShare(0.012), 1.0);
  // The ends pass it on: the inflow's plug moves in at Q / A + w A_mean / A, the outflow's out
  // at Q / A - w A_mean / A.
  VesselEnds ends(path, anatomicalScenario().blood);
  const double w = 0.05;
  ends.setFlows(0, 0, w);
  EXPECT_NEAR(double(ends.inflowSpeed()), w * atrium, 1e-6);
}

// One site per d^2 of the lumen in every layer, the sinuses' lobes and the atrium's bulb
// included, as in a straight vessel: a layer that held fewer would leave a gap at the wall that
// the blood spreads into, emptying the lumen's core in the first steps.
TEST(VesselShape, EveryLayerOfTheBulgesStartsAtRestDensity) {
  const Scenario scenario = anatomicalScenario();
  const double d = double(scenario.blood.spacing);
  const LvModel& model = anatomicalModel();
  const FlowPath& path = model.flowPath;
  const VesselSites sites = vesselSites(scenario, model);
  int layersChecked = 0;
  for (const bool inflow : {true, false}) {
    const std::vector<Vec3>& column = inflow ? sites.inflow : sites.outflow;
    const Orifice& orifice = inflow ? path.mitral : path.aortic;
    const VesselShape& shape = inflow ? path.inflowShape : path.outflowShape;
    const Real top = inflow ? path.inflowTop : path.outflowTop;
    for (std::size_t first = 0; first < column.size();) {
      std::size_t end = first;
      while (end < column.size() && column[end].y() == column[first].y()) ++end;
      const double u = FlowPath::heightShare(orifice, top, column[first].y());
      if (shape.bulge(u) > 0.5) {
        double area = 0;  // int r(th)^2 / 2 dth
        for (int j = 0; j < 3600; ++j)
          area += 0.5 * std::pow(shape.radius(u, 2 * kPi * (j + 0.5) / 3600, double(orifice.radius)), 2) * 2 * kPi / 3600;
        const double held = double(end - first), expected = area / (d * d);
        EXPECT_GT(held, 0.9 * expected) << (inflow ? "atrium" : "root") << " layer at u = " << u;
        EXPECT_LT(held, 1.15 * expected) << (inflow ? "atrium" : "root") << " layer at u = " << u;
        ++layersChecked;
      }
      first = end;
    }
  }
  EXPECT_GE(layersChecked, 6);
}

// The fill is measured where the lumen is now: with the base descended the vessels are
// stretched, and sites taken at rest in a bulge would lie in its wall (or in the narrower vessel
// above it); carried with the stretch they stay in the lumen.
TEST(VesselShape, TheFillIsMeasuredWhereTheBaseHasCarriedTheLumen) {
  const Scenario scenario = anatomicalScenario();
  const LvModel& model = anatomicalModel();
  const VesselSites rest = vesselSites(scenario, model);
  const Real descent = Real(0.015);  // an adult's base descends 12-15 mm in systole
  const VesselSites moved = rest.descended(model.flowPath, descent);
  const FlowPath low = model.flowPath.descended(descent);
  std::size_t restOutside = 0;
  for (const bool inflow : {true, false}) {
    const FlowRegion region = inflow ? FlowRegion::InflowVessel : FlowRegion::OutflowVessel;
    const std::vector<Vec3>& now = inflow ? moved.inflow : moved.outflow;
    const std::vector<Vec3>& before = inflow ? rest.inflow : rest.outflow;
    for (std::size_t k = 0; k < now.size(); ++k) {
      EXPECT_EQ(low.classify(now[k], 0, 0), region) << "site " << k;
      restOutside += low.classify(before[k], 0, 0) != region;
    }
  }
  EXPECT_GT(restOutside, 20u) << "sites left at rest would read the wall as empty lumen";
}

TEST(VesselShape, BadSizesAreRefusedWithTheKeyAndTheReason) {
  LvGeometryParams g = anatomicalGeometry();
  g.aorticSinusRadius = Real(0.009);
  EXPECT_NE(buildError(g).find("model.aortic_sinus_radius: must be 0 (a straight root) or within"), std::string::npos)
      << buildError(g);
  g = anatomicalGeometry();
  g.atriumRadius = Real(0.05);
  EXPECT_NE(buildError(g).find("model.atrium_radius: must be 0 (no atrium) or within"), std::string::npos)
      << buildError(g);
  g = anatomicalGeometry();
  g.vesselLeanDeg = Real(41);
  EXPECT_NE(buildError(g).find("model.vessel_lean_deg: must be within [0, 40]"), std::string::npos) << buildError(g);
  g = anatomicalGeometry();
  g.atriumRadius = Real(-0.01);
  EXPECT_NE(buildError(g).find("model.atrium_radius: must be 0 (none) or positive"), std::string::npos)
      << buildError(g);
  g = anatomicalGeometry();
  g.mitralLeafletLength = Real(-0.01);
  EXPECT_NE(buildError(g).find("model.mitral_leaflet_length: must be 0 (none) or positive"), std::string::npos)
      << buildError(g);
  g.mitralLeafletLength = g.endoLongAxis;  // leaflets reaching the apex
  EXPECT_NE(buildError(g).find("model.mitral_leaflet_length: must be within [0, 0.5 x model.endo_long_axis]"),
            std::string::npos)
      << buildError(g);
  // Upright vessels with both bulges would meet above the base: refused, with where.
  g = anatomicalGeometry();
  g.vesselLeanDeg = 0;
  const std::string clash = buildError(g);
  EXPECT_NE(clash.find("would come within a vessel wall of each other"), std::string::npos) << clash;
  EXPECT_NE(clash.find("m above the base"), std::string::npos) << clash;
  EXPECT_NE(clash.find("model.vessel_lean_deg"), std::string::npos) << clash;
}

}  // namespace
}  // namespace hs::cardiac
