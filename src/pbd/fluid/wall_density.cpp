#include "pbd/fluid/wall_density.h"

#include "pbd/fluid/wall_bounds.h"
#include "pbd/grid/cell_grid.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
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

// The running nearest triangle to p within reach (closest point on each, Ericson 5.1.5):
// candidates may be offered in any order and repeated; the minimum distance, ties to the lowest
// id, does not depend on it.
class NearestTriangle {
 public:
  NearestTriangle(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles, const Vec3& p, Real reach)
      : m_x(x), m_triangles(triangles), m_p(p), m_best(reach * reach) {}

  void offer(Index t) {
    const Triangle& tri = m_triangles[t];
    const Vec3 c = closestPointOnTriangle(m_p, m_x[tri[0]], m_x[tri[1]], m_x[tri[2]]);
    const Real d2 = (m_p - c).squaredNorm();
    if (d2 < m_best || (d2 == m_best && t < m_bestId)) {
      m_best = d2;
      m_bestId = t;
      m_closest = c;
    }
  }
  // The squared distance to beat (reach^2 until a triangle within reach is found).
  [[nodiscard]] Real best2() const { return m_best; }
  [[nodiscard]] WallProximity result() const {
    const Real d = std::sqrt(m_best);
    if (m_bestId == ~Index(0) || !(d > Real(0))) return {};
    return {d, (m_p - m_closest) / d};
  }

 private:
  const std::vector<Vec3>& m_x;
  const std::vector<Triangle>& m_triangles;
  Vec3 m_p;
  Real m_best;
  Index m_bestId = ~Index(0);
  Vec3 m_closest = Vec3::Zero();
};

// The nearest wall triangle to p of the candidates of one cell of the grid, from the entries'
// own copies of their triangles' boxes and planes: a lower bound of each candidate's distance
// (the larger of its box's and its plane's) in one vectorised pass over contiguous arrays, then
// the triangle with the smallest bound, then every candidate whose bound is not beyond the best so
// far. The minimum (ties to the lowest id) is the same as over all candidates: the bounds only
// order and prune.
WallProximity nearestInCell(const WallTriangleGrid& grid, const std::vector<Vec3>& x,
                            const std::vector<Triangle>& triangles, std::size_t cell, const Vec3& p) {
  const CellGrid& g = grid.grid();
  const Index begin = g.begin(cell);
  const std::size_t n = g.end(cell) - begin;
  thread_local std::vector<Real> bounds;
  bounds.resize(n + kWallBoundsPadding);
  WallBoundsJob job{};
  for (int a = 0; a < 3; ++a) {
    job.lo[a] = grid.entryLo(a) + begin;
    job.hi[a] = grid.entryHi(a) + begin;
  }
  for (int k = 0; k < 4; ++k) job.plane[k] = grid.entryPlane(k) + begin;
  job.slack = grid.slack();
  job.px = p.x(), job.py = p.y(), job.pz = p.z();
  job.n = n;
  const WallBoundsMinimum smallest = wallCandidateBounds(job, bounds.data());
  const Real reach = grid.reach();
  if (!(smallest.bound < reach * reach)) return {};
  NearestTriangle nearest(x, triangles, p, reach);
  const Index* items = g.items().data() + begin;
  nearest.offer(items[smallest.first]);
  // The others in entry order, those whose bound is not beyond the best so far: the bits mark
  // those not beyond the first's distance (the best only shrinks), checked again when reached.
  thread_local std::vector<std::uint64_t> within;
  within.resize(wallCandidateWords(n));
  wallCandidatesWithin(bounds.data(), n, nearest.best2(), within.data());
  for (std::size_t w = 0; w < within.size(); ++w)
    for (std::uint64_t word = within[w]; word != 0; word &= word - 1) {
      const std::size_t k = 64 * w + std::size_t(std::countr_zero(word));
      if (k != smallest.first && !(bounds[k] > nearest.best2())) nearest.offer(items[k]);
    }
  return nearest.result();
}

// The plane of triangle (a, b, c) as n . x = c0 with n of unit length (zero, and so no bound,
// for a degenerate triangle).
std::array<Real, 4> planeOf(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 cross = (b - a).cross(c - a);
  const Real length = cross.norm();
  if (!(length > Real(0)) || !std::isfinite(length)) return {0, 0, 0, 0};
  const Vec3 n = cross / length;
  return {n.x(), n.y(), n.z(), n.dot(a)};
}

// The slack of the bounds for a wall within the box [lo, hi]: the rounding of a plane's n and c0,
// of n . p - c0 and of a box's distance for a point p within reach, and of the closest point's own
// distance, is a few units in the last place of the coordinates' size; a margin of 2^-14 of it
// (6e-6 m at 0.1 m in float) keeps the bounds below every distance the closest point can compute,
// and costs no pruning worth having.
Real boundSlack(const Vec3& lo, const Vec3& hi, Real reach) {
  return (lo.cwiseAbs().cwiseMax(hi.cwiseAbs()).maxCoeff() + 2 * reach) * Real(1.0 / 16384);
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
// A triangle's box grown by reach spans about 3 cells of reach along each axis: the work per
// triangle that decides whether binning forks.
constexpr std::size_t kCellsPerTriangle = 27;
// Below these sizes the boxes and the entries' copies are made on one thread.
constexpr std::size_t kParallelTriangles = 1024;
constexpr std::ptrdiff_t kParallelEntries = 32768;

}  // namespace

