#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cardiac/anatomy/lv_anatomy.h"
#include "normal_geometry.h"

namespace hs::cardiac {
namespace {

// normal's sizes with straight vessels: the root's diameter is the annulus's.
LvGeometryParams normalGeometry() { return testing::withStraightVessels(testing::normalGeometry()); }

// A ring of N vertices on its lumen's circle encloses the regular N-gon's area,
// N/2 r^2 sin(2 pi / N): a little below the disc's (4.72 cm^2 for normal's 4.91 cm^2 mitral).
double inscribedArea(std::size_t n, Real radius) {
  return 0.5 * double(n) * double(radius * radius) * std::sin(2 * std::numbers::pi / double(n));
}

TEST(LvAnatomy, MeasuresTheProceduralHeartsSizesOnItsMesh) {
  const LvGeometryParams g = normalGeometry();
  const LvModel model = buildLvModel(g);
  const AnatomyFigures f = measureAnatomy(model);
  EXPECT_NEAR(f.mitralArea, inscribedArea(model.mitralRing.size(), g.mitralRadius), 1e-3 * f.mitralArea);
  EXPECT_NEAR(f.aorticArea, inscribedArea(model.aorticRing.size(), g.aorticRadius), 1e-3 * f.aorticArea);
  ASSERT_TRUE(f.aorticRootDiameter.has_value());
  EXPECT_NEAR(*f.aorticRootDiameter, 2 * double(g.aorticRadius), 1e-4);  // a straight tube
  EXPECT_NEAR(f.longAxis, double(g.endoLongAxis), 1e-4);                 // base plane to apex
}

TEST(LvAnatomy, FollowsTheMeshNotItsParameters) {
  const LvGeometryParams g = normalGeometry();
  LvModel model = buildLvModel(g);
  const AnatomyFigures before = measureAnatomy(model);
  for (Vec3& x : model.mesh.vertices) x *= Real(2);
  const AnatomyFigures twice = measureAnatomy(model);
  EXPECT_NEAR(twice.mitralArea, 4 * before.mitralArea, 1e-6 * before.mitralArea);
  EXPECT_NEAR(twice.aorticArea, 4 * before.aorticArea, 1e-6 * before.aorticArea);
  EXPECT_NEAR(*twice.aorticRootDiameter, 2 * *before.aorticRootDiameter, 1e-6);
  EXPECT_NEAR(twice.longAxis, 2 * before.longAxis, 1e-6);

  // A bulge in the outflow vessel's lumen is the root's diameter.
  LvModel bulged = buildLvModel(g);
  const Vec3 axisPoint(bulged.flowPath.aortic.centre.x(), 0, bulged.flowPath.aortic.centre.z());
  for (std::size_t v = 0; v < bulged.mesh.vertices.size(); v += 2) {
    if (bulged.region[v] != Region::OutflowVessel) continue;
    Vec3& x = bulged.mesh.vertices[v];
    const Vec3 out(x.x() - axisPoint.x(), 0, x.z() - axisPoint.z());
    x += Real(0.5) * out;  // the lumen 1.5 times as wide
  }
  EXPECT_NEAR(*measureAnatomy(bulged).aorticRootDiameter, 1.5 * *before.aorticRootDiameter, 1e-4);
}

TEST(LvAnatomy, NoRootWithoutAnOutflowVessel) {
  LvModel model = buildLvModel(normalGeometry());
  for (Region& r : model.region)
    if (r == Region::OutflowVessel) r = Region::BasePlate;
  EXPECT_FALSE(measureAnatomy(model).aorticRootDiameter.has_value());
}

}  // namespace
}  // namespace hs::cardiac
