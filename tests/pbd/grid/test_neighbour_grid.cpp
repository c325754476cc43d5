// Over 400 lines on purpose: one test file per module, its cases sharing the file's set-up helpers.
// NeighbourGrid against brute force: random clouds, exact cell-boundary and radius-boundary
// cases, far outliers (hashed fallback), degenerate inputs, thread determinism of the CSR
// lists, Morton reordering, and buffer reuse across rebuilds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "pbd/grid/neighbour_grid.h"

namespace hs::pbd {
namespace {

using Lists = std::vector<std::vector<Index>>;

// Same distance test as the grid: |x_i - x_j|^2 < radius^2 in Real.
Lists bruteForce(const std::vector<Vec3>& x, Real radius) {
  Lists out(x.size());
  const Real r2 = radius * radius;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = 0; j < x.size(); ++j) {
      if (i == j) continue;
      const Vec3 r = x[i] - x[j];
      if (r.squaredNorm() < r2) out[i].push_back(Index(j));
    }
  return out;
}

// Neighbours via forEachNeighbour, sorted; also checks the r_ij and |r_ij|^2 passed to f.
Lists viaQuery(const NeighbourGrid& grid, const std::vector<Vec3>& x, Real radius) {
  Lists out(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    grid.forEachNeighbour(Index(i), x, radius, [&](Index j, const Vec3& r, Real d2) {
      EXPECT_EQ(r, Vec3(x[i] - x[j]));
      EXPECT_EQ(d2, r.squaredNorm());
      out[i].push_back(j);
    });
    std::sort(out[i].begin(), out[i].end());
    EXPECT_TRUE(std::adjacent_find(out[i].begin(), out[i].end()) == out[i].end()) << "duplicate neighbour of " << i;
  }
  return out;
}

Lists fromCsr(const NeighbourLists& csr) {
  Lists out(csr.offsets.empty() ? 0 : csr.offsets.size() - 1);
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i].assign(csr.indices.begin() + csr.offsets[i], csr.indices.begin() + csr.offsets[i + 1]);
  return out;
}

std::vector<Vec3> randomCloud(std::size_t n, unsigned seed, Real side) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, double(side));
  std::vector<Vec3> x(n);
  for (auto& p : x) p = Vec3(Real(u(rng)), Real(u(rng)), Real(u(rng)));
  return x;
}

std::size_t pairCount(const Lists& l) {
  std::size_t s = 0;
  for (const auto& v : l) s += v.size();
  return s;
}

// Checks query and CSR results against brute force for one grid configuration.
void expectMatchesBruteForce(const std::vector<Vec3>& x, Real cellSize, Real radius, bool forceHashing,
                             const char* what) {
  SCOPED_TRACE(what);
  NeighbourGridSettings s;
  s.forceHashing = forceHashing;
  NeighbourGrid grid(s);
  grid.build(x, cellSize);
  if (forceHashing) {
    EXPECT_TRUE(grid.hashed());
  }
  const Lists expected = bruteForce(x, radius);
  EXPECT_EQ(viaQuery(grid, x, radius), expected);
  NeighbourLists csr;
  grid.buildNeighbourLists(x, radius, csr);
  EXPECT_EQ(fromCsr(csr), expected);
}

TEST(NeighbourGrid, RandomCloudsMatchBruteForce) {
  const Real h = Real(0.1);
  for (unsigned seed : {1u, 2u, 3u, 4u}) {
    // Offset the box so the origin is not at 0.
    std::vector<Vec3> x = randomCloud(2000, seed, Real(1));
    for (auto& p : x) p += Vec3(Real(-3.3), Real(0.7), Real(12.1));
    const Lists full = bruteForce(x, h);
    ASSERT_GT(pairCount(full), 2000u) << "cloud too sparse to test anything";
    for (bool hashing : {false, true}) {
      expectMatchesBruteForce(x, h, h, hashing, hashing ? "hashed, radius = cell" : "dense, radius = cell");
      expectMatchesBruteForce(x, h, Real(0.63) * h, hashing, hashing ? "hashed, radius < cell" : "dense, radius < cell");
    }
  }
}

