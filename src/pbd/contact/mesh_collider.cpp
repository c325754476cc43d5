// The static mesh collider's collision response (mesh_collider.h): the mesh's checks and
// preprocessing, the tunnelling test and the contact push-outs, run over the candidates of its
// triangle grid (mesh_collider_grid.cpp) or, as the tests' reference, over every triangle.
#include "pbd/contact/mesh_collider.h"

#include "pbd/core/closest_point.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace hs::pbd {
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  return closestPointOnTriangleOf(p, a, b, c);
}

namespace {

using detail::ColliderGeometry;
using detail::ColliderTriangle;

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
  m_grid = detail::TriangleGrid(m_geometry, cellSize);
}

Vec3 StaticMeshCollider::collide(const Vec3& previous, const Vec3& predicted, Real radius) const {
  return collideWith(m_geometry, m_grid, previous, predicted, radius);
}

void StaticMeshCollider::candidateTriangles(const Vec3& lo, const Vec3& hi, std::vector<Index>& out) const {
  out.clear();
  const double l[3] = {double(lo[0]), double(lo[1]), double(lo[2])};
  const double h[3] = {double(hi[0]), double(hi[1]), double(hi[2])};
  m_grid.inBox(lo, hi, [&](Index k) {
    const ColliderTriangle& t = m_geometry.triangles[k];
    if (detail::planeTouchesBox(t, l, h, double(t.slack))) out.push_back(t.id);
  });
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

bool StaticMeshCollider::triangleMayTouchBox(Index triangle, const Vec3& lo, const Vec3& hi) const {
  if (triangle >= m_slotOf.size() || m_slotOf[triangle] == kNone) return false;
  const ColliderTriangle& t = m_geometry.triangles[m_slotOf[triangle]];
  const double l[3] = {double(lo[0]), double(lo[1]), double(lo[2])};
  const double h[3] = {double(hi[0]), double(hi[1]), double(hi[2])};
  return detail::planeTouchesBox(t, l, h, double(t.slack));
}

Vec3 collideBruteForce(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                       const Vec3& previous, const Vec3& predicted, Real radius) {
  const ColliderGeometry geometry = detail::buildColliderGeometry(vertices, triangles);
  return collideWith(geometry, AllCandidates{Index(geometry.triangles.size())}, previous, predicted, radius);
}

}  // namespace hs::pbd
