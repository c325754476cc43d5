#include "pbd/wall_density.h"

#include "pbd/cell_grid.h"

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace hs::pbd {
namespace {

// Composite Simpson's rule for int_a^b f(r) dr with an even number of intervals.
template <class F>
double simpson(F f, double a, double b, int intervals) {
  if (!(b > a)) return 0;
  const double step = (b - a) / intervals;
  double sum = f(a) + f(b);
  for (int k = 1; k < intervals; ++k) sum += (k % 2 ? 4 : 2) * f(a + k * step);
  return sum * step / 3;
}

}  // namespace

WallDensityTable::WallDensityTable(const SphKernels& kernels, int samples)
    : m_h(kernels.h), m_step(kernels.h / Real(samples)) {
  const double h = double(kernels.h);
  const double pi = std::numbers::pi;
  const double poly6 = 315.0 / (64.0 * pi * std::pow(h, 9));
  const double spikyGrad = 45.0 / (pi * std::pow(h, 6));  // |W'(r)| = 45/(pi h^6) (h - r)^2
  m_density.resize(std::size_t(samples) + 1);
  m_gradient.resize(std::size_t(samples) + 1);
  for (int k = 0; k <= samples; ++k) {
    const double d = h * k / samples;
    m_density[std::size_t(k)] = Real(simpson(
        [&](double r) { return poly6 * std::pow(h * h - r * r, 3) * 2 * pi * r * (r - d); }, d, h, 200));
    m_gradient[std::size_t(k)] = Real(simpson(
        [&](double r) { return spikyGrad * (h - r) * (h - r) * pi * (r * r - d * d); }, d, h, 200));
  }
}

Real WallDensityTable::lookup(const std::vector<Real>& table, Real d) const {
  if (!(d < m_h)) return Real(0);
  const Real x = std::max(Real(0), d) / m_step;
  const auto k = std::min(std::size_t(x), table.size() - 2);
  const Real t = x - Real(k);
  return table[k] + t * (table[k + 1] - table[k]);
}

namespace {

// The nearest of `candidates` (triangle ids, repeats allowed) to p within `reach`; of equally
// near ones the lowest id, so the answer does not depend on the candidates' order.
// `boxes` (lo, hi per triangle, optional) let a triangle whose box is farther than the best so
// far be skipped.
template <class Ids>
WallProximity nearestOf(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles, const Ids& candidates,
                        const Vec3& p, Real reach, const std::vector<std::array<Vec3, 2>>* boxes = nullptr) {
  Real best = reach * reach;
  Index bestId = ~Index(0);
  Vec3 closest = Vec3::Zero();
  auto boxDistance2 = [&](Index t) {
    const auto& [lo, hi] = (*boxes)[t];
    return (p - p.cwiseMax(lo).cwiseMin(hi)).squaredNorm();
  };
  auto offer = [&](Index t) {
    const Triangle& tri = triangles[t];
    const Vec3 c = closestPointOnTriangle(p, x[tri[0]], x[tri[1]], x[tri[2]]);
    const Real d2 = (p - c).squaredNorm();
    if (d2 < best || (d2 == best && t < bestId)) {
      best = d2;
      bestId = t;
      closest = c;
    }
  };
  if (boxes) {
    // The triangle with the nearest box first: its distance bounds the others' from above, and
    // most boxes are then farther than it. The result is the same minimum (ties to the lowest id).
    thread_local std::vector<Real> boxDistances;
    boxDistances.resize(candidates.size());
    std::size_t first = candidates.size();
    Real firstBox = best;
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      boxDistances[k] = boxDistance2(candidates[k]);
      if (boxDistances[k] < firstBox) firstBox = boxDistances[k], first = k;
    }
    if (first == candidates.size()) return {};
    offer(candidates[first]);
    for (std::size_t k = 0; k < candidates.size(); ++k)
      if (k != first && !(boxDistances[k] > best)) offer(candidates[k]);
  } else {
    for (Index t : candidates) offer(t);
  }
  const Real d = std::sqrt(best);
  if (bestId == ~Index(0) || !(d > Real(0))) return {};
  return {d, (p - closest) / d};
}

// Cell coordinates along an axis are capped (a grid this large is never built: the cells are
// grown first, see kMaxCellsPerTriangle).
constexpr double kMaxCoord = 1e15;
// The triangles' grid has at most this many cells per triangle (plus a few for tiny surfaces).
constexpr double kMaxCellsPerTriangle = 64;
// Cell edge as a share of `reach`. Smaller cells list fewer triangles far from every point of
// the cell but enter each triangle in more cells, and the wall moves every step, so it is binned
// every step. Instructions of the finding (binning and queries) over 40 steps of `normal` in
// systole (t = 0.15-0.19 s, callgrind, one thread): 459 M with cells of reach, 469 M with 1/2,
// 788 M with 1/4 (the 27-cell search before: 646 M).
constexpr double kCellPerReach = 1;

}  // namespace

