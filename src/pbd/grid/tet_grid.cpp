#include "pbd/grid/tet_grid.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>

#include "pbd/core/tet_geometry.h"

namespace hs::pbd {
namespace {

// Below this the dense grid is always allowed, so tiny meshes get a sensible resolution.
constexpr double kMinCells = 64;
// Each enlargement of the cells overshoots the cap's cube root by this factor, so the loop ends.
constexpr double kCellGrowth = 1.001;
// Cell coordinates along an axis are capped (only reached on the way to a grid within the cap).
constexpr double kMaxCoord = 1e15;
// Below this many entries copying the boxes on one thread beats a fork-join.
constexpr std::ptrdiff_t kParallelEntries = 32768;
// A tet's box spans 2 to 3 cells of half its extent along each axis (cellSizeFactor 0.5): up to
// 27 cells, the work per tet that decides whether binning forks.
constexpr std::size_t kCellsPerTet = 27;
// The boxes are computed in this many fixed chunks, whatever the thread count, so that the
// summed extent (and the cell size from it) is the same bits on any number of threads.
constexpr std::size_t kBoxChunks = 8;
// Below this many tets the boxes are computed on one thread.
constexpr std::size_t kParallelBoxes = 1024;

// The box of tet t over `vertices` grown by pad on every side; false if a corner is not finite
// (cwiseMin/Max may silently drop a NaN, so the corners are checked themselves).
bool paddedBox(const std::vector<Vec3>& vertices, const Tet& t, const Vec3& pad, Vec3& lo, Vec3& hi) {
  lo = hi = vertices[t[0]];
  bool allFinite = lo.allFinite();
  for (std::size_t k = 1; k < 4; ++k) {
    const Vec3& v = vertices[t[k]];
    allFinite = allFinite && v.allFinite();
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  lo -= pad;
  hi += pad;
  return allFinite && lo.allFinite() && hi.allFinite();
}

}  // namespace

TetGrid::BoxStats TetGrid::computeBoxes(const std::vector<Vec3>& vertices, const std::vector<Tet>& tets) {
  const std::size_t n = tets.size();
  m_lo.resize(n);
  m_hi.resize(n);
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::array<BoxStats, kBoxChunks> chunks;
  chunks.fill(BoxStats{{inf, inf, inf}, {-inf, -inf, -inf}});
  const Vec3 pad = Vec3::Constant(m_settings.padding);
  const auto chunkCount = std::ptrdiff_t(kBoxChunks);
#pragma omp parallel for schedule(static) num_threads(m_settings.threads) if (n >= kParallelBoxes)
  for (std::ptrdiff_t chunk = 0; chunk < chunkCount; ++chunk) {
    BoxStats& s = chunks[std::size_t(chunk)];
    for (std::size_t t = n * std::size_t(chunk) / kBoxChunks, end = n * std::size_t(chunk + 1) / kBoxChunks; t < end;
         ++t) {
      Vec3 a, b;
      if (!paddedBox(vertices, tets[t], pad, a, b)) {
        // An empty box (lo > hi) contains nothing; such a tet is entered in no cell.
        m_lo[t] = Vec3::Constant(std::numeric_limits<Real>::max());
        m_hi[t] = Vec3::Constant(std::numeric_limits<Real>::lowest());
        continue;
      }
      m_lo[t] = a;
      m_hi[t] = b;
      for (int k = 0; k < 3; ++k) {
        s.lo[std::size_t(k)] = std::min(s.lo[std::size_t(k)], double(a[k]));
        s.hi[std::size_t(k)] = std::max(s.hi[std::size_t(k)], double(b[k]));
      }
      s.extentSum += double((b - a).maxCoeff());
      ++s.finite;
    }
  }
  BoxStats all = chunks[0];
  for (std::size_t c = 1; c < kBoxChunks; ++c) {
    for (std::size_t k = 0; k < 3; ++k) {
      all.lo[k] = std::min(all.lo[k], chunks[c].lo[k]);
      all.hi[k] = std::max(all.hi[k], chunks[c].hi[k]);
    }
    all.extentSum += chunks[c].extentSum;
    all.finite += chunks[c].finite;
  }
  return all;
}

std::size_t TetGrid::sizeCells(const BoxStats& boxes, std::size_t tetCount) {
  if (boxes.finite == 0) {
    m_cellSize = 0;
    m_cells.dims = {0, 0, 0};
    return 0;
  }
  // Cell size from the mean extent, grown until the cell count respects the cap.
  double span = 0;
  for (std::size_t k = 0; k < 3; ++k) span = std::max(span, boxes.hi[k] - boxes.lo[k]);
  double cell = double(m_settings.cellSizeFactor) * boxes.extentSum / double(boxes.finite);
  if (!(cell > 0)) cell = span > 0 ? span : 1;  // every tet is a single point
  const double limit = double(m_settings.maxCellsPerTet) * double(tetCount) + kMinCells;
  const double cells = m_cells.coverWithin(boxes.lo, boxes.hi, cell, limit, kCellGrowth, kMaxCoord);
  m_cellSize = Real(m_cells.cellSize);
  // Reserve for the largest cell count this tet count allows, so that rebuilds with moved
  // vertices never reallocate the cell array.
  if (tetCount != m_reservedFor) {
    m_grid.reserve(std::size_t(limit), tetCount, m_settings.threads, kCellsPerTet);
    m_reservedFor = tetCount;
  }
  return std::size_t(cells);
}

void TetGrid::build(const std::vector<Vec3>& vertices, const std::vector<Tet>& tets) {
  assert(m_settings.cellSizeFactor > 0 && m_settings.padding >= 0 && m_settings.maxCellsPerTet > 0);
  const std::size_t n = tets.size();
  if (n >= std::size_t(std::numeric_limits<Index>::max())) throw std::length_error("TetGrid: too many tets");
  const std::size_t cellCount = sizeCells(computeBoxes(vertices, tets), n);
  // Each tet goes in the cells its box overlaps (none for an empty box).
  const bool fits = m_grid.bin(n, cellCount, m_settings.threads, [this](std::size_t t, auto&& emit) {
    CellBox r;
    if (m_cells.cellRange(m_lo[t], m_hi[t], r)) m_cells.forEachCell(r, [&emit](std::size_t cell, auto...) { emit(cell); });
  }, kCellsPerTet);
  if (!fits) throw std::length_error("TetGrid: too many entries");
  copyEntryBoxes();
}

void TetGrid::copyEntryBoxes() {
  const std::vector<Index>& items = m_grid.items();
  m_entryBoxes.resize(items.size());
  const auto entries = std::ptrdiff_t(items.size());
#pragma omp parallel for schedule(static) num_threads(m_settings.threads) if (entries >= kParallelEntries)
  for (std::ptrdiff_t e = 0; e < entries; ++e) {
    const Index t = items[std::size_t(e)];
    EntryBox& b = m_entryBoxes[std::size_t(e)];
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = m_lo[t][k];
      b.hi[k] = m_hi[t][k];
    }
    b.tet = t;
  }
}

bool TetGrid::refit(const std::vector<Vec3>& vertices, const std::vector<Tet>& tets) {
  const std::size_t n = tets.size();
  if (n != m_lo.size() || m_grid.entryCount() == 0) return false;
  m_refitLo.resize(n);
  m_refitHi.resize(n);
  const Vec3 pad = Vec3::Constant(m_settings.padding);
  // The cells of a box strictly inside the grid (no clamping): those it was entered in must be
  // the same, and a box poking out of the grid would lose the points beyond it.
  auto cellsOf = [this](const Vec3& lo, const Vec3& hi, CellBox& r) {
    for (int a = 0; a < 3; ++a) {
      const double tl = m_cells.axisCoord(double(lo[a]), a), th = m_cells.axisCoord(double(hi[a]), a);
      if (!(tl >= 0 && tl <= th && th < double(m_cells.dims[std::size_t(a)]))) return false;
      r.lo[a] = std::int64_t(tl);
      r.hi[a] = std::int64_t(th);
    }
    return true;
  };
  const auto count = std::ptrdiff_t(n);
  int moved = 0;
#pragma omp parallel for schedule(static) num_threads(m_settings.threads) reduction(+ : moved) if (n >= kParallelBoxes)
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    const auto t = std::size_t(k);
    Vec3 a, b;
    CellBox before, after;
    const bool same = paddedBox(vertices, tets[t], pad, a, b) && cellsOf(m_lo[t], m_hi[t], before) && cellsOf(a, b, after) &&
                      std::equal(before.lo, before.lo + 3, after.lo) && std::equal(before.hi, before.hi + 3, after.hi);
    moved += same ? 0 : 1;
    m_refitLo[t] = a;
    m_refitHi[t] = b;
  }
  if (moved > 0) return false;
  m_lo.swap(m_refitLo);
  m_hi.swap(m_refitHi);
  copyEntryBoxes();
  return true;
}

void TetGrid::candidates(const Vec3& p, std::vector<Index>& out) const {
  out.clear();
  forEachCandidate(p, [&out](Index t) { out.push_back(t); });
}

void TetGrid::tetsContaining(const Vec3& p, const std::vector<Vec3>& vertices, const std::vector<Tet>& tets,
                             Real tolerance, std::vector<Index>& out) const {
  assert(tets.size() == m_lo.size());
  out.clear();
  forEachCandidate(p, [&](Index t) {
    if (isPointInTet(tetPoints(vertices, tets[t]), p, tolerance)) out.push_back(t);
  });
}

}  // namespace hs::pbd
