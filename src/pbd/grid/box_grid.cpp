// Boxes binned into a uniform grid, see box_grid.h.
#include "pbd/grid/box_grid.h"

namespace hs::pbd {
namespace {

// Cells per box at most: the grid stays O(boxes) in memory however the boxes are spread.
constexpr double kMaxCellsPerBox = 8;
// A box of the mean size spans about two cells per axis: the work per box that decides whether
// binning forks.
constexpr std::size_t kCellsPerBox = 8;
// Cell coordinates are stored in 32 bits per axis.
constexpr double kMaxCoord = 1 << 30;

bool usable(const Box3& b) { return b.lo.allFinite() && b.hi.allFinite() && (b.lo.array() <= b.hi.array()).all(); }

}  // namespace

void BoxGrid::build(const std::vector<Box3>& boxes, int threads) {
  std::array<double, 3> lo{}, hi{};
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  double extent = 0;
  std::size_t used = 0;
  for (const Box3& b : boxes) {
    if (!usable(b)) continue;
    ++used;
    for (int a = 0; a < 3; ++a) {
      lo[std::size_t(a)] = std::min(lo[std::size_t(a)], double(b.lo[a]));
      hi[std::size_t(a)] = std::max(hi[std::size_t(a)], double(b.hi[a]));
    }
    extent += double((b.hi - b.lo).maxCoeff());
  }
  m_empty = used == 0;
  m_unbinned = false;
  m_firstCell.assign(boxes.size(), {0, 0, 0});
  if (m_empty) return;
  // The mean box's size: a box then spans about two cells per axis, a short query one or two.
  double edge = extent / double(used);
  double size = 0;
  for (std::size_t a = 0; a < 3; ++a) size = std::max(size, hi[a] - lo[a]);
  if (!(edge > 0)) edge = size > 0 ? size : 1;
  m_cells.coverWithin(lo, hi, edge, kMaxCellsPerBox * double(used) + 1, 1.05, kMaxCoord);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    CellBox r;
    if (!usable(boxes[i]) || !m_cells.cellRange(boxes[i].lo, boxes[i].hi, r)) continue;
    m_firstCell[i] = {std::int32_t(r.lo[0]), std::int32_t(r.lo[1]), std::int32_t(r.lo[2])};
  }
  const bool fits = m_grid.bin(boxes.size(), m_cells.cellCount(), threads, [&](std::size_t i, auto&& emit) {
    CellBox r;
    if (!usable(boxes[i]) || !m_cells.cellRange(boxes[i].lo, boxes[i].hi, r)) return;
    m_cells.forEachCell(r, [&](std::size_t cell, std::int64_t, std::int64_t, std::int64_t) { emit(cell); });
  }, kCellsPerBox);
  // Too many entries for an Index (never for a mesh that fits in memory): no grid, every query
  // goes to the caller's other structure.
  m_unbinned = !fits;
}

}  // namespace hs::pbd
