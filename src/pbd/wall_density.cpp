#include "pbd/wall_density.h"

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <numbers>

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

// Triangles binned by the cells their bounding boxes touch (cell edge `cell`).
struct TriangleBins {
  Vec3 lo, hi;  // the triangles' bounding box
  Real cell;
  std::array<int, 3> dims{};
  std::vector<std::size_t> start;  // per cell, offsets into ids (one more than cells)
  std::vector<Index> ids;
  std::vector<std::array<Vec3, 2>> boxes;  // per triangle: lo, hi

  [[nodiscard]] std::array<int, 3> cellOf(const Vec3& p) const {
    std::array<int, 3> c{};
    for (int a = 0; a < 3; ++a) c[a] = std::clamp(int(std::floor((p[a] - lo[a]) / cell)), 0, dims[a] - 1);
    return c;
  }
  [[nodiscard]] std::size_t index(int i, int j, int k) const {
    return (std::size_t(k) * std::size_t(dims[1]) + std::size_t(j)) * std::size_t(dims[0]) + std::size_t(i);
  }
};

TriangleBins binTriangles(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles, Real cell) {
  TriangleBins bins;
  bins.cell = cell;
  Vec3 lo = Vec3::Constant(std::numeric_limits<Real>::max()), hi = -lo;
  for (const Triangle& t : triangles)
    for (Index v : t) {
      lo = lo.cwiseMin(x[v]);
      hi = hi.cwiseMax(x[v]);
    }
  bins.lo = lo;
  bins.hi = hi;
  for (int a = 0; a < 3; ++a) bins.dims[a] = std::max(1, int(std::ceil((hi[a] - lo[a]) / cell)) + 1);
  const std::size_t cells = std::size_t(bins.dims[0]) * std::size_t(bins.dims[1]) * std::size_t(bins.dims[2]);
  // Two passes: count, then fill (counting sort), each triangle in every cell its box touches.
  std::vector<std::size_t> count(cells + 1, 0);
  bins.boxes.resize(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& v = triangles[t];
    bins.boxes[t] = {x[v[0]].cwiseMin(x[v[1]]).cwiseMin(x[v[2]]), x[v[0]].cwiseMax(x[v[1]]).cwiseMax(x[v[2]])};
  }
  auto forCells = [&](std::size_t t, auto&& visit) {
    const auto a = bins.cellOf(bins.boxes[t][0]), b = bins.cellOf(bins.boxes[t][1]);
    for (int k = a[2]; k <= b[2]; ++k)
      for (int j = a[1]; j <= b[1]; ++j)
        for (int i = a[0]; i <= b[0]; ++i) visit(bins.index(i, j, k));
  };
  for (std::size_t t = 0; t < triangles.size(); ++t) forCells(t, [&](std::size_t c) { ++count[c + 1]; });
  for (std::size_t c = 0; c < cells; ++c) count[c + 1] += count[c];
  bins.start = count;
  bins.ids.resize(count[cells]);
  for (std::size_t t = 0; t < triangles.size(); ++t) forCells(t, [&](std::size_t c) { bins.ids[count[c]++] = Index(t); });
  return bins;
}

}  // namespace

void findNearestWalls(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                      std::span<const Vec3> points, Real reach, std::vector<WallProximity>& out, int threads) {
  out.assign(points.size(), WallProximity{});
  if (triangles.empty()) return;
  const TriangleBins bins = binTriangles(vertices, triangles, reach);
  const auto n = std::ptrdiff_t(points.size());
#pragma omp parallel num_threads(threads) if (n >= 256)
  {
    std::vector<Index> candidates;
    // A triangle whose box touches several of p's cells is a candidate once: seen[t] holds the
    // last point it was offered for.
    std::vector<std::ptrdiff_t> seen(triangles.size(), -1);
    auto offer = [&](std::size_t cell, std::ptrdiff_t point) {
      for (std::size_t k = bins.start[cell]; k < bins.start[cell + 1]; ++k) {
        const Index t = bins.ids[k];
        if (seen[t] == point) continue;
        seen[t] = point;
        candidates.push_back(t);
      }
    };
#pragma omp for schedule(static)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      const Vec3& p = points[std::size_t(i)];
      if (!p.allFinite()) continue;
      // Farther than reach from every triangle's box (blood parked away from the walls).
      if ((p - p.cwiseMax(bins.lo).cwiseMin(bins.hi)).squaredNorm() > reach * reach) continue;
      // p's own cell first (its nearest triangle is likely there, and then the boxes of most
      // others are farther), then the cells of the box p +- reach.
      const auto own = bins.cellOf(p);
      candidates.clear();
      offer(bins.index(own[0], own[1], own[2]), i);
      const auto a = bins.cellOf(p - Vec3::Constant(reach)), b = bins.cellOf(p + Vec3::Constant(reach));
      for (int k = a[2]; k <= b[2]; ++k)
        for (int j = a[1]; j <= b[1]; ++j)
          for (int c = a[0]; c <= b[0]; ++c) offer(bins.index(c, j, k), i);
      out[std::size_t(i)] = nearestOf(vertices, triangles, candidates, p, reach, &bins.boxes);
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