#ifndef HS_HAVE_HIGHWAY
WallBoundsMinimum wallCandidateBounds(const WallBoundsJob& job, Real* out) {
  WallBoundsMinimum smallest{std::numeric_limits<Real>::infinity(), job.n};
  for (std::size_t k = 0; k < job.n; ++k) {
    out[k] = wallCandidateBound(job, k);
    if (out[k] < smallest.bound) smallest = {out[k], k};
  }
  for (std::size_t k = job.n; k < job.n + kWallBoundsPadding; ++k) out[k] = std::numeric_limits<Real>::infinity();
  return smallest;
}

void wallCandidatesWithin(const Real* bounds, std::size_t n, Real threshold, std::uint64_t* words) {
  std::fill(words, words + wallCandidateWords(n), std::uint64_t(0));
  for (std::size_t k = 0; k < n; ++k)
    if (bounds[k] <= threshold) words[k / 64] |= std::uint64_t(1) << (k % 64);
}
#endif

void WallTriangleGrid::update(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles, Real reach,
                              int threads) {
  m_reach = reach;
  m_boxes.resize(triangles.size());
  m_planes.resize(triangles.size());
  // The boxes in fixed chunks (min and max are exact in any order), in parallel on large walls.
  constexpr std::ptrdiff_t kChunks = 8;
  std::array<Vec3, kChunks> chunkLo, chunkHi;
  chunkLo.fill(Vec3::Constant(std::numeric_limits<Real>::max()));
  chunkHi.fill(Vec3::Constant(std::numeric_limits<Real>::lowest()));
  const std::size_t n = triangles.size();
#pragma omp parallel for schedule(static) num_threads(threads) if (n >= kParallelTriangles)
  for (std::ptrdiff_t chunk = 0; chunk < kChunks; ++chunk) {
    Vec3& lo = chunkLo[std::size_t(chunk)];
    Vec3& hi = chunkHi[std::size_t(chunk)];
    for (std::size_t t = n * std::size_t(chunk) / kChunks, end = n * std::size_t(chunk + 1) / kChunks; t < end; ++t) {
      const Triangle& v = triangles[t];
      m_boxes[t] = {vertices[v[0]].cwiseMin(vertices[v[1]]).cwiseMin(vertices[v[2]]),
                    vertices[v[0]].cwiseMax(vertices[v[1]]).cwiseMax(vertices[v[2]])};
      m_planes[t] = planeOf(vertices[v[0]], vertices[v[1]], vertices[v[2]]);
      lo = lo.cwiseMin(m_boxes[t][0]);
      hi = hi.cwiseMax(m_boxes[t][1]);
    }
  }
  Vec3 lo = chunkLo[0], hi = chunkHi[0];
  for (std::size_t c = 1; c < std::size_t(kChunks); ++c) {
    lo = lo.cwiseMin(chunkLo[c]);
    hi = hi.cwiseMax(chunkHi[c]);
  }
  m_slack = boundSlack(lo, hi, reach);
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
  }, kCellsPerTriangle);
  if (!binned) throw std::length_error("findNearestWalls: too many triangle entries for the cell grid");
  const std::vector<Index>& items = m_grid.items();
  // Every array padded with zeros past its last entry for the SIMD pass (wall_bounds.h).
  const std::size_t padded = items.size() + kWallBoundsPadding;
  const auto pad = [&](std::vector<Real>& array) {
    array.resize(padded);
    std::fill(array.begin() + std::ptrdiff_t(items.size()), array.end(), Real(0));
  };
  for (std::size_t a = 0; a < 3; ++a) {
    pad(m_entryLo[a]);
    pad(m_entryHi[a]);
  }
  for (std::vector<Real>& component : m_entryPlane) pad(component);
  const auto entries = std::ptrdiff_t(items.size());
#pragma omp parallel for schedule(static) num_threads(threads) if (entries >= kParallelEntries)
  for (std::ptrdiff_t e = 0; e < entries; ++e) {
    const std::size_t entry = std::size_t(e), t = items[entry];
    for (std::size_t a = 0; a < 3; ++a) {
      m_entryLo[a][entry] = m_boxes[t][0][int(a)];
      m_entryHi[a][entry] = m_boxes[t][1][int(a)];
    }
    for (std::size_t k = 0; k < 4; ++k) m_entryPlane[k][entry] = m_planes[t][k];
  }
}

void findNearestWalls(const WallTriangleGrid& grid, const std::vector<Vec3>& vertices,
                      const std::vector<Triangle>& triangles, std::span<const Vec3> points,
                      std::vector<WallProximity>& out, int threads) {
  out.assign(points.size(), WallProximity{});
  if (!grid.valid()) return;
  const auto n = std::ptrdiff_t(points.size());
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads) if (n >= 256)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const Vec3& p = points[std::size_t(i)];
    std::size_t cell = 0;
    // Outside the grid (or not finite): farther than reach from every triangle's box.
    if (!p.allFinite() || !grid.cells().cellOf(p, cell)) continue;
    out[std::size_t(i)] = nearestInCell(grid, vertices, triangles, cell, p);
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
  NearestTriangle nearest(vertices, triangles, point, reach);
  for (std::size_t t = 0; t < triangles.size(); ++t) nearest.offer(Index(t));
  return nearest.result();
}

}  // namespace hs::pbd
