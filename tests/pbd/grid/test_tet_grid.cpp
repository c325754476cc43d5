// TetGrid against brute force (every tet whose bounding box contains the point): jittered box
// meshes and random tet soups, points inside, on box boundaries, outside the grid and far away,
// padding, a stretched mesh (cell cap), non-finite vertices, buffer reuse across rebuilds, a
// refit after a small move and concurrent queries.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "box_mesh.h"
#include "pbd/core/tet_geometry.h"
#include "pbd/grid/tet_grid.h"

namespace hs::pbd {
namespace {

// Same box arithmetic as the grid: min / max of the corners, then -/+ padding, in Real.
std::vector<Index> bruteForceCandidates(const TetMesh& m, const Vec3& p, Real padding) {
  std::vector<Index> out;
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    Vec3 lo = m.vertices[m.tets[t][0]], hi = lo;
    bool finite = lo.allFinite();
    for (std::size_t k = 1; k < 4; ++k) {
      const Vec3& v = m.vertices[m.tets[t][k]];
      finite = finite && v.allFinite();
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    lo -= Vec3::Constant(padding);
    hi += Vec3::Constant(padding);
    if (finite && (lo.array() <= p.array()).all() && (p.array() <= hi.array()).all()) out.push_back(Index(t));
  }
  return out;
}

TetMesh jitteredBox(int n, Real h, unsigned seed, const Vec3& offset) {
  TetMesh m = testing::makeBoxMesh(n, h);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-0.2f, 0.2f);
  for (Vec3& v : m.vertices) v += offset + h * Vec3(Real(u(rng)), Real(u(rng)), Real(u(rng)));
  return m;
}

// Independent random tets of very different sizes, a few of them spanning the whole soup.
TetMesh tetSoup(std::size_t count, unsigned seed) {
  TetMesh m;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0, 1);
  for (std::size_t t = 0; t < count; ++t) {
    const Vec3 c(Real(u(rng)), Real(u(rng)), Real(u(rng)));
    const Real size = t % 50 == 0 ? Real(1) : Real(0.01) + Real(0.1) * Real(u(rng));
    Tet tet;
    for (std::size_t k = 0; k < 4; ++k) {
      tet[k] = Index(m.vertices.size());
      m.vertices.push_back(
          c + size * Vec3(Real(u(rng)) - Real(0.5), Real(u(rng)) - Real(0.5), Real(u(rng)) - Real(0.5)));
    }
    m.tets.push_back(tet);
  }
  return m;
}

// Random points over the mesh bounds grown by 50%, every vertex (exactly on box boundaries),
// and points outside the grid, far away and non-finite.
std::vector<Vec3> queryPoints(const TetMesh& m, std::size_t count, unsigned seed) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<Real>::max()), hi = -lo;
  for (const Vec3& v : m.vertices) {
    if (!v.allFinite()) continue;
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const Vec3 c = Real(0.5) * (lo + hi), half = Real(0.75) * (hi - lo);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1, 1);
  std::vector<Vec3> p;
  for (std::size_t k = 0; k < count; ++k)
    p.push_back(c + half.cwiseProduct(Vec3(Real(u(rng)), Real(u(rng)), Real(u(rng)))));
  p.insert(p.end(), m.vertices.begin(), m.vertices.end());
  const Real big = Real(1e6), inf = std::numeric_limits<Real>::infinity(),
             nan = std::numeric_limits<Real>::quiet_NaN();
  for (const Vec3& v :
       {Vec3(big, 0, 0), Vec3(-big, -big, -big), Vec3(c[0], c[1], big), Vec3(c[0], -big, c[2]),
        Vec3(inf, c[1], c[2]), Vec3(nan, nan, nan), Vec3(c[0], nan, c[2]), Vec3(hi), Vec3(lo)})
    p.push_back(v);
  return p;
}

void expectMatchesBruteForce(const TetMesh& m, const TetGridSettings& s, std::size_t points,
                             const char* what) {
  SCOPED_TRACE(what);
  TetGrid grid(s);
  grid.build(m.vertices, m.tets);
  std::vector<Index> got;
  std::size_t nonEmpty = 0;
  for (const Vec3& p : queryPoints(m, points, 99)) {
    grid.candidates(p, got);
    ASSERT_EQ(got, bruteForceCandidates(m, p, s.padding)) << p.transpose();  // same order: ascending, once
    nonEmpty += !got.empty();
  }
  EXPECT_GT(nonEmpty, points / 4);
}

