// The non-template half of the shared cell grid (cell_grid.h): sizing the grid to a box, and
// the histogram and prefix-sum steps of the counting sort.
#include "pbd/grid/cell_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hs::pbd {
namespace {

// Below this many entries (items x their cells) one thread bins faster than a fork-join of two
// (a few microseconds).
constexpr std::size_t kMinParallelEntries = 8192;
// Cell counts along an axis are stored as integers; a larger count only occurs on the way to a
// grid within its cell budget and is never indexed.
constexpr double kMaxDim = 4611686018427387904.0;  // 2^62

}  // namespace

double CellIndexing::cover(const std::array<double, 3>& lo, const std::array<double, 3>& hi,
                           double maxCoord) {
  origin = lo;
  double cells = 1;
  for (std::size_t a = 0; a < 3; ++a) {
    const double n = std::floor(std::min((hi[a] - lo[a]) * invCell, maxCoord)) + 1;
    dims[a] = std::int64_t(std::min(n, kMaxDim));
    cells *= n;
  }
  return cells;
}

double CellIndexing::coverWithin(const std::array<double, 3>& lo, const std::array<double, 3>& hi,
                                 double edge, double maxCells, double growth, double maxCoord) {
  for (;;) {
    setCellSize(edge);
    const double cells = cover(lo, hi, maxCoord);
    if (cells <= maxCells) return cells;
    edge *= std::cbrt(cells / maxCells) * growth;
  }
}

int CellGrid::teamsFor(std::size_t itemCount, int threads, std::size_t cellsPerItem) {
  return threads > 1 && itemCount * std::max<std::size_t>(cellsPerItem, 1) >= kMinParallelEntries ? threads : 1;
}

void CellGrid::reserve(std::size_t cells, std::size_t items, int threads, std::size_t cellsPerItem) {
  m_offsets.reserve(cells + 1);
  m_items.reserve(items);
  m_counts.reserve(cells * std::size_t(teamsFor(items, threads, cellsPerItem)));
}

void CellGrid::startCounting(std::size_t cellCount, int teams) {
  m_offsets.resize(cellCount + 1);  // every entry is written by finishCounting
  m_counts.assign(cellCount * std::size_t(teams), 0);
}

bool CellGrid::finishCounting(std::size_t cellCount, int teams) {
  std::uint64_t running = 0;
  for (std::size_t c = 0; c < cellCount; ++c) {
    m_offsets[c] = Index(running);
    for (std::size_t t = 0; t < std::size_t(teams); ++t) {
      Index& count = m_counts[t * cellCount + c];
      running += count;
      count = Index(running);  // one past team t's last entry of cell c: the fill cursor
    }
  }
  if (running >= std::uint64_t(std::numeric_limits<Index>::max())) {
    m_offsets.assign(cellCount + 1, 0);
    m_items.clear();
    return false;
  }
  m_offsets[cellCount] = Index(running);
  // Headroom, so that a moving input whose entry count wobbles does not reallocate every build.
  if (running > m_items.capacity()) m_items.reserve(running + running / 4);
  m_items.resize(running);
  return true;
}

}  // namespace hs::pbd
