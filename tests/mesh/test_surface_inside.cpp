// Inside a closed surface by ray parity: the column grid against brute force, rays through
// edges and corners counted once, and the answer against the exact shape where it is known.
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "mesh/surface_inside.h"
#include "sphere_surface.h"

namespace hs::pbd {
namespace {

// The unit cube's 12 outward triangles: every face's diagonal and every edge lie where a grid
// of query rays meets them exactly.
void unitCube(std::vector<Vec3>& x, std::vector<Triangle>& t) {
  x.clear();
  for (int k = 0; k < 8; ++k) x.emplace_back(Real(k & 1), Real((k >> 1) & 1), Real((k >> 2) & 1));
  t = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
       {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
}

TEST(SurfaceInside, RaysThroughTheCubesEdgesAndCornersCountOnce) {
  std::vector<Vec3> x;
  std::vector<Triangle> t;
  unitCube(x, t);
  const SurfaceInside inside(x, t, Real(0.3));
  // Queries at quarter steps from -0.25 to 1.25 in x and z: their rays pass through the top and
  // bottom faces' diagonals and corners. A point on a side plane (x or z = 0 or 1) may go either
  // way, so only the others are checked against the cube.
  int checked = 0;
  for (int i = -1; i <= 5; ++i)
    for (int j = -1; j <= 5; ++j)
      for (int k = -1; k <= 5; ++k) {
        const Vec3 p(Real(i) / 4, Real(j) / 4 + Real(0.125), Real(k) / 4);
        const bool onSide = i == 0 || i == 4 || k == 0 || k == 4;
        const bool expected = i > 0 && i < 4 && k > 0 && k < 4 && p.y() > 0 && p.y() < 1;
        EXPECT_EQ(insideClosedSurface(x, t, p), inside.contains(p));
        if (onSide) continue;
        EXPECT_EQ(inside.contains(p), expected) << p.transpose();
        ++checked;
      }
  EXPECT_EQ(checked, 5 * 7 * 5);
}

TEST(SurfaceInside, ColumnsAgreeWithBruteForceOnADeformedSphere) {
  testing::TestSurface sphere = testing::makeSphere(3, 1.0);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> bump(-0.15, 0.15), coord(-1.3, 1.3);
  for (Vec3& v : sphere.vertices) v *= Real(1 + bump(rng));
  for (Real column : {Real(0.05), Real(0.4), Real(5)}) {
    const SurfaceInside inside(sphere.vertices, sphere.triangles, column);
    int in = 0;
    for (int n = 0; n < 4000; ++n) {
      // Half the queries on the vertices' own x and z, so rays meet corners exactly.
      Vec3 p(Real(coord(rng)), Real(coord(rng)), Real(coord(rng)));
      if (n % 2 == 0) {
        const Vec3& v = sphere.vertices[std::size_t(n / 2) % sphere.vertices.size()];
        p.x() = v.x();
        p.z() = v.z();
      }
      const bool brute = insideClosedSurface(sphere.vertices, sphere.triangles, p);
      ASSERT_EQ(inside.contains(p), brute) << "column " << column << " at " << p.transpose();
      in += brute;
      // Well inside or outside the bumped sphere (radius 0.85-1.15), the answer is known.
      if (p.norm() < 0.8) {
        EXPECT_TRUE(brute) << p.transpose();
      }
      if (p.norm() > 1.2) {
        EXPECT_FALSE(brute) << p.transpose();
      }
    }
    EXPECT_GT(in, 500);
  }
}

TEST(SurfaceInside, ReversedWindingAndNonFinitePointsDoNotChangeTheAnswer) {
  std::vector<Vec3> x;
  std::vector<Triangle> t;
  unitCube(x, t);
  for (Triangle& f : t) std::swap(f[1], f[2]);
  const SurfaceInside inside(x, t, Real(0.5));
  EXPECT_TRUE(inside.contains(Vec3(Real(0.3), Real(0.6), Real(0.7))));
  EXPECT_FALSE(inside.contains(Vec3(Real(0.3), Real(1.6), Real(0.7))));
  EXPECT_FALSE(inside.contains(Vec3(std::numeric_limits<Real>::quiet_NaN(), 0, 0)));
  EXPECT_THROW(SurfaceInside({}, {}, Real(1)), std::invalid_argument);
}

}  // namespace
}  // namespace hs::pbd
