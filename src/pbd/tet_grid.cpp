#include "pbd/tet_grid.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "pbd/tet_geometry.h"

namespace hs::pbd {
namespace {

// Below this the dense grid is always allowed, so tiny meshes get a sensible resolution.
constexpr double kMinCells = 64;

}  // namespace

void TetGrid::build(const std::vector<Vec3>& vertices, const std::vector<Tet>& tets) {
  assert(m_settings.cellSizeFactor > 0 && m_settings.padding >= 0 && m_settings.maxCellsPerTet > 0);
  const std::size_t n = tets.size();
  if (n >= std::size_t(std::numeric_limits<Index>::max())) throw std::length_error("TetGrid: too many tets");
  m_lo.resize(n);
  m_hi.resize(n);

  // 1. Padded bounding boxes, overall bounds and mean extent of the finite tets.
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::array<double, 3> lo{inf, inf, inf}, hi{-inf, -inf, -inf};
  double extentSum = 0;
  std::size_t finite = 0;
  const Vec3 pad = Vec3::Constant(m_settings.padding);
  for (std::size_t t = 0; t < n; ++t) {
    Vec3 a = vertices[tets[t][0]], b = a;
    bool allFinite = a.allFinite();
    for (std::size_t k = 1; k < 4; ++k) {
      const Vec3& v = vertices[tets[t][k]];
      allFinite = allFinite && v.allFinite();  // cwiseMin/Max may silently drop a NaN
      a = a.cwiseMin(v);
      b = b.cwiseMax(v);
    }
    a -= pad;
    b += pad;
    if (!allFinite || !a.allFinite() || !b.allFinite()) {
      // An empty box (lo > hi) contains nothing; such a tet is entered in no cell.
      m_lo[t] = Vec3::Constant(std::numeric_limits<Real>::max());
      m_hi[t] = Vec3::Constant(std::numeric_limits<Real>::lowest());
      continue;
    }
    m_lo[t] = a;
    m_hi[t] = b;
    for (int k = 0; k < 3; ++k) {
      lo[std::size_t(k)] = std::min(lo[std::size_t(k)], double(a[k]));
      hi[std::size_t(k)] = std::max(hi[std::size_t(k)], double(b[k]));
    }
    extentSum += double((b - a).maxCoeff());
    ++finite;
  }

  // 2. Cell size from the mean extent, grown until the cell count respects the cap.
  m_entryCount = 0;
  if (finite == 0) {
    m_cellSize = 0;
    m_dims = {0, 0, 0};
    m_cellStart.assign(1, 0);
    return;
  }
  double span = 0;
  for (std::size_t k = 0; k < 3; ++k) span = std::max(span, hi[k] - lo[k]);
  double cell = double(m_settings.cellSizeFactor) * extentSum / double(finite);
  if (!(cell > 0)) cell = span > 0 ? span : 1;  // every tet is a single point
  const double limit = double(m_settings.maxCellsPerTet) * double(n) + kMinCells;
  double cells = inf;
  for (;;) {
    m_origin = lo;
    m_invCell = 1.0 / cell;
    cells = 1;
    for (std::size_t k = 0; k < 3; ++k) {
      // Same expression as axisCoord() on the upper bound: the largest coordinate of any box.
      m_dims[k] = std::size_t(std::floor(std::min((hi[k] - lo[k]) * m_invCell, 1e15))) + 1;
      cells *= double(m_dims[k]);
    }
    if (cells <= limit) break;
    cell *= std::cbrt(cells / limit) * 1.001;
  }
  m_cellSize = Real(cell);

  // Reserve for the largest cell count this tet count allows, so that rebuilds with moved
  // vertices never reallocate the cell array.
  if (n != m_reservedFor) {
    m_cellStart.reserve(std::size_t(limit) + 1);
    m_reservedFor = n;
  }
  const std::size_t cellCount = std::size_t(cells);
  m_cellStart.assign(cellCount + 1, 0);

  // Cell range of box t along each axis (clamped: rounding in the double conversion must not
  // step outside the grid).
  auto range = [this](std::size_t t, std::size_t(&c0)[3], std::size_t(&c1)[3]) {
    if (!(m_lo[t][0] <= m_hi[t][0])) return false;
    for (int a = 0; a < 3; ++a) {
      const double top = double(m_dims[std::size_t(a)] - 1);
      c0[a] = std::size_t(std::clamp(std::floor(axisCoord(m_lo[t][a], a)), 0.0, top));
      c1[a] = std::size_t(std::clamp(std::floor(axisCoord(m_hi[t][a], a)), 0.0, top));
    }
    return true;
  };
  const std::size_t dx = m_dims[0], dxy = m_dims[0] * m_dims[1];

  // 3. Histogram of entries per cell.
  std::size_t total = 0;
  for (std::size_t t = 0; t < n; ++t) {
    std::size_t c0[3], c1[3];
    if (!range(t, c0, c1)) continue;
    for (std::size_t z = c0[2]; z <= c1[2]; ++z)
      for (std::size_t y = c0[1]; y <= c1[1]; ++y)
        for (std::size_t x = c0[0]; x <= c1[0]; ++x) ++m_cellStart[z * dxy + y * dx + x];
    total += (c1[0] - c0[0] + 1) * (c1[1] - c0[1] + 1) * (c1[2] - c0[2] + 1);
  }
  if (total >= std::size_t(std::numeric_limits<Index>::max()))
    throw std::length_error("TetGrid: too many entries");
  // 4. Inclusive prefix sum: m_cellStart[c] = end of cell c.
  Index running = 0;
  for (std::size_t c = 0; c < cellCount; ++c) {
    running += m_cellStart[c];
    m_cellStart[c] = running;
  }
  m_cellStart[cellCount] = Index(total);
  if (total > m_entries.size()) {
    m_entries.reserve(total + total / 4);
    m_entries.resize(m_entries.capacity());
  }
  m_entryCount = total;
  // 5. Scatter backwards, decrementing: afterwards m_cellStart[c] = begin of cell c, and each
  //    cell lists its tets in increasing index.
  for (std::size_t t = n; t-- > 0;) {
    std::size_t c0[3], c1[3];
    if (!range(t, c0, c1)) continue;
    for (std::size_t z = c0[2]; z <= c1[2]; ++z)
      for (std::size_t y = c0[1]; y <= c1[1]; ++y)
        for (std::size_t x = c0[0]; x <= c1[0]; ++x)
          m_entries[--m_cellStart[z * dxy + y * dx + x]] = Index(t);
  }
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
