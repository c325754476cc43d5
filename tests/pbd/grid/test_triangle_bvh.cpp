// TriangleBvh against brute force (every triangle whose swept box the padded segment touches):
// the boundary of jittered box meshes and random triangle soups, random deformations over the
// step (small and large), random segments (short, long, axis-parallel, points), refits of
// the same tree, non-finite vertices, and the refit bitwise the same for 1 and 2 threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

#include "box_mesh.h"
#include "pbd/grid/triangle_bvh.h"

namespace hs::pbd {
namespace {

std::vector<std::size_t> bruteForce(const std::vector<Triangle>& triangles, const std::vector<Vec3>& start,
                                    const std::vector<Vec3>& end, Real margin, const Vec3& a, const Vec3& b,
                                    Real pad) {
  std::vector<std::size_t> out;
  for (std::size_t t = 0; t < triangles.size(); ++t)
    if (segmentTouchesBox(a, b, sweptTriangleBox(start, end, triangles[t], margin), pad)) out.push_back(t);
  return out;
}

std::vector<std::size_t> query(const TriangleBvh& bvh, const Vec3& a, const Vec3& b, Real pad) {
  std::vector<std::size_t> out;
  bvh.forEachTouching(a, b, pad, [&](std::size_t t) { out.push_back(t); });
  std::sort(out.begin(), out.end());
  EXPECT_TRUE(std::adjacent_find(out.begin(), out.end()) == out.end()) << "a triangle reported twice";
  return out;
}

struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;
};

Mesh boxSurface(int n, Real h, std::mt19937& rng) {
  TetMesh m = testing::makeBoxMesh(n, h);
  std::uniform_real_distribution<Real> jitter(Real(-0.2) * h, Real(0.2) * h);
  for (Vec3& v : m.vertices) v += Vec3(jitter(rng), jitter(rng), jitter(rng));
  return {m.vertices, boundaryFaces(m.tets)};
}

Mesh triangleSoup(std::size_t count, std::mt19937& rng) {
  std::uniform_real_distribution<Real> u(-1, 1), small(Real(-0.1), Real(0.1));
  Mesh m;
  for (std::size_t t = 0; t < count; ++t) {
    const Vec3 c(u(rng), u(rng), u(rng));
    const auto first = Index(m.vertices.size());
    for (int k = 0; k < 3; ++k) m.vertices.push_back(c + Vec3(small(rng), small(rng), small(rng)));
    m.triangles.push_back({first, first + 1, first + 2});
  }
  return m;
}

// The vertices' end of step: a smooth swirl plus noise of the given size.
std::vector<Vec3> deformed(const std::vector<Vec3>& x, Real amount, std::mt19937& rng) {
  std::uniform_real_distribution<Real> u(-1, 1);
  std::vector<Vec3> out(x.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    out[i] = x[i] + amount * Vec3(std::sin(Real(3) * x[i].y()), std::cos(Real(2) * x[i].z()), x[i].x()) +
             Real(0.3) * amount * Vec3(u(rng), u(rng), u(rng));
  return out;
}

void expectAgreesWithBruteForce(const Mesh& m, const std::vector<Vec3>& start, const std::vector<Vec3>& end,
                                TriangleBvh& bvh, Real margin, std::mt19937& rng, std::size_t minimumNonEmpty = 40) {
  bvh.refit(start, end, margin);
  std::uniform_real_distribution<Real> u(Real(-1.3), Real(1.3)), shortHop(Real(-0.05), Real(0.05));
  std::size_t nonEmpty = 0;
  for (int q = 0; q < 400; ++q) {
    Vec3 a(u(rng), u(rng), u(rng)), b;
    switch (q % 4) {
      case 0: b = Vec3(u(rng), u(rng), u(rng)); break;                     // long
      case 1: b = a + Vec3(shortHop(rng), shortHop(rng), shortHop(rng)); break;  // a particle's step
      case 2: b = a + Vec3(0, 0, Real(2) * shortHop(rng) * 20); break;      // axis-parallel
      default: b = a; break;                                                 // a point
    }
    const Real pad = (q % 3 == 0) ? Real(0) : Real(0.01);
    const std::vector<std::size_t> expected = bruteForce(m.triangles, start, end, margin, a, b, pad);
    EXPECT_EQ(query(bvh, a, b, pad), expected) << "query " << q;
    nonEmpty += !expected.empty();
  }
  EXPECT_GE(nonEmpty, minimumNonEmpty) << "the segments must meet the mesh often enough to test something";
}

TEST(TriangleBvh, AgreesWithBruteForceOnBoxSurfaces) {
  std::mt19937 rng(3);
  for (int n : {1, 3, 6}) {
    SCOPED_TRACE(n);
    Mesh m = boxSurface(n, Real(2) / Real(n), rng);
    for (Vec3& v : m.vertices) v -= Vec3::Ones();
    TriangleBvh bvh(m.triangles, m.vertices);
    for (Real amount : {Real(0), Real(0.02), Real(0.3)}) {
      SCOPED_TRACE(amount);
      const std::vector<Vec3> start = deformed(m.vertices, amount, rng);
      const std::vector<Vec3> end = deformed(start, amount, rng);
      expectAgreesWithBruteForce(m, start, end, bvh, Real(0.001), rng);
    }
  }
}

TEST(TriangleBvh, AgreesWithBruteForceOnTriangleSoups) {
  std::mt19937 rng(5);
  for (std::size_t count : {std::size_t(1), std::size_t(5), std::size_t(300)}) {
    SCOPED_TRACE(count);
    const Mesh m = triangleSoup(count, rng);
    TriangleBvh bvh(m.triangles, m.vertices);
    // Refitted after large moves: the topology of the first positions stays right, only slower.
    for (Real amount : {Real(0.05), Real(1.0)}) {
      const std::vector<Vec3> start = deformed(m.vertices, amount, rng);
      expectAgreesWithBruteForce(m, start, deformed(start, amount, rng), bvh, Real(0), rng, count > 100 ? 40 : 1);
    }
  }
}

TEST(TriangleBvh, SweptBoxHoldsTheTriangleForTheWholeStep) {
  std::mt19937 rng(7);
  const Mesh m = triangleSoup(50, rng);
  const std::vector<Vec3> end = deformed(m.vertices, Real(0.5), rng);
  TriangleBvh bvh(m.triangles, m.vertices);
  bvh.refit(m.vertices, end, 0);
  std::uniform_real_distribution<Real> u(0, 1);
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const Box3& box = bvh.triangleBox(t);
    for (int k = 0; k < 20; ++k) {
      const Real s = u(rng), b1 = u(rng), b2 = (1 - b1) * u(rng);
      auto at = [&](Index v) -> Vec3 { return m.vertices[v] + s * (end[v] - m.vertices[v]); };
      const Triangle& f = m.triangles[t];
      const Vec3 p = (1 - b1 - b2) * at(f[0]) + b1 * at(f[1]) + b2 * at(f[2]);
      // A point on the moving triangle lies in its box (within float rounding of p itself).
      EXPECT_TRUE(segmentTouchesBox(p, p, box, Real(1e-6))) << "triangle " << t;
    }
  }
}

TEST(TriangleBvh, NonFiniteVerticesAreNeverCandidates) {
  std::mt19937 rng(9);
  Mesh m = triangleSoup(40, rng);
  TriangleBvh bvh(m.triangles, m.vertices);
  std::vector<Vec3> end = m.vertices;
  end[m.triangles[7][1]] = Vec3::Constant(std::numeric_limits<Real>::quiet_NaN());
  end[m.triangles[20][0]].x() = std::numeric_limits<Real>::infinity();
  bvh.refit(m.vertices, end, Real(0.01));
  std::vector<std::size_t> all;
  bvh.forEachTouching(Vec3::Constant(-2), Vec3::Constant(2), Real(3), [&](std::size_t t) { all.push_back(t); });
  EXPECT_EQ(all.size(), m.triangles.size() - 2);
  EXPECT_EQ(std::count(all.begin(), all.end(), std::size_t(7)), 0);
  EXPECT_EQ(std::count(all.begin(), all.end(), std::size_t(20)), 0);
  const Vec3 nan = Vec3::Constant(std::numeric_limits<Real>::quiet_NaN());
  std::size_t hits = 0;
  bvh.forEachTouching(nan, Vec3::Zero(), Real(3), [&](std::size_t) { ++hits; });
  EXPECT_EQ(hits, 0u) << "a non-finite segment touches nothing";
}

TEST(SegmentTouchesBox, EdgesAndPadding) {
  Box3 box;
  box.grow(Vec3(0, 0, 0));
  box.grow(Vec3(1, 1, 1));
  EXPECT_TRUE(segmentTouchesBox(Vec3(-1, Real(0.5), Real(0.5)), Vec3(2, Real(0.5), Real(0.5)), box, 0));
  EXPECT_TRUE(segmentTouchesBox(Vec3(Real(0.5), Real(0.5), Real(0.5)), Vec3(Real(0.5), Real(0.5), Real(0.5)), box, 0));
  EXPECT_FALSE(segmentTouchesBox(Vec3(-1, Real(0.5), Real(0.5)), Vec3(Real(-0.1), Real(0.5), Real(0.5)), box, 0));
  EXPECT_TRUE(segmentTouchesBox(Vec3(-1, Real(0.5), Real(0.5)), Vec3(Real(-0.1), Real(0.5), Real(0.5)), box,
                                Real(0.1)));
  EXPECT_TRUE(segmentTouchesBox(Vec3(-1, 1, Real(0.5)), Vec3(2, 1, Real(0.5)), box, 0)) << "along a face";
  // The diagonal past a corner: each slab alone is met, all three together are not.
  EXPECT_FALSE(segmentTouchesBox(Vec3(Real(2.7), Real(-0.5), Real(0.5)), Vec3(Real(-0.5), Real(2.7), Real(0.5)), box,
                                 0));
  EXPECT_TRUE(segmentTouchesBox(Vec3(Real(1.6), Real(-0.5), Real(0.5)), Vec3(Real(-0.5), Real(1.6), Real(0.5)), box, 0));
  EXPECT_FALSE(segmentTouchesBox(Vec3::Zero(), Vec3::Ones(), Box3{}, Real(10))) << "an empty box";
}

TEST(TriangleBvh, RefitIsBitwiseTheSameForOneAndTwoThreads) {
  std::mt19937 rng(13);
  Mesh m = boxSurface(20, Real(0.1), rng);  // 4800 triangles: above the parallel threshold
  ASSERT_GT(m.triangles.size(), 4000u);
  const std::vector<Vec3> end = deformed(m.vertices, Real(0.05), rng);
  TriangleBvh one(m.triangles, m.vertices), two(m.triangles, m.vertices);
  one.refit(m.vertices, end, Real(0.002), 1);
  two.refit(m.vertices, end, Real(0.002), 2);
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    ASSERT_EQ(one.triangleBox(t).lo, two.triangleBox(t).lo);
    ASSERT_EQ(one.triangleBox(t).hi, two.triangleBox(t).hi);
  }
  const Vec3 a(Real(-0.1), Real(0.5), Real(0.7)), b(Real(2.1), Real(1.3), Real(1.1));
  EXPECT_EQ(query(one, a, b, Real(0.01)), query(two, a, b, Real(0.01)));
  EXPECT_LT(one.depth(), 20u) << "median splits keep the tree shallow";
}

}  // namespace
}  // namespace hs::pbd
