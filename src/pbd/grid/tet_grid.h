#pragma once
// A uniform grid over tetrahedra for point queries: "which tets may contain this point?"
// (the broad phase of particle–tetrahedron penetration, thesis section 4.4.1).
//
// Why these choices:
//  * Each tet is entered in every cell its axis-aligned bounding box overlaps, so a query reads
//    exactly one cell and meets each tet at most once: no duplicate removal, no 27-cell scan.
//  * Cell edge = cellSizeFactor x the mean bounding-box extent (largest side) of the tets. A
//    tet no larger than a cell overlaps at most 2 x 2 x 2 cells, so a mesh of similar tets costs
//    about 8 entries per tet and a query filters a handful of boxes.
//  * The tets move every step, so the grid is rebuilt every step: the counting sort of the
//    shared CellGrid (cell_grid.h), O(tets + cells + entries), into buffers reused between
//    builds. With the same tet count no build allocates once the entry buffer has
//    reached its working size (it grows with 25% headroom).
//  * The number of cells is capped at maxCellsPerTet x tets + 64: if a few tets fly apart and
//    the bounds explode, the cells grow instead of the memory. A query is still exact, it just
//    filters more boxes.
//  * Cell coordinates are computed in double from Real coordinates by the same monotone
//    expression for boxes and points, so a point inside a box always falls in one of the box's
//    cells: candidates are exactly the tets whose (padded) box contains the point.
//  * Queries are const and touch no mutable state: safe from any number of threads at once
//    (OpenMP loops over particles). Within a cell tets are listed in increasing index order.
#include <cassert>
#include <cmath>
#include <cstdint>
#include <vector>

#include "pbd/core/tet_mesh.h"
#include "pbd/core/types.h"
#include "pbd/grid/cell_grid.h"

namespace hs::pbd {

struct TetGridSettings {
  Real cellSizeFactor = 1;  // cell edge = factor x mean bounding-box extent of the tets
  Real padding = 0;         // every bounding box grows by this distance on all sides (>= 0)
  Real maxCellsPerTet = 8;  // cap on the dense cell count (see above)
  int threads = 1;          // OpenMP threads for build() (large meshes only; same grid for any count)
};

class TetGrid {
 public:
  explicit TetGrid(TetGridSettings settings = {}) : m_settings(settings) {}

  const TetGridSettings& settings() const { return m_settings; }
  void setSettings(const TetGridSettings& s) { m_settings = s; }

  // Bounding boxes of tets over `vertices`, sorted into cells. Tets with a non-finite vertex
  // are left out (never candidates). Queries see the geometry as of this call.
  void build(const std::vector<Vec3>& vertices, const std::vector<Tet>& tets);

  // Moves the boxes to `vertices` without binning again when every tet's padded box still
  // covers exactly the cells it was entered in and stays inside the grid. The queries then give
  // what a fresh build would (the tets whose box contains the point, in index order: the cells
  // only narrow the search), for the cost of copying the boxes. Returns false, changing
  // nothing, when a box left its cells or a vertex is not finite: build() then. A wall whose
  // constraints moved a few of its vertices by a fraction of a cell refits.
  [[nodiscard]] bool refit(const std::vector<Vec3>& vertices, const std::vector<Tet>& tets);

  // Calls f(tet) once for every tet whose padded bounding box contains p (boundary included),
  // in increasing tet index. Points outside the grid, and non-finite ones, have no candidates.
  template <class F>
  void forEachCandidate(const Vec3& p, F&& f) const {
    std::size_t cell;
    if (!cellOf(p, cell)) return;
    // The entries' own copies of their boxes: one contiguous read per cell, not two scattered
    // ones per candidate (most candidates of a cell at the wall are rejected by the box).
    for (Index k = m_grid.begin(cell), end = m_grid.end(cell); k < end; ++k) {
      const EntryBox& b = m_entryBoxes[k];
      // Non-short-circuit &: one well-predicted branch (most candidates fail) instead of six.
      if ((b.lo[0] <= p[0]) & (p[0] <= b.hi[0]) & (b.lo[1] <= p[1]) & (p[1] <= b.hi[1]) & (b.lo[2] <= p[2]) &
          (p[2] <= b.hi[2]))
        f(b.tet);
    }
  }

  // The candidates of p in `out` (cleared first), in increasing tet index.
  void candidates(const Vec3& p, std::vector<Index>& out) const;

  // The tets that contain p (isPointInTet with `tolerance`, in barycentric units), in increasing
  // index. `vertices` and `tets` must be those of the last build(). For tolerance > 0 set
  // settings().padding so that the grown tets stay inside the padded boxes.
  void tetsContaining(const Vec3& p, const std::vector<Vec3>& vertices, const std::vector<Tet>& tets,
                      Real tolerance, std::vector<Index>& out) const;

  Index tetCount() const { return Index(m_lo.size()); }
  Real cellSize() const { return m_cellSize; }
  std::size_t cellCount() const { return m_grid.cellCount(); }
  std::size_t entryCount() const { return m_grid.entryCount(); }

  // Runtime buffers, exposed for tests (allocation reuse) and diagnostics.
  const std::vector<Index>& cellStarts() const { return m_grid.offsets(); }
  const std::vector<Index>& entries() const { return m_grid.items(); }

 private:
  // Overall bounds, summed largest extent and count of the finite boxes.
  struct BoxStats {
    std::array<double, 3> lo, hi;
    double extentSum = 0;
    std::size_t finite = 0;
  };

  // Fills m_lo, m_hi with the padded bounding boxes of the tets.
  BoxStats computeBoxes(const std::vector<Vec3>& vertices, const std::vector<Tet>& tets);
  // Copies each entry's tet box (m_lo, m_hi) into m_entryBoxes.
  void copyEntryBoxes();
  // Sets m_cells and m_cellSize from the boxes; returns the cell count.
  std::size_t sizeCells(const BoxStats& boxes, std::size_t tetCount);

  // A cell entry: the tet and its padded box, in the grid's entry order.
  struct EntryBox {
    Real lo[3], hi[3];
    Index tet;
  };

  // Outside the grid no box can contain p (every box lies inside the bounds); also NaN.
  bool cellOf(const Vec3& p, std::size_t& cell) const { return m_grid.entryCount() > 0 && m_cells.cellOf(p, cell); }

  TetGridSettings m_settings;

  // Runtime state of the last build.
  Real m_cellSize = 0;
  CellIndexing m_cells;
  std::vector<Vec3> m_lo, m_hi;                 // padded bounding box of each tet (empty box if non-finite)
  std::vector<Vec3> m_refitLo, m_refitHi;       // refit()'s new boxes before they are accepted
  std::vector<EntryBox> m_entryBoxes;           // per grid entry: its tet and that tet's box
  CellGrid m_grid;                              // tet ids by cell; ascending within a cell
  std::size_t m_reservedFor = ~std::size_t(0);  // tet count m_grid was reserved for
};

}  // namespace hs::pbd
