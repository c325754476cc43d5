#include "pbd/mesh_collider.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace hs::pbd {
// Ericson 5.1.5, ClosestPtPointTriangle: by the Voronoi regions of the corners and edges.
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const Real d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const Real d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const Real vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const Real d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const Real vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const Real va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const Real denom = Real(1) / (va + vb + vc);
  return a + (vb * denom) * ab + (vc * denom) * ac;
}

namespace {

using detail::ColliderGeometry;
using detail::ColliderTriangle;
using detail::TriangleGrid;

constexpr Real kEps = std::numeric_limits<Real>::epsilon();
// Rounding allowance for heights and positions, relative to the coordinates involved.
constexpr Real kRound = 64 * kEps;
// "Inside the triangle" accepts barycentric coordinates down to -kBaryTol: rounding puts a point
// on an edge shared by two triangles slightly outside both, and a particle would slip through
// the crack. A 1e-4 wider triangle is invisible at simulation scale.
constexpr Real kBaryTol = std::is_same_v<Real, float> ? Real(1e-4) : Real(1e-9);
// Zero area up to rounding: |(b - a) x (c - a)| <= kDegenerate * (longest edge)^2.
constexpr Real kDegenerate = 16 * kEps;
// Pushes per call: a corner of k faces needs k; a sharp concave wedge of angle theta converges
// like cos(theta)^n (alternating projections), so 16 leave < 1e-4 r for 60 degrees.
constexpr int kMaxContactIterations = 16;
constexpr int kMaxSegmentPieces = 64;
constexpr std::int64_t kMaxQuickRows = 16;  // rows of cells the empty-neighbourhood test looks at
constexpr double kMinCellBudget = 65536, kCellsPerTriangle = 64;
constexpr Index kNone = ~Index(0);

Real maxAbs(const Vec3& v) { return v.cwiseAbs().maxCoeff(); }

std::string describe(const Vec3& v) {
  std::ostringstream s;
  s << '(' << v[0] << ", " << v[1] << ", " << v[2] << ')';
  return s.str();
}

// Signed height above the triangle's plane: h(x) = n . (x - a).
Real height(const ColliderTriangle& t, const Vec3& x) { return t.normal.dot(x - t.a); }

// Smallest barycentric coordinate of the projection of p onto the plane, each coordinate a ratio
// of signed areas (Ericson 3.4): u_a = N . ((c - b) x (p - b)) / |N|^2, and cyclically. Each uses
// only its own edge, so two triangles sharing an edge evaluate it from the same two points.
Real minBarycentric(const ColliderTriangle& t, const Vec3& p) {
  const Real u = t.baryNormal.dot((t.c - t.b).cross(p - t.b));
  const Real v = t.baryNormal.dot((t.a - t.c).cross(p - t.c));
  const Real w = t.baryNormal.dot((t.b - t.a).cross(p - t.a));
  return std::min({u, v, w});
}


// Does p(s) = previous + s (predicted - previous), s in [0, 1], cross the triangle? The height is
// linear in s, h(s) = h0 + s (h1 - h0), so the plane is crossed at s = h0 / (h0 - h1) when the
// sign changes (landing on the plane counts; starting on it counts as the normal side), and the
// crossing point must lie inside the triangle.
bool crossesTriangle(const ColliderTriangle& t, const Vec3& previous, const Vec3& predicted, Real& s) {
  if ((previous.cwiseMax(predicted).array() < t.boxLo.array()).any() ||
      (previous.cwiseMin(predicted).array() > t.boxHi.array()).any())
    return false;  // the crossing point would lie in both boxes
  const Real h0 = height(t, previous), h1 = height(t, predicted);
  if (h0 >= 0 ? h1 > 0 : h1 < 0) return false;
  s = h0 == h1 ? Real(0) : h0 / (h0 - h1);  // in [0, 1]: |h0| <= |h0 - h1|
  return minBarycentric(t, previous + s * (predicted - previous)) >= -kBaryTol;
}

struct Push {
  Real depth = 0;  // how far to move; <= 0: no contact
  Vec3 direction = Vec3::Zero();
};

// Contact of a particle of radius r at x with one triangle: C(x) = dist(x, T) - r >= 0.
//  * Over the face (the projection of x is inside T): dist = |h|, and the particle belongs on
//    side sigma, so C = sigma h - r and the push is (r - sigma h) along sigma n; this also lifts
//    a particle that is (slightly) behind the face back to its side.
//  * Beside the face: dist = |x - q| with q the closest point on an edge or corner, and the push
//    is (r - |x - q|) along (x - q) / |x - q|, which stays in that edge's Voronoi region, so it
//    cannot cross the triangle.
// sigma is the side of `start` (the position after the tunnelling test), or of `previous` when
// start is within rounding of the plane (it stopped on this triangle), or the normal side.
Push contactPush(const ColliderTriangle& t, const Vec3& x, const Vec3& start, const Vec3& previous,
                 Real radius, Real sideTolerance) {
  // Cheap rejections first: a triangle within `radius` has a point in its box within radius of
  // x, and its plane within radius of x.
  if ((x.array() + radius < t.boxLo.array()).any() || (x.array() - radius > t.boxHi.array()).any()) return {};
  const Real h = height(t, x);
  if (!(std::abs(h) < radius)) return {};
  const Real h0 = height(t, start);
  const Real sigma = std::abs(h0) > sideTolerance ? (h0 > 0 ? Real(1) : Real(-1))
                                                  : (height(t, previous) >= 0 ? Real(1) : Real(-1));
  if (minBarycentric(t, x) >= -kBaryTol) return {radius - sigma * h, sigma * t.normal};
  const Vec3 v = x - closestPointOnTriangle(x, t.a, t.b, t.c);
  const Real d2 = v.squaredNorm();
  if (!(d2 < radius * radius)) return {};
  const Real d = std::sqrt(d2);
  if (d > 0) return {radius - d, v / d};
  return {radius, sigma * t.normal};  // exactly on an edge: leave towards the particle's side
}

// The collision itself, over the triangles a Candidates object offers: mayHaveAny(lo, hi) is
// false only if no triangle has a point in [lo, hi]; inBox(lo, hi, f) calls f(k) at least for
// every triangle k with a point in [lo, hi]; alongSegment(p, q, slack, best, f) at least for
// every triangle crossed by p -> q at a parameter <= best. Duplicates and extra triangles are
// harmless: the selections below do not depend on the visiting order.
template <class Candidates>
Vec3 collideWith(const ColliderGeometry& geometry, const Candidates& candidates, const Vec3& previous,
                 const Vec3& predicted, Real radius) {
  if (!previous.allFinite() || !predicted.allFinite() || !(radius >= 0) || !std::isfinite(radius))
    return predicted;
  const std::vector<ColliderTriangle>& triangles = geometry.triangles;
  const Vec3 step = predicted - previous;

  // 0. Most particles are far from any wall: if no triangle can be near the whole move (the
  //    segment's box widened by the radius and every slack below), nothing changes.
  const Vec3 margin = Vec3::Constant(
      radius + kRound * (maxAbs(previous) + maxAbs(predicted) + maxAbs(step) + geometry.coordScale + radius));
  if (!candidates.mayHaveAny(Vec3(previous.cwiseMin(predicted) - margin),
                             Vec3(previous.cwiseMax(predicted) + margin)))
    return predicted;

  // 1. Tunnelling: stop at the first crossing (smallest s, ties to the lowest triangle).
  //    segmentSlack bounds the rounding of positions and heights along the segment: it widens
  //    the cells searched, and below it a height counts as "on the plane" in step 2.
  const Real segmentSlack = kRound * (maxAbs(previous) + maxAbs(step) + geometry.coordScale);
  Real firstS = 2;
  Index first = kNone;
  candidates.alongSegment(previous, predicted, segmentSlack, firstS, [&](Index k) {
    Real s;
    if (crossesTriangle(triangles[k], previous, predicted, s) && (s < firstS || (s == firstS && k < first))) {
      firstS = s;
      first = k;
    }
  });
  const Vec3 start = first == kNone ? predicted : Vec3(previous + firstS * step);

  // 2. Contacts: push out of the deepest one (ties to the lowest triangle) until none is left.
  Vec3 x = start;
  for (int iteration = 0; iteration < kMaxContactIterations; ++iteration) {
    const Real scale = maxAbs(x) + geometry.coordScale + radius;
    const Vec3 reach = Vec3::Constant(radius + kRound * scale);
    Real bestDepth = 16 * kEps * scale;  // shallower contacts are rounding noise
    Index best = kNone;
    Vec3 direction = Vec3::Zero();
    candidates.inBox(Vec3(x - reach), Vec3(x + reach), [&](Index k) {
      const Push push = contactPush(triangles[k], x, start, previous, radius, segmentSlack);
      if (push.depth > bestDepth || (best != kNone && push.depth == bestDepth && k < best)) {
        bestDepth = push.depth;
        best = k;
        direction = push.direction;
      }
    });
    if (best == kNone) break;
    x += bestDepth * direction;
  }
  return x;
}

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

struct CellBox {
  std::int64_t lo[3], hi[3];
};

// Cells overlapping [lo, hi]; false if none. The cell coordinate floor((x - origin) / cell) is
// monotone in x, so every point of the box falls in a cell of the range.
bool cellRange(const TriangleGrid& g, const double lo[3], const double hi[3], CellBox& r) {
  if (g.cellStart.empty()) return false;
  for (int a = 0; a < 3; ++a) {
    const double tl = (lo[a] - g.origin[a]) * g.invCell, th = (hi[a] - g.origin[a]) * g.invCell;
    const double top = double(g.dims[a] - 1);
    if (!(th >= 0) || !(tl < top + 1) || !(tl <= th)) return false;
    r.lo[a] = tl <= 0 ? 0 : std::int64_t(tl);
    r.hi[a] = std::int64_t(std::min(th, top));
  }
  return true;
}

template <class F>
void forEachInCells(const TriangleGrid& g, const CellBox& r, F& f) {
  for (std::int64_t z = r.lo[2]; z <= r.hi[2]; ++z)
    for (std::int64_t y = r.lo[1]; y <= r.hi[1]; ++y) {
      // Cells (x0..x1, y, z) are consecutive: one contiguous run of entries per row.
      const std::int64_t row = (z * g.dims[1] + y) * g.dims[0];
      const Index end = g.cellStart[std::size_t(row + r.hi[0] + 1)];
      for (Index e = g.cellStart[std::size_t(row + r.lo[0])]; e < end; ++e) f(g.entries[e]);
    }
}

struct GridCandidates {
  const TriangleGrid& grid;

