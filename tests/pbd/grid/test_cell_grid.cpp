// CellGrid and CellIndexing against brute force: every item is listed in exactly the cells its
// box overlaps, in increasing index, for boxes and points, negative coordinates, one cell,
// empty input and items in no cell; 1 and 2 threads give the same grid; the cell budget.
// Coordinates are multiples of 1/64 and cells 1/4 wide, so the brute force's overlap test is
// exact arithmetic.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "pbd/grid/cell_grid.h"

namespace hs::pbd {
namespace {

struct Box {
  Vec3 lo, hi;
};

constexpr double kCell = 0.25;

// Boxes with corners on a 1/64 grid inside [from, to]^3, at most maxSide wide.
std::vector<Box> randomBoxes(std::size_t n, int from, int to, double maxSide, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> corner(from * 64, to * 64);
  std::uniform_int_distribution<int> side(0, int(maxSide * 64));
  std::vector<Box> boxes(n);
  for (Box& b : boxes)
    for (int a = 0; a < 3; ++a) {
      const int lo = corner(rng);
      b.lo[a] = Real(lo / 64.0);
      b.hi[a] = Real(std::min(lo + side(rng), to * 64) / 64.0);
    }
  return boxes;
}

CellIndexing indexingOver(const std::vector<Box>& boxes) {
  std::array<double, 3> lo{1e30, 1e30, 1e30}, hi{-1e30, -1e30, -1e30};
  for (const Box& b : boxes)
    for (std::size_t a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], double(b.lo[a]));
      hi[a] = std::max(hi[a], double(b.hi[a]));
    }
  CellIndexing cells;
  cells.setCellSize(kCell);
  cells.cover(lo, hi, 1e15);
  return cells;
}

CellGrid binBoxes(const CellIndexing& cells, const std::vector<Box>& boxes, int threads) {
  CellGrid grid;
  const bool fits = grid.bin(boxes.size(), cells.cellCount(), threads, [&](std::size_t i, auto&& emit) {
    CellBox r;
    if (cells.cellRange(boxes[i].lo, boxes[i].hi, r))
      cells.forEachCell(r, [&emit](std::size_t cell, auto...) { emit(cell); });
  });
  EXPECT_TRUE(fits);
  return grid;
}

// Brute force: the items of cell (x, y, z) are the boxes meeting its half-open box, ascending.
void expectMatchesBruteForce(const CellIndexing& cells, const CellGrid& grid, const std::vector<Box>& boxes) {
  ASSERT_EQ(grid.cellCount(), cells.cellCount());
  std::size_t entries = 0;
  for (std::int64_t z = 0; z < cells.dims[2]; ++z)
    for (std::int64_t y = 0; y < cells.dims[1]; ++y)
      for (std::int64_t x = 0; x < cells.dims[0]; ++x) {
        const std::int64_t c[3] = {x, y, z};
        std::vector<Index> expected;
        for (std::size_t i = 0; i < boxes.size(); ++i) {
          bool meets = true;
          for (std::size_t a = 0; a < 3; ++a) {
            const double cellLo = cells.origin[a] + double(c[a]) * kCell;
            meets = meets && double(boxes[i].lo[int(a)]) < cellLo + kCell &&
                    double(boxes[i].hi[int(a)]) >= cellLo;
          }
          if (meets) expected.push_back(Index(i));
        }
        const std::size_t cell = std::size_t(cells.cellIndex(x, y, z));
        const std::vector<Index> got(grid.items().begin() + grid.begin(cell),
                                     grid.items().begin() + grid.end(cell));
        ASSERT_EQ(got, expected) << "cell " << x << ' ' << y << ' ' << z;
        entries += got.size();
      }
  EXPECT_EQ(grid.entryCount(), entries);
  EXPECT_EQ(grid.offsets().back(), Index(entries));
}

TEST(CellGrid, BoxesMatchBruteForce) {
  const std::vector<Box> boxes = randomBoxes(600, 0, 3, 0.6, 1);
  const CellIndexing cells = indexingOver(boxes);
  EXPECT_EQ(cells.cellCount(), 13u * 13u * 13u);
  expectMatchesBruteForce(cells, binBoxes(cells, boxes, 1), boxes);
}

TEST(CellGrid, NegativeCoordinates) {
  const std::vector<Box> boxes = randomBoxes(400, -5, -3, 0.4, 2);
  const CellIndexing cells = indexingOver(boxes);
  EXPECT_LT(cells.origin[0], -4.9);
  expectMatchesBruteForce(cells, binBoxes(cells, boxes, 1), boxes);
}

