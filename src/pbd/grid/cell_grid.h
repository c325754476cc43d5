#pragma once
// The uniform cell grid shared by the engine's spatial searches (NeighbourGrid, TetGrid and the
// static mesh collider's triangle grid): a box cut into cubic cells (CellIndexing) and the items
// of every cell as compressed rows, offsets + items (CellGrid), filled by a counting sort
// (histogram, prefix sum, scatter; Green 2010, "Particle Simulation using CUDA").
//
// Why these choices:
//  * Counting sort: cell keys are small integers, so binning is O(items + cells) with no
//    comparisons, into buffers reused between builds.
//  * Within a cell, items come in increasing index. The users' results depend on the order in
//    which they visit candidates (sums, first-found ties), so the order is fixed by the input
//    alone, whatever the thread count.
//  * In parallel the items are cut into one contiguous chunk per thread, each thread counts its
//    chunk into a histogram of its own, and the prefix sum runs over (cell, thread) in that
//    order, so thread t's entries of a cell follow thread t-1's: the same items in the same
//    order as one thread (the local-histogram radix sort of Satish, Harris & Garland 2009,
//    "Designing efficient sorting algorithms for manycore GPUs").
//  * Cells are numbered x fastest: the cells (x0..x1, y, z) of a row are consecutive, so the
//    items of a box of cells are one contiguous run per row.
#include <omp.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pbd/core/types.h"

namespace hs::pbd {

// An inclusive range of cell coordinates, lo[a] <= hi[a] on every axis.
struct CellBox {
  std::int64_t lo[3], hi[3];
};

// Cell (x, y, z) covers origin + cellSize * [x, x + 1) x [y, y + 1) x [z, z + 1); its index is
// (z * dims[1] + y) * dims[0] + x.
struct CellIndexing {
  std::array<double, 3> origin{0, 0, 0};
  double cellSize = 1;
  double invCell = 1;
  std::array<std::int64_t, 3> dims{0, 0, 0};

  void setCellSize(double edge) {
    cellSize = edge;
    invCell = 1.0 / edge;
  }

  // The one expression for the cell coordinate of v along axis a, for boxes and points alike:
  // it is monotone in v, so a point inside a box falls in one of the box's cells.
  double axisCoord(double v, int a) const { return (v - origin[std::size_t(a)]) * invCell; }

  std::size_t cellCount() const { return std::size_t(dims[0] * dims[1] * dims[2]); }
  std::int64_t cellIndex(std::int64_t x, std::int64_t y, std::int64_t z) const {
    return (z * dims[1] + y) * dims[0] + x;
  }

  // Origin at lo and the cells along each axis that cover [lo, hi]:
  // floor(min((hi - lo) / cellSize, maxCoord)) + 1. Returns the cell count, in double (the
  // product may not fit an integer).
  double cover(const std::array<double, 3>& lo, const std::array<double, 3>& hi, double maxCoord);

  // cover() with the cell edge grown from `edge` (by cbrt(cells / maxCells) x growth at a time)
  // until the grid has at most maxCells cells. Returns the cell count.
  double coverWithin(const std::array<double, 3>& lo, const std::array<double, 3>& hi, double edge,
                     double maxCells, double growth, double maxCoord);

  // The cells overlapping the box [lo, hi], clamped to the grid; false if the box misses the
  // grid, is empty (lo > hi) or NaN.
  bool cellRange(const double lo[3], const double hi[3], CellBox& r) const {
    if (dims[0] <= 0) return false;
    for (int a = 0; a < 3; ++a) {
      const double tl = axisCoord(lo[a], a), th = axisCoord(hi[a], a);
      const double top = double(dims[std::size_t(a)] - 1);
      if (!(th >= 0) || !(tl < top + 1) || !(tl <= th)) return false;
      r.lo[a] = tl <= 0 ? 0 : std::int64_t(tl);
      r.hi[a] = std::int64_t(std::min(th, top));
    }
    return true;
  }

  bool cellRange(const Vec3& lo, const Vec3& hi, CellBox& r) const {
    const double l[3] = {double(lo[0]), double(lo[1]), double(lo[2])};
    const double h[3] = {double(hi[0]), double(hi[1]), double(hi[2])};
    return cellRange(l, h, r);
  }

  // Calls f(cell, x, y, z) for every cell (x, y, z) of box r, x fastest.
  template <class F>
  void forEachCell(const CellBox& r, F&& f) const {
    for (std::int64_t z = r.lo[2]; z <= r.hi[2]; ++z)
      for (std::int64_t y = r.lo[1]; y <= r.hi[1]; ++y)
        for (std::int64_t x = r.lo[0]; x <= r.hi[0]; ++x) f(std::size_t(cellIndex(x, y, z)), x, y, z);
  }