  // False only if every cell overlapping [lo, hi] is empty; true without looking for large boxes.
  bool mayHaveAny(const Vec3& lo, const Vec3& hi) const {
    const double l[3] = {double(lo[0]), double(lo[1]), double(lo[2])};
    const double h[3] = {double(hi[0]), double(hi[1]), double(hi[2])};
    CellBox r;
    if (!cellRange(grid, l, h, r)) return false;
    if ((r.hi[1] - r.lo[1] + 1) * (r.hi[2] - r.lo[2] + 1) > kMaxQuickRows) return true;
    for (std::int64_t z = r.lo[2]; z <= r.hi[2]; ++z)
      for (std::int64_t y = r.lo[1]; y <= r.hi[1]; ++y) {
        const std::int64_t row = (z * grid.dims[1] + y) * grid.dims[0];
        if (grid.cellStart[std::size_t(row + r.hi[0] + 1)] != grid.cellStart[std::size_t(row + r.lo[0])])
          return true;
      }
    return false;
  }

  template <class F>
  void inBox(const Vec3& lo, const Vec3& hi, F&& f) const {
    const double l[3] = {double(lo[0]), double(lo[1]), double(lo[2])};
    const double h[3] = {double(hi[0]), double(hi[1]), double(hi[2])};
    CellBox r;
    if (cellRange(grid, l, h, r)) forEachInCells(grid, r, f);
  }

