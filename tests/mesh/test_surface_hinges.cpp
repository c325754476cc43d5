// Hinges of a triangle surface and the angle each is bent by (mesh/surface_hinges.h): a folded
// pair of triangles, a sphere moved rigidly (no turn) and dented (a crease), an open cup's rim.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesh/surface_hinges.h"
#include "sphere_surface.h"

namespace hs::pbd {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(SurfaceHinges, TwoTrianglesFoldedByAKnownAngle) {
  // The square (0,0,0) (1,0,0) (1,1,0) (0,1,0) cut along 0-2; triangle 3 turned about that edge.
  const std::vector<Triangle> triangles = {{0, 2, 3}, {0, 1, 2}};
  const std::vector<Hinge> hinges = surfaceHinges(triangles);
  ASSERT_EQ(hinges.size(), 1u);  // the shared edge only; the four outer edges are boundary
  std::vector<Vec3> x = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  EXPECT_NEAR(hingeAngle(hinges[0], x), 0.0, 1e-7);  // flat
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 1, 0).normalized();
  for (double fold : {0.3, 1.0, kPi / 2, 2.5}) {
    x[3] = (Eigen::AngleAxisd(fold, axis) * Eigen::Vector3d(0, 1, 0)).cast<Real>();
    EXPECT_NEAR(std::abs(hingeAngle(hinges[0], x)), fold, 1e-6) << fold;
    EXPECT_NEAR(largestHingeTurn(hinges, {0.0}, x), fold, 1e-6);
  }
  // Folding the other way turns the angle's sign.
  x[3] = (Eigen::AngleAxisd(0.5, axis) * Eigen::Vector3d(0, 1, 0)).cast<Real>();
  const double one = hingeAngle(hinges[0], x);
  x[3] = (Eigen::AngleAxisd(-0.5, axis) * Eigen::Vector3d(0, 1, 0)).cast<Real>();
  EXPECT_NEAR(hingeAngle(hinges[0], x), -one, 1e-6);
}

TEST(SurfaceHinges, ASphereTurnsNowhereWhenMovedAndCreasesWhereDented) {
  const auto sphere = testing::makeSphere(3, 1.0);
  const std::vector<Hinge> hinges = surfaceHinges(sphere.triangles);
  EXPECT_EQ(hinges.size(), 3 * sphere.triangles.size() / 2);  // closed: every edge a hinge
  std::vector<double> rest;
  for (const Hinge& h : hinges) rest.push_back(hingeAngle(h, sphere.vertices));
  // Rotated, scaled and moved: every angle as at rest.
  const Eigen::Matrix3d q = Eigen::AngleAxisd(0.8, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  std::vector<Vec3> moved;
  for (const Vec3& v : sphere.vertices) moved.push_back((2.5 * q * v.cast<double>() + Eigen::Vector3d(3, -1, 7)).cast<Real>());
  EXPECT_LT(largestHingeTurn(hinges, rest, moved), 1e-5);
  // One vertex pushed 60% of the way to the centre: the surface creases around it.
  std::vector<Vec3> dented = sphere.vertices;
  dented[0] *= Real(0.4);
  EXPECT_GT(largestHingeTurn(hinges, rest, dented), 0.5);  // about 30 degrees and more
  // A sphere shrunk evenly (a beat without a crease) turns nowhere.
  std::vector<Vec3> shrunk = sphere.vertices;
  for (Vec3& v : shrunk) v *= Real(0.7);
  EXPECT_LT(largestHingeTurn(hinges, rest, shrunk), 1e-5);
}

TEST(SurfaceHinges, AnOpenCupHasNoHingeOnItsRim) {
  const auto sphere = testing::makeSphere(3, 1.0);
  std::vector<Triangle> cup;
  for (const Triangle& t : sphere.triangles)
    if (sphere.vertices[t[0]].z() + sphere.vertices[t[1]].z() + sphere.vertices[t[2]].z() < 0) cup.push_back(t);
  const std::vector<Hinge> hinges = surfaceHinges(cup);
  std::size_t rimEdges = 3 * cup.size() - 2 * hinges.size();
  EXPECT_GT(rimEdges, 0u);
  EXPECT_EQ((3 * cup.size() - rimEdges) % 2, 0u);
  // A triangle wound the other way (one at the bottom, away from the rim) has no hinge with
  // its three neighbours.
  std::vector<Triangle> flipped = cup;
  const auto bottom = std::find_if(flipped.begin(), flipped.end(), [&](const Triangle& t) {
    return sphere.vertices[t[0]].z() + sphere.vertices[t[1]].z() + sphere.vertices[t[2]].z() < -2.7;
  });
  ASSERT_NE(bottom, flipped.end());
  std::swap((*bottom)[1], (*bottom)[2]);
  EXPECT_EQ(surfaceHinges(flipped).size(), hinges.size() - 3);
}

}  // namespace
}  // namespace hs::pbd