TEST(NeighbourGrid, PointsOnCellBoundaries) {
  // Lattice of spacing h/2 with coordinates that are multiples of the cell size h = 0.25
  // (exact in binary): every coordinate difference and square is exact.
  const Real h = Real(0.25), s = h / 2;
  std::vector<Vec3> x;
  for (int k = 0; k < 7; ++k)
    for (int j = 0; j < 7; ++j)
      for (int i = 0; i < 7; ++i) x.emplace_back(Real(i) * s, Real(j) * s, Real(k) * s);
  expectMatchesBruteForce(x, h, h, false, "lattice h/2, dense");
  expectMatchesBruteForce(x, h, h, true, "lattice h/2, hashed");

  // Interior point: the offsets (a,b,c) with a^2+b^2+c^2 < 4 lattice units, minus itself:
  // 6 + 12 + 8 = 26. The 6 at distance exactly h must be excluded.
  NeighbourGrid grid;
  grid.build(x, h);
  const Index centre = Index((3 * 7 + 3) * 7 + 3);
  std::vector<Index> found;
  grid.forEachNeighbour(centre, x, h, [&](Index j, const Vec3&, Real) { found.push_back(j); });
  EXPECT_EQ(found.size(), 26u);

  // Spacing exactly h with radius h: the axis neighbours are at distance == radius, so nobody
  // has a neighbour at all.
  std::vector<Vec3> coarse;
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 5; ++i) coarse.emplace_back(Real(i) * h, Real(j) * h, Real(k) * h);
  grid.build(coarse, h);
  NeighbourLists csr;
  grid.buildNeighbourLists(coarse, h, csr);
  EXPECT_TRUE(csr.indices.empty());
  expectMatchesBruteForce(coarse, h, h, true, "lattice h, hashed");
}

TEST(NeighbourGrid, DistanceExactlyRadiusExcludedJustBelowIncluded) {
  const Real h = Real(0.25);
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 a = Vec3(Real(1), Real(2), Real(3));  // multiples of h: on cell boundaries
    Vec3 at = a, below = a;
    at[axis] += h;
    below[axis] = std::nextafter(at[axis], a[axis]);
    for (bool hashing : {false, true}) {
      NeighbourGridSettings s;
      s.forceHashing = hashing;
      NeighbourGrid grid(s);
      const std::vector<Vec3> equal{a, at}, inside{a, below};
      grid.build(equal, h);
      NeighbourLists csr;
      grid.buildNeighbourLists(equal, h, csr);
      EXPECT_TRUE(csr.indices.empty()) << "axis " << axis;
      grid.build(inside, h);
      grid.buildNeighbourLists(inside, h, csr);
      EXPECT_EQ(fromCsr(csr), (Lists{{1}, {0}})) << "axis " << axis;
    }
  }
  // Also with a non-dyadic cell size, where rounding decides: must agree with brute force.
  const Real h2 = Real(0.1);
  std::vector<Vec3> x;
  for (int i = 0; i < 40; ++i) {
    const Real base = Real(i) * h2;
    x.emplace_back(base, Real(0), Real(0));
    x.emplace_back(std::nextafter(base + h2, base), Real(1), Real(0));
    x.emplace_back(base, Real(1), Real(0));
  }
  expectMatchesBruteForce(x, h2, h2, false, "non-dyadic rows, dense");
  expectMatchesBruteForce(x, h2, h2, true, "non-dyadic rows, hashed");
}

TEST(NeighbourGrid, FarOutliersUseHashingAndStayCorrect) {
  const Real h = Real(0.1);
  std::vector<Vec3> x = randomCloud(2000, 7, Real(1));
  // Two small clusters about 1e6 cells away, on different axes, each with neighbours inside.
  x.emplace_back(Real(1e5), Real(0.5), Real(0.5));
  x.emplace_back(Real(1e5) + Real(0.05), Real(0.5), Real(0.5));
  x.emplace_back(Real(1e5), Real(0.5) + Real(0.07), Real(0.5));
  x.emplace_back(Real(0.5), Real(-1e5), Real(0.5));
  x.emplace_back(Real(0.5), Real(-1e5), Real(0.5) + Real(0.03));
  x.emplace_back(Real(0.2), Real(0.3), Real(-1e5));  // lonely
  NeighbourGrid grid;
  grid.build(x, h);
  EXPECT_TRUE(grid.hashed());
  EXPECT_LE(grid.cellCount(), 4 * x.size());
  const Lists expected = bruteForce(x, h);
  EXPECT_EQ(expected[2000].size(), 2u);
  EXPECT_EQ(expected[2003].size(), 1u);
  EXPECT_EQ(viaQuery(grid, x, h), expected);
  NeighbourLists csr;
  grid.buildNeighbourLists(x, h, csr);
  EXPECT_EQ(fromCsr(csr), expected);

  // Without the outliers the same cloud uses the dense grid.
  x.resize(2000);
  grid.build(x, h);
  EXPECT_FALSE(grid.hashed());
}