  template <class F>
  void alongSegment(const Vec3& p, const Vec3& q, Real slack, const Real& best, F&& f) const {
    // Clip to the grid's box widened by a cell, so rounding cannot matter (slab method,
    // Ericson 5.3.3): no triangle lies outside it.
    double t0 = 0, t1 = 1, d[3];
    for (int a = 0; a < 3; ++a) {
      d[a] = double(q[a]) - double(p[a]);
      const double lo = grid.origin[a] - grid.cellSize;
      const double hi = grid.origin[a] + double(grid.dims[a] + 1) * grid.cellSize;
      if (d[a] == 0) {
        if (double(p[a]) < lo || double(p[a]) > hi) return;
        continue;
      }
      double ta = (lo - double(p[a])) / d[a], tb = (hi - double(p[a])) / d[a];
      if (ta > tb) std::swap(ta, tb);
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
      if (!(t0 <= t1)) return;
    }
    // Pieces about a cell long: the cells of each piece's box, not of the whole segment's box
    // (mostly empty space for a long diagonal move). Pieces go in order along the segment, so
    // once a crossing is found no later piece can hold an earlier one.
    const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) * (t1 - t0);
    const int pieces = int(std::clamp(std::ceil(length / grid.cellSize), 1.0, double(kMaxSegmentPieces)));
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
      if (cellRange(grid, l, h, r)) forEachInCells(grid, r, f);
      if (double(best) <= s1) return;
    }
  }
};

