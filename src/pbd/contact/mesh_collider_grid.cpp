// The static mesh collider's triangle grid (mesh_collider_grid.h): building it over the
// triangles' planes, and the queries that are not templates.
#include "pbd/contact/mesh_collider_grid.h"

#include <limits>
#include <stdexcept>

#include "pbd/contact/mesh_collider.h"

namespace hs::pbd::detail {
namespace {

constexpr double kMinCellBudget = 65536, kCellsPerTriangle = 64;
// Each enlargement of the cells overshoots the budget's cube root by this factor, so it ends.
constexpr double kCellGrowth = 1.01;
constexpr std::int64_t kMaxQuickRows = 16;  // rows of cells the empty-neighbourhood test looks at

}  // namespace

// Ericson 5.2.3, plane against box: the box [lo, hi] clipped to the triangle's widened bounding
// box touches the slab |n . (x - a)| <= margin iff |n . (centre - a)| <= extents . |n| + margin.
bool planeTouchesBox(const ColliderTriangle& t, const double lo[3], const double hi[3], double margin) {
  double s = 0, r = 0;
  for (int a = 0; a < 3; ++a) {
    const double l = std::max(lo[a], double(t.boxLo[a])), h = std::min(hi[a], double(t.boxHi[a]));
    if (!(l <= h)) return false;
    const double n = double(t.normal[a]);
    s += n * (0.5 * (l + h) - double(t.a[a]));
    r += 0.5 * (h - l) * std::abs(n);
  }
  return std::abs(s) <= r + margin;
}

TriangleGrid::TriangleGrid(const ColliderGeometry& geometry, Real requestedCellSize) {
  const auto& triangles = geometry.triangles;
  if (triangles.empty()) return;
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::array<double, 3> lo{inf, inf, inf}, hi{-inf, -inf, -inf};
  for (const ColliderTriangle& t : triangles)
    for (std::size_t a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], double(t.boxLo[a]));
      hi[a] = std::max(hi[a], double(t.boxHi[a]));
    }
  const double budget = std::max(kMinCellBudget, kCellsPerTriangle * double(triangles.size()));
  const double cells = m_cells.coverWithin(lo, hi, double(requestedCellSize), budget, kCellGrowth, inf);

  const double pad = 1e-6 * m_cells.cellSize;  // covers rounding of the cell coordinates
  const bool fits = m_grid.bin(triangles.size(), std::size_t(cells), 1, [&](std::size_t k, auto&& emit) {
    const ColliderTriangle& t = triangles[k];
    CellBox r;
    if (!m_cells.cellRange(t.boxLo, t.boxHi, r)) return;
    m_cells.forEachCell(r, [&](std::size_t cell, std::int64_t x, std::int64_t y, std::int64_t z) {
      const std::int64_t c[3] = {x, y, z};
      double cl[3], ch[3];
      for (std::size_t a = 0; a < 3; ++a) {
        cl[a] = m_cells.origin[a] + double(c[a]) * m_cells.cellSize - pad;
        ch[a] = m_cells.origin[a] + double(c[a] + 1) * m_cells.cellSize + pad;
      }
      if (planeTouchesBox(t, cl, ch, 2 * double(t.slack))) emit(cell);
    });
  });
  if (!fits) throw std::length_error("StaticMeshCollider: too many (cell, triangle) pairs");
}

bool TriangleGrid::mayHaveAny(const Vec3& lo, const Vec3& hi) const {
  CellBox r;
  if (!m_cells.cellRange(lo, hi, r)) return false;
  if ((r.hi[1] - r.lo[1] + 1) * (r.hi[2] - r.lo[2] + 1) > kMaxQuickRows) return true;
  bool any = false;
  m_grid.forEachRun(m_cells, r, [&any](Index begin, Index end) { any = any || begin != end; });
  return any;
}

bool TriangleGrid::clipToGrid(const Vec3& p, const double d[3], double& t0, double& t1) const {
  for (std::size_t a = 0; a < 3; ++a) {
    const double lo = m_cells.origin[a] - m_cells.cellSize;
    const double hi = m_cells.origin[a] + double(m_cells.dims[a] + 1) * m_cells.cellSize;
    if (d[a] == 0) {
      if (double(p[a]) < lo || double(p[a]) > hi) return false;
      continue;
    }
    double ta = (lo - double(p[a])) / d[a], tb = (hi - double(p[a])) / d[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (!(t0 <= t1)) return false;
  }
  return true;
}

}  // namespace hs::pbd::detail
