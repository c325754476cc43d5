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
  for (Index t : candidates) {
    if (boxes) {
      const auto& [lo, hi] = (*boxes)[t];
      if ((p - p.cwiseMax(lo).cwiseMin(hi)).squaredNorm() > best) continue;
    }
    const Triangle& tri = triangles[t];
    const Vec3 c = closestPointOnTriangle(p, x[tri[0]], x[tri[1]], x[tri[2]]);
    const Real d2 = (p - c).squaredNorm();
    if (d2 < best || (d2 == best && t < bestId)) {
      best = d2;
      bestId = t;
      closest = c;
    }
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

}  // namespace

void findNearestWalls(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                      std::span<const Vec3> points, Real reach, std::vector<WallProximity>& out, int threads) {
  out.assign(points.size(), WallProximity{});
  if (triangles.empty()) return;
  // The triangles binned by the cells their boxes touch (the engine's CellGrid), cells of edge
  // `reach` over the surface's box: a point's nearest triangle within reach is in the cells of
  // the box p +- reach.
  std::vector<std::array<Vec3, 2>> boxes(triangles.size());
  Vec3 lo = Vec3::Constant(std::numeric_limits<Real>::max()), hi = -lo;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& v = triangles[t];
    boxes[t] = {vertices[v[0]].cwiseMin(vertices[v[1]]).cwiseMin(vertices[v[2]]),
                vertices[v[0]].cwiseMax(vertices[v[1]]).cwiseMax(vertices[v[2]])};
    lo = lo.cwiseMin(boxes[t][0]);
    hi = hi.cwiseMax(boxes[t][1]);
  }
  CellIndexing cells;
  cells.coverWithin({double(lo[0]), double(lo[1]), double(lo[2])}, {double(hi[0]), double(hi[1]), double(hi[2])},
                    double(reach), kMaxCellsPerTriangle * double(triangles.size()) + 64, 1.001, kMaxCoord);
  CellGrid grid;
  const bool binned = grid.bin(triangles.size(), cells.cellCount(), threads, [&](std::size_t t, auto&& emit) {
    CellBox r;
    if (cells.cellRange(boxes[t][0], boxes[t][1], r)) cells.forEachCell(r, [&](std::size_t c, auto, auto, auto) { emit(c); });
  });
  if (!binned) throw std::length_error("findNearestWalls: too many triangle entries for the cell grid");
  const auto n = std::ptrdiff_t(points.size());
#pragma omp parallel num_threads(threads) if (n >= 256)
  {
    std::vector<Index> candidates;
    // A triangle whose box touches several of p's cells is a candidate once: seen[t] holds the
    // last point it was offered for.
    std::vector<std::ptrdiff_t> seen(triangles.size(), -1);
    auto offer = [&](Index t, std::ptrdiff_t point) {
      if (seen[t] == point) return;
      seen[t] = point;
      candidates.push_back(t);
    };
#pragma omp for schedule(static)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      const Vec3& p = points[std::size_t(i)];
      if (!p.allFinite()) continue;
      // Farther than reach from every triangle's box (blood parked away from the walls).
      if ((p - p.cwiseMax(lo).cwiseMin(hi)).squaredNorm() > reach * reach) continue;
      // p's own cell first (its nearest triangle is likely there, and then the boxes of most
      // others are farther), then the cells of the box p +- reach.
      candidates.clear();
      std::size_t own = 0;
      if (cells.cellOf(p, own))
        for (Index e = grid.begin(own); e < grid.end(own); ++e) offer(grid.item(e), i);
      CellBox r;
      if (cells.cellRange(p - Vec3::Constant(reach), p + Vec3::Constant(reach), r))
        grid.forEachItem(cells, r, [&](Index t) { offer(t, i); });
      out[std::size_t(i)] = nearestOf(vertices, triangles, candidates, p, reach, &boxes);
    }
  }
}

WallProximity nearestWallBruteForce(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                                    const Vec3& point, Real reach) {
  std::vector<Index> all(triangles.size());
  for (std::size_t t = 0; t < all.size(); ++t) all[t] = Index(t);
  return nearestOf(vertices, triangles, all, point, reach);
}

}  // namespace hs::pbd
