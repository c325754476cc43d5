// BoxGrid against brute force: every box overlapping a query box is a candidate, reported
// once; queries too large for the grid are refused, not answered partly.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

#include "pbd/grid/box_grid.h"

namespace hs::pbd {
namespace {

bool overlaps(const Box3& b, const std::array<double, 3>& lo, const std::array<double, 3>& hi) {
  for (int a = 0; a < 3; ++a)
    if (!(double(b.lo[a]) <= hi[std::size_t(a)] && lo[std::size_t(a)] <= double(b.hi[a]))) return false;
  return true;
}

std::vector<Box3> randomBoxes(std::size_t count, std::mt19937& rng) {
  std::uniform_real_distribution<Real> u(-1, 1), size(Real(0), Real(0.15));
  std::vector<Box3> boxes(count);
  for (Box3& b : boxes) {
    b.grow(Vec3(u(rng), u(rng), u(rng)));
    b.grow(b.lo + Vec3(size(rng), size(rng), size(rng)));
  }
  return boxes;
}

TEST(BoxGrid, ReportsEveryOverlappingBoxOnce) {
  std::mt19937 rng(11);
  for (std::size_t count : {std::size_t(1), std::size_t(7), std::size_t(500)}) {
    SCOPED_TRACE(count);
    std::vector<Box3> boxes = randomBoxes(count, rng);
    boxes.push_back(Box3{});  // empty: never a candidate
    BoxGrid grid;
    grid.build(boxes);
    std::uniform_real_distribution<double> u(-1.2, 1.2), hop(0, 0.1);
    std::size_t answered = 0, found = 0;
    for (int q = 0; q < 2000; ++q) {
      const std::array<double, 3> lo{u(rng), u(rng), u(rng)};
      const double reach = q % 5 == 0 ? 1.0 : hop(rng);
      const std::array<double, 3> hi{lo[0] + reach, lo[1] + hop(rng), lo[2] + (q % 3 == 0 ? 0.0 : hop(rng))};
      std::vector<std::size_t> candidates;
      if (!grid.forEachCandidate(lo, hi, [&](std::size_t b) { candidates.push_back(b); })) {
        EXPECT_TRUE(candidates.empty()) << "a refused query must report nothing";
        continue;
      }
      ++answered;
      std::sort(candidates.begin(), candidates.end());
      EXPECT_TRUE(std::adjacent_find(candidates.begin(), candidates.end()) == candidates.end()) << "query " << q;
      for (std::size_t b = 0; b < boxes.size(); ++b) {
        if (!overlaps(boxes[b], lo, hi)) continue;
        ++found;
        EXPECT_TRUE(std::binary_search(candidates.begin(), candidates.end(), b)) << "query " << q << " box " << b;
      }
      EXPECT_FALSE(std::binary_search(candidates.begin(), candidates.end(), boxes.size() - 1)) << "the empty box";
    }
    EXPECT_GE(answered, 1000u) << "short queries must be answered by the grid";
    if (count > 100) {
      EXPECT_GE(found, 200u) << "the queries must meet boxes often enough to test something";
    }
  }
}

TEST(BoxGrid, RefusesLongAndNonFiniteQueriesAndAnswersEmptyGrids) {
  std::mt19937 rng(2);
  BoxGrid grid;
  grid.build(randomBoxes(200, rng));
  int calls = 0;
  EXPECT_FALSE(grid.forEachCandidate({-1, -1, -1}, {1, 1, 1}, [&](std::size_t) { ++calls; }));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(grid.forEachCandidate({nan, 0, 0}, {0, 0, 0}, [&](std::size_t) { ++calls; }));
  EXPECT_TRUE(grid.forEachCandidate({5, 5, 5}, {5.01, 5.01, 5.01}, [&](std::size_t) { ++calls; })) << "off the grid";
  BoxGrid empty;
  empty.build({Box3{}});
  EXPECT_TRUE(empty.forEachCandidate({-1, -1, -1}, {1, 1, 1}, [&](std::size_t) { ++calls; }));
  EXPECT_EQ(calls, 0);
}

}  // namespace
}  // namespace hs::pbd