TEST(TetGrid, CandidatesMatchBruteForce) {
  const TetMesh box = jitteredBox(5, Real(0.01), 1, Vec3(Real(-0.31), Real(0.02), Real(1.7)));
  expectMatchesBruteForce(box, {}, 3000, "jittered box");
  TetGridSettings padded;
  padded.padding = Real(0.002);
  expectMatchesBruteForce(box, padded, 3000, "jittered box, padded");
  TetGridSettings coarse;
  coarse.cellSizeFactor = Real(3.5);
  expectMatchesBruteForce(box, coarse, 3000, "jittered box, coarse cells");
  expectMatchesBruteForce(tetSoup(400, 2), {}, 3000, "tet soup");
}

// A few vertices nudged by three paddings: the grid refits (its cells still hold every box) and answers
// as brute force on the moved mesh; a vertex moved across cells (or out of the grid) is refused
// and the grid still answers for the mesh it was built on.
TEST(TetGrid, RefitAfterASmallMoveMatchesBruteForceAndALargeOneIsRefused) {
  const TetMesh built = jitteredBox(5, Real(0.01), 3, Vec3(Real(0.1), Real(-0.2), Real(0.05)));
  TetGridSettings s;
  s.padding = Real(1e-5);
  s.cellSizeFactor = Real(0.5);
  TetGrid grid(s);
  grid.build(built.vertices, built.tets);
  TetMesh nudged = built;
  for (std::size_t v = 0; v < nudged.vertices.size(); v += 37) nudged.vertices[v] += Vec3::Constant(Real(3e-5));
  ASSERT_TRUE(grid.refit(nudged.vertices, nudged.tets));
  std::vector<Index> got;
  std::size_t differ = 0;  // points whose answer the nudge changed: the refit must see it
  for (const Vec3& p : queryPoints(nudged, 2000, 5)) {
    grid.candidates(p, got);
    ASSERT_EQ(got, bruteForceCandidates(nudged, p, s.padding)) << p.transpose();
    differ += got != bruteForceCandidates(built, p, s.padding);
  }
  EXPECT_GT(differ, 0u);  // the vertices themselves sit on the boxes' moved faces
  TetMesh far = nudged;
  far.vertices[0] += Vec3::Constant(Real(0.5));  // out of every cell it was in, and out of the grid
  EXPECT_FALSE(grid.refit(far.vertices, far.tets));
  for (const Vec3& p : queryPoints(nudged, 500, 6)) {
    grid.candidates(p, got);
    ASSERT_EQ(got, bruteForceCandidates(nudged, p, s.padding)) << p.transpose();
  }
  TetMesh other = built;
  other.tets.pop_back();
  EXPECT_FALSE(grid.refit(other.vertices, other.tets));  // a different mesh: build() it
}

TEST(TetGrid, CellSizeIsTheMeanBoxExtent) {
  const TetMesh box = testing::makeBoxMesh(4, Real(0.25));  // Kuhn tets: every box is a cube of 0.25
  TetGrid grid;
  grid.build(box.vertices, box.tets);
  EXPECT_EQ(grid.cellSize(), Real(0.25));
  EXPECT_EQ(grid.cellCount(), 125u);  // 1 m / 0.25 = 4 cells, + 1 for the upper bound
  TetGridSettings s;
  s.cellSizeFactor = 2;
  grid.setSettings(s);
  grid.build(box.vertices, box.tets);
  EXPECT_EQ(grid.cellSize(), Real(0.5));
}

TEST(TetGrid, StretchedMeshCapsTheCellCount) {
  TetMesh m = jitteredBox(4, Real(0.01), 3, Vec3::Zero());
  m.vertices[7] += Vec3(Real(1e4), Real(-3e3), Real(5e2));  // one vertex flew away
  TetGrid grid;
  grid.build(m.vertices, m.tets);
  EXPECT_LE(double(grid.cellCount()), 8.0 * double(m.tets.size()) + 64);
  expectMatchesBruteForce(m, {}, 2000, "stretched");
}