TEST(NeighbourGrid, SingleParticleAndEmptyInput) {
  NeighbourGrid grid;
  NeighbourLists csr;
  const std::vector<Vec3> one{Vec3(Real(5), Real(-2), Real(1e4))};
  grid.build(one, Real(0.1));
  int calls = 0;
  grid.forEachNeighbour(0, one, Real(0.1), [&](Index, const Vec3&, Real) { ++calls; });
  EXPECT_EQ(calls, 0);
  grid.buildNeighbourLists(one, Real(0.1), csr);
  EXPECT_EQ(csr.offsets, (std::vector<Index>{0, 0}));
  EXPECT_TRUE(csr.indices.empty());
  // Point queries still find the particle.
  grid.forEachNeighbourOfPoint(Vec3(Real(5.05), Real(-2), Real(1e4)), Real(0.1), [&](Index j, const Vec3&, Real) {
    EXPECT_EQ(j, 0u);
    ++calls;
  });
  EXPECT_EQ(calls, 1);

  const std::vector<Vec3> none;
  grid.build(none, Real(0.1));
  EXPECT_EQ(grid.particleCount(), 0u);
  grid.buildNeighbourLists(none, Real(0.1), csr);
  EXPECT_EQ(csr.offsets, (std::vector<Index>{0}));
  EXPECT_TRUE(csr.indices.empty());
  grid.forEachNeighbourOfPoint(Vec3::Zero(), Real(0.1), [&](Index, const Vec3&, Real) { ++calls; });
  EXPECT_EQ(calls, 1);
  EXPECT_TRUE(mortonOrder(none, Real(0.1)).empty());
  EXPECT_EQ(mortonOrder(one, Real(0.1)), (std::vector<Index>{0}));
}

TEST(NeighbourGrid, CsrIdenticalForAnyThreadCount) {
  const std::vector<Vec3> x = randomCloud(5000, 11, Real(1));
  NeighbourLists reference;
  for (int threads : {1, 2, 4}) {
    for (bool hashing : {false, true}) {
      NeighbourGridSettings s;
      s.threads = threads;
      s.forceHashing = hashing;
      NeighbourGrid grid(s);
      grid.build(x, Real(0.08));
      NeighbourLists csr;
      grid.buildNeighbourLists(x, Real(0.08), csr);
      if (threads == 1 && !hashing) {
        reference = csr;
        ASSERT_GT(reference.indices.size(), 5000u);
        for (std::size_t i = 0; i + 1 < csr.offsets.size(); ++i)
          EXPECT_TRUE(std::is_sorted(csr.indices.begin() + csr.offsets[i], csr.indices.begin() + csr.offsets[i + 1]));
        continue;
      }
      EXPECT_EQ(csr.offsets, reference.offsets) << threads << " threads, hashing " << hashing;
      EXPECT_EQ(csr.indices, reference.indices) << threads << " threads, hashing " << hashing;
    }
  }
}

TEST(NeighbourGrid, MortonOrderIsPermutationAndPreservesNeighbourSets) {
  const Real h = Real(0.1);
  std::vector<Vec3> x = randomCloud(2000, 5, Real(1));
  x.emplace_back(Real(3e5), Real(0), Real(0));  // far outlier forces coarsened codes
  const std::vector<Index> order = mortonOrder(x, h);
  ASSERT_EQ(order.size(), x.size());
  std::vector<Index> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  std::vector<Index> identity(x.size());
  std::iota(identity.begin(), identity.end(), Index(0));
  EXPECT_EQ(sorted, identity);

  std::vector<Vec3> y = x;
  applyOrder(y, order);
  for (std::size_t k = 0; k < y.size(); ++k) ASSERT_EQ(y[k], x[order[k]]);

  // Neighbours of new slot k, mapped back to old indices, equal those of old particle order[k].
  NeighbourGrid grid;
  grid.build(y, h);
  NeighbourLists csr;
  grid.buildNeighbourLists(y, h, csr);
  const Lists expected = bruteForce(x, h);
  const Lists reordered = fromCsr(csr);
  for (std::size_t k = 0; k < y.size(); ++k) {
    std::vector<Index> mapped;
    for (const Index j : reordered[k]) mapped.push_back(order[j]);
    std::sort(mapped.begin(), mapped.end());
    ASSERT_EQ(mapped, expected[order[k]]) << "slot " << k;
  }

  // Locality: consecutive particles are much closer along the curve than in random order.
  auto pathLength = [](const std::vector<Vec3>& p) {
    double s = 0;
    for (std::size_t k = 0; k + 2 < p.size(); ++k) s += double((p[k + 1] - p[k]).norm());  // skip the outlier
    return s;
  };
  std::vector<Vec3> xNoOutlier(x.begin(), x.end() - 1);
  const std::vector<Index> order2 = mortonOrder(xNoOutlier, h);
  std::vector<Vec3> y2 = xNoOutlier;
  applyOrder(y2, order2);
  EXPECT_LT(pathLength(y2), 0.25 * pathLength(xNoOutlier));
}