TEST(CellGrid, PointsMatchBruteForce) {
  std::vector<Box> points = randomBoxes(500, -1, 1, 0, 3);
  const CellIndexing cells = indexingOver(points);
  const CellGrid grid = binBoxes(cells, points, 1);
  expectMatchesBruteForce(cells, grid, points);
  EXPECT_EQ(grid.entryCount(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::size_t cell = 0;
    ASSERT_TRUE(cells.cellOf(points[i].lo, cell));
    const auto first = grid.items().begin() + grid.begin(cell), last = grid.items().begin() + grid.end(cell);
    EXPECT_NE(std::find(first, last, Index(i)), last);
  }
  std::size_t cell = 0;
  EXPECT_FALSE(cells.cellOf(Vec3(Real(-1.5), 0, 0), cell));
  EXPECT_FALSE(cells.cellOf(Vec3(0, std::nan(""), 0), cell));
}

TEST(CellGrid, OneCell) {
  const std::vector<Box> boxes(
      5, Box{Vec3(Real(0.5), Real(0.5), Real(0.5)), Vec3(Real(0.5), Real(0.5), Real(0.5))});
  const CellIndexing cells = indexingOver(boxes);
  ASSERT_EQ(cells.cellCount(), 1u);
  const CellGrid grid = binBoxes(cells, boxes, 1);
  EXPECT_EQ(grid.offsets(), (std::vector<Index>{0, 5}));
  EXPECT_EQ(grid.items(), (std::vector<Index>{0, 1, 2, 3, 4}));
}

TEST(CellGrid, EmptyInputAndItemsInNoCell) {
  CellGrid grid;
  ASSERT_TRUE(grid.bin(0, 7, 2, [](std::size_t, auto&&) {}));
  EXPECT_EQ(grid.offsets(), std::vector<Index>(8, 0));
  EXPECT_EQ(grid.entryCount(), 0u);
  ASSERT_TRUE(grid.bin(0, 0, 1, [](std::size_t, auto&&) {}));
  EXPECT_EQ(grid.cellCount(), 0u);
  // Odd items go nowhere; even ones to cell i % 3.
  ASSERT_TRUE(grid.bin(10, 3, 1, [](std::size_t i, auto&& emit) {
    if (i % 2 == 0) emit(i % 3);
  }));
  EXPECT_EQ(grid.offsets(), (std::vector<Index>{0, 2, 3, 5}));
  EXPECT_EQ(grid.items(), (std::vector<Index>{0, 6, 4, 2, 8}));
  // A box beside the grid, or empty, has no cells.
  const CellIndexing cells = indexingOver(randomBoxes(10, 0, 1, 0.5, 4));
  CellBox r;
  EXPECT_FALSE(cells.cellRange(Vec3(Real(-2), 0, 0), Vec3(Real(-1), 0, 0), r));
  EXPECT_FALSE(cells.cellRange(Vec3(Real(0.5), 0, 0), Vec3(Real(0.25), 0, 0), r));
  EXPECT_FALSE(CellIndexing{}.cellRange(Vec3::Zero(), Vec3::Zero(), r));
}

TEST(CellGrid, OneAndTwoThreadsGiveTheSameGrid) {
  // Enough items for the parallel sort, and a rebuild into the same grid object.
  const std::vector<Box> boxes = randomBoxes(30000, -2, 2, 0.3, 5);
  const CellIndexing cells = indexingOver(boxes);
  const CellGrid one = binBoxes(cells, boxes, 1);
  const CellGrid two = binBoxes(cells, boxes, 2);
  EXPECT_EQ(one.offsets(), two.offsets());
  EXPECT_EQ(one.items(), two.items());
  CellGrid again = binBoxes(cells, boxes, 2);
  ASSERT_TRUE(again.bin(boxes.size(), cells.cellCount(), 2, [&](std::size_t i, auto&& emit) {
    std::size_t cell;
    if (cells.cellOf(boxes[i].lo, cell)) emit(cell);
  }));
  const CellGrid pointsOne = [&] {
    CellGrid g;
    EXPECT_TRUE(g.bin(boxes.size(), cells.cellCount(), 1, [&](std::size_t i, auto&& emit) {
      std::size_t cell;
      if (cells.cellOf(boxes[i].lo, cell)) emit(cell);
    }));
    return g;
  }();
  EXPECT_EQ(again.offsets(), pointsOne.offsets());
  EXPECT_EQ(again.items(), pointsOne.items());
  const std::vector<Box> few(boxes.begin(), boxes.begin() + 300);
  expectMatchesBruteForce(cells, binBoxes(cells, few, 2), few);
}

TEST(CellIndexing, CoverWithinKeepsTheBudget) {
  CellIndexing cells;
  const double count = cells.coverWithin({-1, 0, 0}, {99, 10, 1}, 0.01, 1000, 1.01, 1e15);
  EXPECT_LE(count, 1000);
  EXPECT_EQ(double(cells.cellCount()), count);
  EXPECT_GT(cells.cellSize, 0.01);
  EXPECT_EQ(cells.origin[0], -1);
  // Every corner of the box falls in a cell.
  std::size_t cell;
  EXPECT_TRUE(cells.cellOf(Vec3(Real(99), Real(10), Real(1)), cell));
  EXPECT_TRUE(cells.cellOf(Vec3(Real(-1), 0, 0), cell));
  EXPECT_EQ(cell, 0u);
}

}  // namespace
}  // namespace hs::pbd