  // The cell holding point p; false outside the grid (and for NaN).
  bool cellOf(const Vec3& p, std::size_t& cell) const {
    std::int64_t c[3];
    for (int a = 0; a < 3; ++a) {
      const double t = axisCoord(double(p[a]), a);
      if (!(t >= 0 && t < double(dims[std::size_t(a)]))) return false;
      c[a] = std::int64_t(t);
    }
    cell = std::size_t(cellIndex(c[0], c[1], c[2]));
    return true;
  }
};

// Items binned into cells as compressed rows: cell c holds items()[offsets()[c] ..
// offsets()[c + 1]), in increasing item index.
class CellGrid {
 public:
  // Counting sort of items 0 .. itemCount-1 into cellCount cells: cellsOf(i, emit) calls
  // emit(cell) once for every cell of item i (cell < cellCount; any number of cells, in any
  // order, none to leave the item out). cellsOf is called twice per item (count, then fill),
  // from `threads` threads at once when there is enough work: itemCount x cellsPerItem (the
  // caller's estimate of an item's cells; a tet's box spans up to 27). Returns false, leaving
  // the grid empty, when the entries would overflow an Index.
  template <class CellsOf>
  [[nodiscard]] bool bin(std::size_t itemCount, std::size_t cellCount, int threads, const CellsOf& cellsOf,
                         std::size_t cellsPerItem = 1);

  // Buffers for later builds of `items` items (and at least as many entries) into `cells`
  // cells on `threads` threads, so that they do not allocate.
  void reserve(std::size_t cells, std::size_t items, int threads = 1, std::size_t cellsPerItem = 1);

  // Threads bin() runs on for itemCount items of about cellsPerItem cells each (1 below the
  // work where a fork-join pays): also the right team for a user's own per-item loops around it.
  static int teamsFor(std::size_t itemCount, int threads, std::size_t cellsPerItem = 1);

  std::size_t cellCount() const { return m_offsets.empty() ? 0 : m_offsets.size() - 1; }
  std::size_t entryCount() const { return m_items.size(); }
  Index begin(std::size_t cell) const { return m_offsets[cell]; }
  Index end(std::size_t cell) const { return m_offsets[cell + 1]; }
  Index item(Index entry) const { return m_items[entry]; }
  const std::vector<Index>& offsets() const { return m_offsets; }
  const std::vector<Index>& items() const { return m_items; }

  // Calls run(begin, end) for the entries of each row of cells (r.lo[0] .. r.hi[0], y, z) of
  // box r, rows in increasing cell index.
  template <class F>
  void forEachRun(const CellIndexing& cells, const CellBox& r, F&& run) const {
    for (std::int64_t z = r.lo[2]; z <= r.hi[2]; ++z)
      for (std::int64_t y = r.lo[1]; y <= r.hi[1]; ++y) {
        const std::int64_t row = cells.cellIndex(0, y, z);
        run(m_offsets[std::size_t(row + r.lo[0])], m_offsets[std::size_t(row + r.hi[0] + 1)]);
      }
  }

  // Calls f(item) for every entry of the cells of box r, rows in increasing cell index.
  template <class F>
  void forEachItem(const CellIndexing& cells, const CellBox& r, F&& f) const {
    forEachRun(cells, r, [&](Index begin, Index end) {
      for (Index e = begin; e < end; ++e) f(m_items[e]);
    });
  }

 private:
  // Zeroed histograms, one per team, each of cellCount counts.
  void startCounting(std::size_t cellCount, int teams);
  // The prefix sum over (cell, team): offsets, each team's fill cursors, the item buffer.
  bool finishCounting(std::size_t cellCount, int teams);

  std::vector<Index> m_offsets;  // cells + 1
  std::vector<Index> m_items;    // item ids by cell
  std::vector<Index> m_counts;   // team t's count (then fill cursor) of cell c at t * cells + c
};

template <class CellsOf>
bool CellGrid::bin(std::size_t itemCount, std::size_t cellCount, int threads, const CellsOf& cellsOf,
                   std::size_t cellsPerItem) {
  const int teams = teamsFor(itemCount, threads, cellsPerItem);
  startCounting(cellCount, teams);
  bool fits = true;
#pragma omp parallel num_threads(teams) if (teams > 1)
  {
    // omp_get_num_threads() may be below `teams`; the surplus histograms stay zero.
    const std::size_t t = std::size_t(omp_get_thread_num()), parts = std::size_t(omp_get_num_threads());
    const std::size_t first = itemCount * t / parts, last = itemCount * (t + 1) / parts;
    Index* const count = m_counts.data() + t * cellCount;
    for (std::size_t i = first; i < last; ++i) cellsOf(i, [count](std::size_t cell) { ++count[cell]; });
#pragma omp barrier
#pragma omp single
    fits = finishCounting(cellCount, teams);
    // The implicit barrier of `single` publishes the cursors. Backwards, decrementing: each
    // team's entries of a cell end in increasing item order.
    if (fits) {
      Index* const items = m_items.data();
      for (std::size_t i = last; i-- > first;)
        cellsOf(i, [count, items, i](std::size_t cell) { items[--count[cell]] = Index(i); });
    }
  }
  return fits;
}

}  // namespace hs::pbd