TEST(TetGrid, NonFiniteVerticesAndEmptyMeshes) {
  TetMesh m = jitteredBox(3, Real(0.01), 4, Vec3::Zero());
  m.vertices[5] = Vec3(std::numeric_limits<Real>::quiet_NaN(), 0, 0);
  m.vertices[9][2] = std::numeric_limits<Real>::infinity();
  expectMatchesBruteForce(m, {}, 2000, "non-finite vertices");
  TetGrid grid;
  std::vector<Index> out;
  grid.build({}, {});
  EXPECT_EQ(grid.tetCount(), 0u);
  grid.candidates(Vec3::Zero(), out);
  EXPECT_TRUE(out.empty());
  TetMesh nan;
  nan.vertices.assign(4, Vec3::Constant(std::numeric_limits<Real>::quiet_NaN()));
  nan.tets = {{0, 1, 2, 3}};
  grid.build(nan.vertices, nan.tets);
  grid.candidates(Vec3::Zero(), out);
  EXPECT_TRUE(out.empty());
  TetGrid unbuilt;
  unbuilt.candidates(Vec3::Zero(), out);
  EXPECT_TRUE(out.empty());
}

TEST(TetGrid, TetsContainingMatchesBruteForce) {
  const TetMesh m = jitteredBox(4, Real(0.01), 5, Vec3(Real(0.1), Real(0.2), Real(0.3)));
  TetGrid grid;
  grid.build(m.vertices, m.tets);
  std::vector<Index> got;
  std::size_t found = 0;
  for (const Vec3& p : queryPoints(m, 4000, 6)) {
    for (Real tol : {Real(0), kBarycentricSlack}) {
      grid.tetsContaining(p, m.vertices, m.tets, tol, got);
      std::vector<Index> expected;
      for (std::size_t t = 0; t < m.tets.size(); ++t)
        if (isPointInTet(tetPoints(m.vertices, m.tets[t]), p, tol)) expected.push_back(Index(t));
      ASSERT_EQ(got, expected);
      found += !got.empty();
    }
  }
  EXPECT_GT(found, 1000u);
}

TEST(TetGrid, RebuildsOfAMovingMeshReuseTheirBuffers) {
  TetMesh m = jitteredBox(5, Real(0.01), 7, Vec3::Zero());
  const std::vector<Vec3> rest = m.vertices;
  TetGrid grid;
  const Index* cells = nullptr;
  const Index* entries = nullptr;
  for (int step = 0; step < 40; ++step) {
    // A breathing, drifting mesh: bounds, cell counts and entries change every step.
    const Real s = Real(1) + Real(0.1) * std::sin(Real(step) * Real(0.4));
    for (std::size_t v = 0; v < rest.size(); ++v)
      m.vertices[v] = s * rest[v] + Vec3(Real(0.001) * Real(step), 0, 0);
    grid.build(m.vertices, m.tets);
    if (step == 2) {
      cells = grid.cellStarts().data();
      entries = grid.entries().data();
    } else if (step > 2) {
      EXPECT_EQ(grid.cellStarts().data(), cells) << step;
      EXPECT_EQ(grid.entries().data(), entries) << step;
    }
    if (step % 10 == 0) {
      std::vector<Index> got;
      for (const Vec3& p : queryPoints(m, 200, unsigned(step))) {
        grid.candidates(p, got);
        ASSERT_EQ(got, bruteForceCandidates(m, p, 0));
      }
    }
  }
}

TEST(TetGrid, ConcurrentQueriesAgreeWithSerialOnes) {
  const TetMesh m = jitteredBox(6, Real(0.01), 8, Vec3::Zero());
  TetGrid grid;
  grid.build(m.vertices, m.tets);
  const std::vector<Vec3> points = queryPoints(m, 20000, 9);
  const std::int64_t n = std::int64_t(points.size());
  std::vector<std::size_t> serial(points.size()), parallel(points.size());
  for (std::int64_t i = 0; i < n; ++i) {
    std::vector<Index> out;
    grid.tetsContaining(points[std::size_t(i)], m.vertices, m.tets, 0, out);
    serial[std::size_t(i)] = out.empty() ? ~std::size_t(0) : out.front() * 31 + out.size();
  }
#pragma omp parallel for num_threads(2) schedule(dynamic, 64)
  for (std::int64_t i = 0; i < n; ++i) {
    std::vector<Index> out;
    grid.tetsContaining(points[std::size_t(i)], m.vertices, m.tets, 0, out);
    parallel[std::size_t(i)] = out.empty() ? ~std::size_t(0) : out.front() * 31 + out.size();
  }
  EXPECT_EQ(parallel, serial);
}

}  // namespace
}  // namespace hs::pbd