struct AllCandidates {
  Index count;

  bool mayHaveAny(const Vec3&, const Vec3&) const { return count > 0; }

  template <class F>
  void inBox(const Vec3&, const Vec3&, F&& f) const {
    for (Index k = 0; k < count; ++k) f(k);
  }
  template <class F>
  void alongSegment(const Vec3&, const Vec3&, Real, const Real&, F&& f) const {
    for (Index k = 0; k < count; ++k) f(k);
  }
};

// Grid over the triangles' widened boxes; a triangle is entered in each cell of its box that its
// plane passes through (counting sort: count, prefix sum, fill, in triangle order).
TriangleGrid buildGrid(const ColliderGeometry& geometry, Real requestedCellSize) {
  TriangleGrid g;
  const auto& triangles = geometry.triangles;
  if (triangles.empty()) return g;
  std::array<double, 3> hi;
  g.origin.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  for (const ColliderTriangle& t : triangles)
    for (int a = 0; a < 3; ++a) {
      g.origin[a] = std::min(g.origin[a], double(t.boxLo[a]));
      hi[a] = std::max(hi[a], double(t.boxHi[a]));
    }
  // Enlarge the cells while the grid would need more than the budget (a big, mostly empty
  // container with small particles).
  const double budget = std::max(kMinCellBudget, kCellsPerTriangle * double(triangles.size()));
  g.cellSize = double(requestedCellSize);
  double cells = 0, dims[3];
  for (;;) {
    g.invCell = 1.0 / g.cellSize;
    cells = 1;
    for (int a = 0; a < 3; ++a) cells *= dims[a] = std::floor((hi[a] - g.origin[a]) * g.invCell) + 1;
    if (cells <= budget) break;
    g.cellSize *= std::cbrt(cells / budget) * 1.01;
  }
  for (int a = 0; a < 3; ++a) g.dims[a] = std::int64_t(dims[a]);

  const double pad = 1e-6 * g.cellSize;  // covers rounding of the cell coordinates
  auto forEachCellOf = [&](const ColliderTriangle& t, auto&& f) {
    const double l[3] = {double(t.boxLo[0]), double(t.boxLo[1]), double(t.boxLo[2])};
    const double h[3] = {double(t.boxHi[0]), double(t.boxHi[1]), double(t.boxHi[2])};
    CellBox r;
    if (!cellRange(g, l, h, r)) return;
    for (std::int64_t z = r.lo[2]; z <= r.hi[2]; ++z)
      for (std::int64_t y = r.lo[1]; y <= r.hi[1]; ++y)
        for (std::int64_t x = r.lo[0]; x <= r.hi[0]; ++x) {
          const std::int64_t c[3] = {x, y, z};
          double cl[3], ch[3];
          for (int a = 0; a < 3; ++a) {
            cl[a] = g.origin[a] + double(c[a]) * g.cellSize - pad;
            ch[a] = g.origin[a] + double(c[a] + 1) * g.cellSize + pad;
          }
          if (planeTouchesBox(t, cl, ch, 2 * double(t.slack)))
            f(std::size_t((z * g.dims[1] + y) * g.dims[0] + x));
        }
  };
  g.cellStart.assign(std::size_t(cells) + 1, 0);
  for (const ColliderTriangle& t : triangles)
    forEachCellOf(t, [&](std::size_t cell) { ++g.cellStart[cell + 1]; });
  std::uint64_t total = 0;
  for (Index& s : g.cellStart) {
    total += s;
    if (total >= std::uint64_t(kNone))
      throw std::length_error("StaticMeshCollider: too many (cell, triangle) pairs");
    s = Index(total);
  }
  g.entries.resize(std::size_t(total));
  std::vector<Index> cursor(g.cellStart.begin(), g.cellStart.end() - 1);
  for (Index k = 0; k < Index(triangles.size()); ++k)
    forEachCellOf(triangles[k], [&](std::size_t cell) { g.entries[cursor[cell]++] = k; });
  return g;
}

}  // namespace