TEST(NeighbourGrid, RebuildWithSameCountDoesNotReallocate) {
  std::vector<Vec3> x = randomCloud(3000, 3, Real(1));
  NeighbourGrid grid;
  NeighbourLists csr;
  grid.build(x, Real(0.1));
  grid.buildNeighbourLists(x, Real(0.1), csr);
  EXPECT_FALSE(grid.hashed());
  const auto* cellData = grid.cellStarts().data();
  const auto* sortedData = grid.sortedIndices().data();
  const auto* cellOfData = grid.particleCells().data();
  const auto* posData = grid.sortedPositions().data();
  const std::size_t cellCap = grid.cellStarts().capacity();
  const auto* offData = csr.offsets.data();
  const auto* idxData = csr.indices.data();

  auto expectSameBuffers = [&](const char* what) {
    SCOPED_TRACE(what);
    EXPECT_EQ(grid.cellStarts().data(), cellData);
    EXPECT_EQ(grid.cellStarts().capacity(), cellCap);
    EXPECT_EQ(grid.sortedIndices().data(), sortedData);
    EXPECT_EQ(grid.particleCells().data(), cellOfData);
    EXPECT_EQ(grid.sortedPositions().data(), posData);
  };
  // Same positions: CSR buffers are reused too.
  grid.build(x, Real(0.1));
  grid.buildNeighbourLists(x, Real(0.1), csr);
  expectSameBuffers("same positions");
  EXPECT_EQ(csr.offsets.data(), offData);
  EXPECT_EQ(csr.indices.data(), idxData);
  // Moved particles: a wider box (more dense cells) and then an outlier (hashed layout).
  for (auto& p : x) p *= Real(1.5);
  grid.build(x, Real(0.1));
  expectSameBuffers("wider box");
  x[17] = Vec3(Real(-4e4), Real(2e4), Real(9e4));
  grid.build(x, Real(0.1));
  EXPECT_TRUE(grid.hashed());
  expectSameBuffers("outlier, hashed");
}

}  // namespace
}  // namespace hs::pbd

namespace hs::pbd {
namespace {

// Slot lists (the fluid solver's fast path) against brute force: the neighbours of slot k
// are exactly the particles within the radius of sortedIndices()[k], as slots, ascending in
// the dense layout; identical for 1 and 2 threads; no reallocation once warmed up.
void checkSlotLists(const std::vector<Vec3>& x, Real h, bool forceHashing) {
  for (int threads : {1, 2}) {
    NeighbourGridSettings s;
    s.threads = threads;
    s.forceHashing = forceHashing;
    NeighbourGrid grid(s);
    grid.build(x, h);
    NeighbourLists lists;
    grid.buildSlotNeighbourLists(h, lists);
    const auto& sorted = grid.sortedIndices();
    ASSERT_EQ(lists.offsets.size(), x.size() + 1);
    for (std::size_t k = 0; k < x.size(); ++k) {
      const Index i = sorted[k];
      std::vector<Index> expected;
      for (Index j = 0; j < x.size(); ++j)
        if (j != i && (x[i] - x[j]).squaredNorm() < h * h) expected.push_back(j);
      std::vector<Index> got;
      for (Index e = lists.offsets[k]; e < lists.offsets[k + 1]; ++e) {
        if (e > lists.offsets[k]) {
          EXPECT_LT(lists.indices[e - 1], lists.indices[e]) << "slot " << k;
        }
        got.push_back(sorted[lists.indices[e]]);
      }
      std::sort(got.begin(), got.end());
      ASSERT_EQ(got, expected) << "slot " << k << " (particle " << i << "), threads " << threads;
    }
    // Rebuilding the same cloud reuses every buffer.
    const Index* before = lists.indices.data();
    const std::size_t capacity = lists.indices.capacity();
    grid.build(x, h);
    grid.buildSlotNeighbourLists(h, lists);
    EXPECT_EQ(lists.indices.data(), before);
    EXPECT_EQ(lists.indices.capacity(), capacity);
  }
}

TEST(NeighbourGridSlots, SlotListsEqualBruteForceOnRandomCloudsCellBoundariesAndOutliers) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1.5);
  const Real h = Real(0.25);
  std::vector<Vec3> cloud(3000);
  for (auto& p : cloud) p = Vec3(Real(u(rng)), Real(u(rng)), Real(u(rng)));
  checkSlotLists(cloud, h, false);
  checkSlotLists(cloud, h, true);
  // Particles exactly on cell boundaries and exactly h apart (excluded: strictly closer).
  std::vector<Vec3> lattice;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      for (int k = 0; k < 4; ++k) lattice.push_back(h * Vec3(Real(i), Real(j), Real(k)));
  checkSlotLists(lattice, h, false);
  // A few particles far outside the initial domain.
  std::vector<Vec3> outliers = cloud;
  outliers.resize(500);
  outliers.push_back(Vec3(1e6, 0, 0));
  outliers.push_back(Vec3(1e6, Real(0.1), 0));
  outliers.push_back(Vec3(-3e7, 5e5, 2e6));
  checkSlotLists(outliers, h, false);
}

}  // namespace
}  // namespace hs::pbd
