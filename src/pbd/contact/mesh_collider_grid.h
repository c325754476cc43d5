#pragma once
// The broad phase of the static mesh collider (mesh_collider.h): a uniform grid over the
// triangles (the shared CellGrid, cell_grid.h), cell edge about 2-4 particle radii. A triangle
// is entered in the cells of its widened bounding box that its plane passes through (Ericson
// 2005, "Real-Time Collision Detection", 5.2.3, plane against box), so a large tilted wall does
// not fill the whole volume of its bounding box. The queries offer candidates for a box and for
// a segment; the collision response (mesh_collider.cpp) filters them exactly.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "pbd/core/types.h"
#include "pbd/grid/cell_grid.h"

namespace hs::pbd::detail {

struct ColliderTriangle;
struct ColliderGeometry;

// Does the box [lo, hi], clipped to the triangle's widened bounding box, touch the slab
// |n . (x - a)| <= margin around its plane?
bool planeTouchesBox(const ColliderTriangle& t, const double lo[3], const double hi[3], double margin);

// Candidates are positions in ColliderGeometry::triangles; each cell lists them ascending.
class TriangleGrid {
 public:
  TriangleGrid() = default;
  // Cells of edge requestedCellSize, enlarged while the grid would need more than
  // max(65536, 64 * triangles) cells (a big, mostly empty container with small particles).
  // Throws std::length_error if the (cell, triangle) pairs overflow an Index.
  TriangleGrid(const ColliderGeometry& geometry, Real requestedCellSize);

  double cellSize() const { return m_cells.cellSize; }
  std::size_t cellCount() const { return m_grid.cellCount(); }
  std::size_t entryCount() const { return m_grid.entryCount(); }

  // False only if every cell overlapping [lo, hi] is empty; true without looking for large boxes.
  bool mayHaveAny(const Vec3& lo, const Vec3& hi) const;

  // f(k) for every triangle entered in a cell overlapping [lo, hi] (a triangle may come more
  // than once).
  template <class F>
  void inBox(const Vec3& lo, const Vec3& hi, F&& f) const {
    CellBox r;
    if (m_cells.cellRange(lo, hi, r)) m_grid.forEachItem(m_cells, r, f);
  }

  // f(k) at least for every triangle within `slack` of the segment p -> q, piece by piece along
  // it, stopping after the piece that reaches parameter `best` (the caller lowers it as it finds
  // crossings).
  template <class F>
  void alongSegment(const Vec3& p, const Vec3& q, Real slack, const Real& best, F&& f) const;

 private:
  // The part [t0, t1] of the segment p + t d, t in [0, 1], inside the grid's box widened by a
  // cell (slab method, Ericson 5.3.3); false if none.
  bool clipToGrid(const Vec3& p, const double d[3], double& t0, double& t1) const;

  CellIndexing m_cells;
  CellGrid m_grid;
};

template <class F>
void TriangleGrid::alongSegment(const Vec3& p, const Vec3& q, Real slack, const Real& best, F&& f) const {
  // No triangle lies outside the grid's box; widened by a cell so rounding cannot matter.
  double t0 = 0, t1 = 1;
  const double d[3] = {double(q[0]) - double(p[0]), double(q[1]) - double(p[1]), double(q[2]) - double(p[2])};
  if (!clipToGrid(p, d, t0, t1)) return;
  // Pieces about a cell long: the cells of each piece's box, not of the whole segment's box
  // (mostly empty space for a long diagonal move). Pieces go in order along the segment, so
  // once a crossing is found no later piece can hold an earlier one.
  constexpr int kMaxSegmentPieces = 64;
  const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) * (t1 - t0);
  const int pieces = int(std::clamp(std::ceil(length / m_cells.cellSize), 1.0, double(kMaxSegmentPieces)));
  for (int k = 0; k < pieces; ++k) {
    const double s0 = t0 + (t1 - t0) * k / pieces,
                 s1 = k + 1 == pieces ? t1 : t0 + (t1 - t0) * (k + 1) / pieces;
    double l[3], h[3];
    for (int a = 0; a < 3; ++a) {
      const double x0 = double(p[a]) + s0 * d[a], x1 = double(p[a]) + s1 * d[a];
      l[a] = std::min(x0, x1) - double(slack);
      h[a] = std::max(x0, x1) + double(slack);
    }
    CellBox r;
    if (m_cells.cellRange(l, h, r)) m_grid.forEachItem(m_cells, r, f);
    if (double(best) <= s1) return;
  }
}

}  // namespace hs::pbd::detail
