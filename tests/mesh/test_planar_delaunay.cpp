#include <gtest/gtest.h>

#include <vector>

#include "mesh/planar_delaunay.h"

namespace hs::pbd {
namespace {

TEST(PlanarDelaunay, ShiftedRowsAreTriangulatedWithEmptyCircles) {
  // Rows y = 0.9 j of x = i (+0.37 on odd rows), i = 0..5, j = 0..4.
  std::vector<Eigen::Vector2d> pts;
  for (int j = 0; j < 5; ++j) {
    for (int i = 0; i < 6; ++i) pts.emplace_back(i + 0.37 * (j % 2), 0.9 * j);
  }
  const auto tris = delaunayTriangulation(pts);
  double area = 0;
  for (const Triangle& t : tris) {
    const Eigen::Vector2d a = pts[t[1]] - pts[t[0]];
    const Eigen::Vector2d b = pts[t[2]] - pts[t[0]];
    const double cross = a.x() * b.y() - a.y() * b.x();
    EXPECT_GT(cross, 0);  // counter-clockwise
    area += 0.5 * cross;
    for (Index p = 0; p < pts.size(); ++p) {
      if (p == t[0] || p == t[1] || p == t[2]) continue;
      EXPECT_LT(inCircle(pts[t[0]], pts[t[1]], pts[t[2]], pts[p]), 1e-9);  // empty circumcircle
    }
  }
  // n points with h of them on the hull boundary give 2n - h - 2 triangles: here h = 15
  // (both full rows, (0, 1.8), (5.37, 0.9), (5.37, 2.7)).
  EXPECT_EQ(tris.size(), 2 * pts.size() - 15 - 2);
  // Hull area: the 5 x 3.6 rectangle plus the trapezoid 0.37 wide on the right.
  EXPECT_NEAR(area, 5.0 * 3.6 + 0.37 * 2.7, 1e-9);
}

}  // namespace
}  // namespace hs::pbd
