#pragma once
// Axis-aligned boxes binned into a uniform grid of cells: the boxes near a small query box in a
// few memory reads. The broad phase's fast path for short queries (a particle's step against
// the moving wall, swept_contact.h); the BVH (triangle_bvh.h) answers the long ones.
//
// Why a grid beside the tree: a blood particle's step is a millimetre, the wall's triangles a
// few millimetres, and most particles are nowhere near the wall. The tree's upper boxes each
// cover a stretch of a curved wall and so much of the cavity, and every query walked a dozen
// of them before finding nothing; the grid's cell says "nothing here" in one read.
//
// Each box enters every cell its extent overlaps (CellGrid's counting sort), so a query sees a
// box once per shared cell. It is reported once, from the first shared cell only: the cell
// whose coordinates are, per axis, the larger of the two ranges' lower ends (the "reference
// point" test of Ericson 2004, "Real-Time Collision Detection", 7.1.6, on cell ranges).
//
// Exactness: a box and a query box that overlap share a point, and that point's cell lies in
// both cell ranges (CellIndexing::axisCoord is monotone), so every box overlapping the query
// is among the candidates. Candidates are a superset: the caller tests each exactly.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "pbd/core/types.h"
#include "pbd/grid/cell_grid.h"

namespace hs::pbd {

// An axis-aligned box; empty (lo > hi) when it holds nothing.
struct Box3 {
  Vec3 lo = Vec3::Constant(std::numeric_limits<Real>::infinity());
  Vec3 hi = Vec3::Constant(-std::numeric_limits<Real>::infinity());
  void grow(const Vec3& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  void grow(const Box3& b) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
  }
};

class BoxGrid {
 public:
  // Queries spanning more cells than this are left to the caller's other structure.
  static constexpr std::int64_t kMaxQueryCells = 27;

  // Bins `boxes` (empty or non-finite ones are left out; they overlap nothing) into cubic cells
  // of the boxes' mean largest extent, grown until there are at most 8 cells per box.
  void build(const std::vector<Box3>& boxes, int threads = 1);

  // Calls f(box index) once for every box whose cell range overlaps that of [lo, hi] (a
  // superset of the boxes overlapping it), in cell order. Returns false, calling nothing, when
  // the query spans more than kMaxQueryCells cells or is not finite: the caller must answer it
  // another way. An empty grid answers every finite query with nothing.
  template <class F>
  [[nodiscard]] bool forEachCandidate(const std::array<double, 3>& lo, const std::array<double, 3>& hi, F&& f) const;

  [[nodiscard]] double cellSize() const { return m_cells.cellSize; }
  [[nodiscard]] std::size_t cellCount() const { return m_cells.cellCount(); }

 private:
  CellIndexing m_cells;
  CellGrid m_grid;
  std::vector<std::array<std::int32_t, 3>> m_firstCell;  // per box: its cell range's lower corner
  bool m_empty = true;      // no usable box: every finite query finds nothing
  bool m_unbinned = false;  // too many entries to bin: every query goes elsewhere
};

template <class F>
bool BoxGrid::forEachCandidate(const std::array<double, 3>& lo, const std::array<double, 3>& hi, F&& f) const {
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(lo[std::size_t(a)]) || !std::isfinite(hi[std::size_t(a)])) return false;
  if (m_empty) return true;
  if (m_unbinned) return false;
  // The query's cells, before clamping to the grid: its size decides the path.
  double span = 1;
  for (int a = 0; a < 3; ++a)
    span *= std::floor(m_cells.axisCoord(hi[std::size_t(a)], a)) - std::floor(m_cells.axisCoord(lo[std::size_t(a)], a)) + 1;
  if (!(span <= double(kMaxQueryCells))) return false;
  CellBox r;
  if (!m_cells.cellRange(lo.data(), hi.data(), r)) return true;  // off the grid: no box there
  const bool single = r.lo[0] == r.hi[0] && r.lo[1] == r.hi[1] && r.lo[2] == r.hi[2];
  m_cells.forEachCell(r, [&](std::size_t cell, std::int64_t x, std::int64_t y, std::int64_t z) {
    const std::int64_t at[3] = {x, y, z};
    for (Index e = m_grid.begin(cell); e < m_grid.end(cell); ++e) {
      const Index item = m_grid.item(e);
      if (!single) {
        // Report from the first cell the two ranges share only.
        const std::array<std::int32_t, 3>& first = m_firstCell[item];
        bool reference = true;
        for (int a = 0; a < 3 && reference; ++a)
          reference = at[a] == std::max<std::int64_t>(r.lo[a], first[std::size_t(a)]);
        if (!reference) continue;
      }
      f(std::size_t(item));
    }
  });
  return true;
}

}  // namespace hs::pbd