namespace detail {

ColliderGeometry buildColliderGeometry(const std::vector<Vec3>& vertices,
                                       const std::vector<Triangle>& triangles) {
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Index v = triangles[t][std::size_t(k)];
      if (v >= vertices.size())
        throw std::invalid_argument("StaticMeshCollider: triangle " + std::to_string(t) + " corner " +
                                    std::to_string(k) + " is vertex " + std::to_string(v) +
                                    ", expected an index < " + std::to_string(vertices.size()) +
                                    " (the vertex count)");
      if (!vertices[v].allFinite())
        throw std::invalid_argument("StaticMeshCollider: triangle " + std::to_string(t) + " uses vertex " +
                                    std::to_string(v) + " = " + describe(vertices[v]) +
                                    ", expected finite coordinates");
    }
  ColliderGeometry g;
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    if (!vertices[v].allFinite())
      throw std::invalid_argument("StaticMeshCollider: vertex " + std::to_string(v) + " = " +
                                  describe(vertices[v]) +
                                  " (used by no triangle), expected finite coordinates");
    g.coordScale = std::max(g.coordScale, maxAbs(vertices[v]));
  }
  for (std::size_t id = 0; id < triangles.size(); ++id) {
    ColliderTriangle t;
    t.a = vertices[triangles[id][0]];
    t.b = vertices[triangles[id][1]];
    t.c = vertices[triangles[id][2]];
    const Vec3 n = (t.b - t.a).cross(t.c - t.a);
    const Real area2 = n.norm();  // twice the area
    const Real longest = std::max({(t.b - t.a).norm(), (t.c - t.a).norm(), (t.c - t.b).norm()});
    if (!(area2 > kDegenerate * longest * longest)) continue;
    t.normal = n / area2;
    t.baryNormal = t.normal / area2;
    // Wide enough for points the barycentric tolerance accepts (at most kBaryTol times a
    // height outside an edge, twice that near a corner) and for rounding of the coordinates.
    t.slack = 2 * kBaryTol * longest + kRound * (g.coordScale + longest);
    t.boxLo = t.a.cwiseMin(t.b).cwiseMin(t.c) - Vec3::Constant(t.slack);
    t.boxHi = t.a.cwiseMax(t.b).cwiseMax(t.c) + Vec3::Constant(t.slack);
    t.id = Index(id);
    g.triangles.push_back(t);
  }
  return g;
}

}  // namespace detail

StaticMeshCollider::StaticMeshCollider(std::vector<Vec3> vertices, std::vector<Triangle> triangles,
                                       Real cellSize)
    : m_vertices(std::move(vertices)), m_triangles(std::move(triangles)) {
  if (!(cellSize > 0) || !std::isfinite(cellSize))
    throw std::invalid_argument("StaticMeshCollider: cellSize is " + std::to_string(cellSize) +
                                ", expected a finite value > 0 (about 2-4 particle radii)");
  if (m_triangles.size() >= std::size_t(kNone))
    throw std::length_error("StaticMeshCollider: too many triangles");
  m_geometry = detail::buildColliderGeometry(m_vertices, m_triangles);
  m_slotOf.assign(m_triangles.size(), kNone);
  for (Index k = 0; k < Index(m_geometry.triangles.size()); ++k) m_slotOf[m_geometry.triangles[k].id] = k;
  m_grid = buildGrid(m_geometry, cellSize);
}

Vec3 StaticMeshCollider::collide(const Vec3& previous, const Vec3& predicted, Real radius) const {
  return collideWith(m_geometry, GridCandidates{m_grid}, previous, predicted, radius);
}

void StaticMeshCollider::candidateTriangles(const Vec3& lo, const Vec3& hi, std::vector<Index>& out) const {
  out.clear();
  const double l[3] = {double(lo[0]), double(lo[1]), double(lo[2])};
  const double h[3] = {double(hi[0]), double(hi[1]), double(hi[2])};
  CellBox r;
  auto keep = [&](Index k) {
    const ColliderTriangle& t = m_geometry.triangles[k];
    if (planeTouchesBox(t, l, h, double(t.slack))) out.push_back(t.id);
  };
  if (cellRange(m_grid, l, h, r)) forEachInCells(m_grid, r, keep);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

bool StaticMeshCollider::triangleMayTouchBox(Index triangle, const Vec3& lo, const Vec3& hi) const {
  if (triangle >= m_slotOf.size() || m_slotOf[triangle] == kNone) return false;
  const ColliderTriangle& t = m_geometry.triangles[m_slotOf[triangle]];
  const double l[3] = {double(lo[0]), double(lo[1]), double(lo[2])};
  const double h[3] = {double(hi[0]), double(hi[1]), double(hi[2])};
  return planeTouchesBox(t, l, h, double(t.slack));
}

Vec3 collideBruteForce(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                       const Vec3& previous, const Vec3& predicted, Real radius) {
  const ColliderGeometry geometry = detail::buildColliderGeometry(vertices, triangles);
  return collideWith(geometry, AllCandidates{Index(geometry.triangles.size())}, previous, predicted, radius);
}

}  // namespace hs::pbd