void WallTriangleGrid::update(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles, Real reach,
                              int threads) {
  m_reach = reach;
  m_boxes.resize(triangles.size());
  Vec3 lo = Vec3::Constant(std::numeric_limits<Real>::max()), hi = -lo;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& v = triangles[t];
    m_boxes[t] = {vertices[v[0]].cwiseMin(vertices[v[1]]).cwiseMin(vertices[v[2]]),
                  vertices[v[0]].cwiseMax(vertices[v[1]]).cwiseMax(vertices[v[2]])};
    lo = lo.cwiseMin(m_boxes[t][0]);
    hi = hi.cwiseMax(m_boxes[t][1]);
  }
  m_valid = !triangles.empty();
  if (!m_valid) return;
  // Each triangle is binned into every cell its box grown by `reach` touches (the engine's
  // CellGrid), so a point's own cell lists every triangle within reach of it, once: no search of
  // the cells around, no repeats to skip.
  const Vec3 grow = Vec3::Constant(reach);
  const Vec3 gridLo = lo - grow, gridHi = hi + grow;
  m_cells.coverWithin({double(gridLo[0]), double(gridLo[1]), double(gridLo[2])},
                      {double(gridHi[0]), double(gridHi[1]), double(gridHi[2])}, kCellPerReach * double(reach),
                      kMaxCellsPerTriangle * double(triangles.size()) + 64, 1.001, kMaxCoord);
  const bool binned = m_grid.bin(triangles.size(), m_cells.cellCount(), threads, [&](std::size_t t, auto&& emit) {
    CellBox r;
    if (m_cells.cellRange(Vec3(m_boxes[t][0] - grow), Vec3(m_boxes[t][1] + grow), r))
      m_cells.forEachCell(r, [&](std::size_t c, auto, auto, auto) { emit(c); });
  });
  if (!binned) throw std::length_error("findNearestWalls: too many triangle entries for the cell grid");
}

void findNearestWalls(const WallTriangleGrid& grid, const std::vector<Vec3>& vertices,
                      const std::vector<Triangle>& triangles, std::span<const Vec3> points,
                      std::vector<WallProximity>& out, int threads) {
  out.assign(points.size(), WallProximity{});
  if (!grid.valid()) return;
  const Real reach = grid.reach();
  const auto n = std::ptrdiff_t(points.size());
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads) if (n >= 256)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const Vec3& p = points[std::size_t(i)];
    std::size_t cell = 0;
    // Outside the grid (or not finite): farther than reach from every triangle's box.
    if (!p.allFinite() || !grid.cells().cellOf(p, cell)) continue;
    const CellGrid& g = grid.grid();
    const std::span<const Index> candidates(g.items().data() + g.begin(cell), g.end(cell) - g.begin(cell));
    out[std::size_t(i)] = nearestOf(vertices, triangles, candidates, p, reach, &grid.boxes());
  }
}

void findNearestWalls(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                      std::span<const Vec3> points, Real reach, std::vector<WallProximity>& out, int threads) {
  WallTriangleGrid grid;
  grid.update(vertices, triangles, reach, threads);
  findNearestWalls(grid, vertices, triangles, points, out, threads);
}

WallProximity nearestWallBruteForce(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                                    const Vec3& point, Real reach) {
  std::vector<Index> all(triangles.size());
  for (std::size_t t = 0; t < all.size(); ++t) all[t] = Index(t);
  return nearestOf(vertices, triangles, all, point, reach);
}

}  // namespace hs::pbd
