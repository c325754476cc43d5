#include "mesh/surface_remesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace hs::pbd {

namespace {

constexpr Index kNone = ~Index(0);

// A surface under edit: triangles may die (collapse), vertices too; each vertex knows the
// triangles around it (alive or dead: filtered on use).
class EditableSurface {
 public:
  EditableSurface(const std::vector<Vec3>& v, const std::vector<Triangle>& t)
      : m_tris(t), m_triDead(t.size(), false) {
    for (const Vec3& p : v) m_pos.push_back(p.cast<double>());
    m_vertDead.assign(v.size(), false);
    m_around.resize(v.size());
    for (Index f = 0; f < m_tris.size(); ++f)
      for (Index i : m_tris[f]) m_around[i].push_back(f);
  }

  std::vector<Vec3d> m_pos;
  std::vector<Triangle> m_tris;
  std::vector<bool> m_triDead, m_vertDead;
  std::vector<std::vector<Index>> m_around;

  std::vector<Index> trianglesAt(Index v) const {
    std::vector<Index> out;
    for (Index f : m_around[v])
      if (!m_triDead[f] && std::find(out.begin(), out.end(), f) == out.end()) out.push_back(f);
    return out;
  }
  std::vector<Index> trianglesOfEdge(Index a, Index b) const {
    std::vector<Index> out;
    for (Index f : trianglesAt(a))
      if (contains(m_tris[f], b)) out.push_back(f);
    return out;
  }
  std::vector<Index> neighbours(Index v) const {
    std::vector<Index> nb;
    for (Index f : trianglesAt(v))
      for (Index w : m_tris[f])
        if (w != v) nb.push_back(w);
    std::sort(nb.begin(), nb.end());
    nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
    return nb;
  }
  bool onBoundary(Index v) const {
    for (Index w : neighbours(v))
      if (trianglesOfEdge(v, w).size() == 1) return true;
    return false;
  }
  // Unique alive edges (a < b), sorted.
  std::vector<Edge> edges() const {
    std::vector<Edge> e;
    for (Index f = 0; f < m_tris.size(); ++f) {
      if (m_triDead[f]) continue;
      for (std::size_t k = 0; k < 3; ++k) {
        const Index a = m_tris[f][k], b = m_tris[f][(k + 1) % 3];
        e.push_back({std::min(a, b), std::max(a, b)});
      }
    }
    std::sort(e.begin(), e.end());
    e.erase(std::unique(e.begin(), e.end()), e.end());
    return e;
  }
  double length(Index a, Index b) const { return (m_pos[a] - m_pos[b]).norm(); }
  Vec3d normal(const Triangle& t) const {
    return (m_pos[t[1]] - m_pos[t[0]]).cross(m_pos[t[2]] - m_pos[t[0]]);
  }

  static bool contains(const Triangle& t, Index v) { return t[0] == v || t[1] == v || t[2] == v; }

  // Triangle (x, y, c) traversing x -> y: replaced by (x, m, c) and (m, y, c).
  void split(Index a, Index b) {
    const Index m = static_cast<Index>(m_pos.size());
    m_pos.push_back(0.5 * (m_pos[a] + m_pos[b]));
    m_vertDead.push_back(false);
    m_around.emplace_back();
    for (Index f : trianglesOfEdge(a, b)) {
      Triangle t = m_tris[f];
      int k = 0;
      while (!((t[k] == a && t[(k + 1) % 3] == b) || (t[k] == b && t[(k + 1) % 3] == a))) ++k;
      const Index x = t[k], y = t[(k + 1) % 3], c = t[(k + 2) % 3];
      m_tris[f] = {x, m, c};
      const auto g = static_cast<Index>(m_tris.size());
      m_tris.push_back({m, y, c});
      m_triDead.push_back(false);
      m_around[m].push_back(f);
      m_around[m].push_back(g);
      m_around[c].push_back(g);
      auto& aroundY = m_around[y];
      std::replace(aroundY.begin(), aroundY.end(), f, g);
    }
  }

  // Removes vertex r into k, which moves to `target`; checks first, returns whether done.
  bool collapse(Index r, Index k, const Vec3d& target, double maxEdge) {
    const std::vector<Index> shared = trianglesOfEdge(r, k);
    // Link condition: the common neighbours are exactly the edge's opposite vertices.
    const std::vector<Index> nr = neighbours(r), nk = neighbours(k);
    std::vector<Index> common;
    std::set_intersection(nr.begin(), nr.end(), nk.begin(), nk.end(), std::back_inserter(common));
    if (common.size() != shared.size()) return false;
    for (Index n : nr)
      if (n != k && (target - m_pos[n]).norm() > maxEdge) return false;
    for (Index n : nk)
      if (n != r && (target - m_pos[n]).norm() > maxEdge) return false;
    // No triangle may fold or flatten: its normal keeps its side.
    for (Index v : {r, k})
      for (Index f : trianglesAt(v)) {
        if (contains(m_tris[f], r) && contains(m_tris[f], k)) continue;
        const Vec3d before = normal(m_tris[f]);
        Triangle t = m_tris[f];
        std::vector<Vec3d> p = {m_pos[t[0]], m_pos[t[1]], m_pos[t[2]]};
        for (int j = 0; j < 3; ++j)
          if (t[j] == r || t[j] == k) p[j] = target;
        const Vec3d after = (p[1] - p[0]).cross(p[2] - p[0]);
        if (after.dot(before) <= 0.3 * before.norm() * after.norm() || after.norm() < 1e-3 * before.norm())
          return false;
      }
    for (Index f : shared) m_triDead[f] = true;
    for (Index f : trianglesAt(r)) {
      for (Index& v : m_tris[f])
        if (v == r) v = k;
      m_around[k].push_back(f);
    }
    m_pos[k] = target;
    m_vertDead[r] = true;
    m_around[r].clear();
    return true;
  }
};

int valenceTarget(bool boundary) { return boundary ? 4 : 6; }

void splitLongEdges(EditableSurface& s, double maxEdge) {
  for (const Edge& e : s.edges())
    if (s.length(e[0], e[1]) > maxEdge) s.split(e[0], e[1]);
}

void collapseShortEdges(EditableSurface& s, double minEdge, double maxEdge) {
  for (const Edge& e : s.edges()) {
    const Index a = e[0], b = e[1];
    if (s.m_vertDead[a] || s.m_vertDead[b]) continue;
    const std::vector<Index> shared = s.trianglesOfEdge(a, b);
    if (shared.empty() || s.length(a, b) >= minEdge) continue;
    const bool ba = s.onBoundary(a), bb = s.onBoundary(b);
    if (shared.size() == 1) {
      // A boundary edge: the loop keeps at least 3 vertices and no ear (a triangle with two
      // boundary edges) is collapsed into a dangling edge.
      const Triangle& t = s.m_tris[shared[0]];
      const Index c = t[0] != a && t[0] != b ? t[0] : (t[1] != a && t[1] != b ? t[1] : t[2]);
      if (s.trianglesOfEdge(a, c).size() == 1 || s.trianglesOfEdge(b, c).size() == 1) continue;
      s.collapse(b, a, 0.5 * (s.m_pos[a] + s.m_pos[b]), maxEdge);
    } else if (shared.size() == 2) {
      if (ba && bb) continue;  // an interior edge between two loop vertices would pinch the surface
      if (ba)
        s.collapse(b, a, s.m_pos[a], maxEdge);
      else if (bb)
        s.collapse(a, b, s.m_pos[b], maxEdge);
      else
        s.collapse(b, a, 0.5 * (s.m_pos[a] + s.m_pos[b]), maxEdge);
    }
  }
}

void flipEdges(EditableSurface& s) {
  std::vector<int> valence(s.m_pos.size(), 0);
  std::vector<bool> boundary(s.m_pos.size(), false);
  for (Index v = 0; v < s.m_pos.size(); ++v) {
    if (s.m_vertDead[v]) continue;
    valence[v] = static_cast<int>(s.neighbours(v).size());
    boundary[v] = s.onBoundary(v);
  }
  for (const Edge& e : s.edges()) {
    const Index a = e[0], b = e[1];
    const std::vector<Index> shared = s.trianglesOfEdge(a, b);
    if (shared.size() != 2) continue;
    // Orient: t1 traverses a -> b, t2 traverses b -> a.
    Triangle t1 = s.m_tris[shared[0]], t2 = s.m_tris[shared[1]];
    auto traverses = [](const Triangle& t, Index x, Index y) {
      for (int k = 0; k < 3; ++k)
        if (t[k] == x && t[(k + 1) % 3] == y) return true;
      return false;
    };
    Index f1 = shared[0], f2 = shared[1];
    if (!traverses(t1, a, b)) std::swap(f1, f2), std::swap(t1, t2);
    if (!traverses(t1, a, b) || !traverses(t2, b, a)) continue;  // inconsistent orientation
    const auto third = [](const Triangle& t, Index x, Index y) {
      for (Index v : t)
        if (v != x && v != y) return v;
      return kNone;
    };
    const Index c = third(t1, a, b), d = third(t2, a, b);
    if (c == d || !s.trianglesOfEdge(c, d).empty()) continue;
    const auto dev = [&](Index v, int change) {
      return std::abs(valence[v] + change - valenceTarget(boundary[v]));
    };
    const int before = dev(a, 0) + dev(b, 0) + dev(c, 0) + dev(d, 0);
    const int after = dev(a, -1) + dev(b, -1) + dev(c, 1) + dev(d, 1);
    if (after >= before || valence[a] <= 3 || valence[b] <= 3) continue;
    // The quad a, d, b, c (counter-clockwise): the new triangles (a, d, c) and (d, b, c) must
    // face as the old ones do.
    const Triangle n1{a, d, c}, n2{d, b, c};
    const Vec3d reference = s.normal(t1).normalized() + s.normal(t2).normalized();
    const Vec3d m1 = s.normal(n1), m2 = s.normal(n2);
    if (m1.dot(reference) <= 0.5 * m1.norm() * reference.norm() ||
        m2.dot(reference) <= 0.5 * m2.norm() * reference.norm())
      continue;
    s.m_tris[f1] = n1;
    s.m_tris[f2] = n2;
    // f1 now holds a, d, c; f2 holds d, b, c: a loses f2, b loses f1, c gains f2, d gains f1.
    auto& aroundA = s.m_around[a];
    aroundA.erase(std::remove(aroundA.begin(), aroundA.end(), f2), aroundA.end());
    auto& aroundB = s.m_around[b];
    aroundB.erase(std::remove(aroundB.begin(), aroundB.end(), f1), aroundB.end());
    s.m_around[c].push_back(f2);
    s.m_around[d].push_back(f1);
    --valence[a], --valence[b], ++valence[c], ++valence[d];
  }
}

// The input's boundary edges, for sliding loop vertices along their loop.
struct ReferenceBoundary {
  std::vector<std::array<Vec3d, 2>> edges;

  Vec3d closestPoint(const Vec3d& p) const {
    double best = std::numeric_limits<double>::infinity();
    Vec3d bestPoint = p;
    for (const auto& [a, b] : edges) {
      const Vec3d ab = b - a;
      const double s = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
      const Vec3d q = a + s * ab;
      if ((q - p).norm() < best) best = (q - p).norm(), bestPoint = q;
    }
    return bestPoint;
  }
};

void relaxTangentially(EditableSurface& s, const ClosestPointQuery& reference,
                       const ReferenceBoundary& boundary) {
  std::vector<Vec3d> next = s.m_pos;
  for (Index v = 0; v < s.m_pos.size(); ++v) {
    if (s.m_vertDead[v]) continue;
    if (s.onBoundary(v)) {
      // Along the loop: toward the midpoint of its two loop neighbours, back onto the input's
      // loop, so that the loop's edges even out while it keeps its shape.
      std::vector<Index> along;
      for (Index w : s.neighbours(v))
        if (s.trianglesOfEdge(v, w).size() == 1) along.push_back(w);
      if (along.size() == 2) next[v] = boundary.closestPoint(0.5 * (s.m_pos[along[0]] + s.m_pos[along[1]]));
      continue;
    }
    const std::vector<Index> nb = s.neighbours(v);
    if (nb.empty()) continue;
    Vec3d centroid = Vec3d::Zero();
    for (Index w : nb) centroid += s.m_pos[w];
    centroid /= double(nb.size());
    Vec3d n = Vec3d::Zero();
    for (Index f : s.trianglesAt(v)) n += s.normal(s.m_tris[f]);
    if (n.norm() == 0) continue;
    n.normalize();
    // p + (I - n n^T)(c - p): toward the centroid, within the tangent plane.
    const Vec3d moved = s.m_pos[v] + (centroid - s.m_pos[v]) - n * n.dot(centroid - s.m_pos[v]);
    next[v] = reference.closestPoint(moved);
  }
  s.m_pos = std::move(next);
}

}  // namespace

RemeshedSurface remeshIsotropic(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                                const RemeshSettings& settings) {
  if (!(settings.targetEdge > 0)) throw std::invalid_argument("remeshIsotropic: targetEdge must be > 0");
  const ClosestPointQuery reference(vertices, triangles);
  ReferenceBoundary boundary;
  for (const std::vector<Index>& loop : boundaryLoopVertices(triangles))
    for (std::size_t k = 0; k < loop.size(); ++k)
      boundary.edges.push_back(
          {vertices[loop[k]].cast<double>(), vertices[loop[(k + 1) % loop.size()]].cast<double>()});
  EditableSurface s(vertices, triangles);
  const double high = 4.0 / 3.0 * settings.targetEdge, low = 4.0 / 5.0 * settings.targetEdge;
  for (int it = 0; it < settings.iterations; ++it) {
    splitLongEdges(s, high);
    collapseShortEdges(s, low, high);
    flipEdges(s);
    relaxTangentially(s, reference, boundary);
  }
  // Compact: alive vertices in their order, alive triangles in theirs.
  RemeshedSurface out;
  std::vector<Index> newId(s.m_pos.size(), kNone);
  for (Index f = 0; f < s.m_tris.size(); ++f)
    if (!s.m_triDead[f])
      for (Index v : s.m_tris[f]) newId[v] = 0;
  for (Index v = 0; v < s.m_pos.size(); ++v)
    if (newId[v] != kNone) {
      newId[v] = static_cast<Index>(out.vertices.size());
      out.vertices.push_back(s.m_pos[v].cast<Real>());
    }
  for (Index f = 0; f < s.m_tris.size(); ++f)
    if (!s.m_triDead[f])
      out.triangles.push_back({newId[s.m_tris[f][0]], newId[s.m_tris[f][1]], newId[s.m_tris[f][2]]});
  return out;
}

double restoreCappedVolume(std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles, double targetVolume) {
  const double restVolume = cappedSignedVolume(vertices, triangles);
  const double sign = restVolume < 0 ? -1.0 : 1.0;  // triangles facing in or out
  const double target = std::abs(targetVolume);
  // Each vertex's share of the distance: 0 on a loop, 1/2 next to one (so that the rim's
  // triangles do not tilt by the whole step at once), 1 beyond.
  std::vector<double> share(vertices.size(), 1);
  for (const std::vector<Index>& loop : boundaryLoopVertices(triangles))
    for (Index v : loop) share[v] = 0;
  const std::vector<double> loopShare = share;
  for (const Triangle& t : triangles)
    for (Index a : t)
      for (Index b : t)
        if (loopShare[b] == 0 && loopShare[a] != 0) share[a] = 0.5;
  // Outward (away from the cavity) unit normals times the shares.
  std::vector<Vec3d> outward = vertexNormals(vertices, triangles);
  for (std::size_t v = 0; v < outward.size(); ++v) outward[v] *= sign * share[v];
  const std::vector<Vec3> rest = vertices;
  auto volumeAt = [&](double d) {
    for (std::size_t v = 0; v < vertices.size(); ++v) vertices[v] = (rest[v].cast<double>() + d * outward[v]).cast<Real>();
    return std::abs(cappedSignedVolume(vertices, triangles));
  };
  double d0 = 0, v0 = std::abs(restVolume);
  if (!(target > 0) || std::abs(v0 - target) <= 1e-9 * target) return 0;
  // First guess: the missing volume spread over the surface, dV/dd ~ area.
  double area = 0;
  for (const Triangle& t : triangles)
    area += 0.5 * (vertices[t[1]] - vertices[t[0]]).cast<double>().cross((vertices[t[2]] - vertices[t[0]]).cast<double>()).norm();
  double d1 = area > 0 ? (target - v0) / area : 0, v1 = volumeAt(d1);
  for (int step = 0; step < 20 && std::abs(v1 - target) > 1e-9 * target && v1 != v0; ++step) {
    const double d2 = d1 + (target - v1) * (d1 - d0) / (v1 - v0);
    d0 = d1, v0 = v1;
    d1 = d2, v1 = volumeAt(d1);
  }
  return d1;  // the vertices are where the last volumeAt put them
}

EdgeLengthStats edgeLengthStats(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles) {
  EdgeLengthStats st;
  std::vector<Edge> edges;
  for (const Triangle& t : triangles)
    for (std::size_t k = 0; k < 3; ++k)
      edges.push_back({std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])});
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  if (edges.empty()) return st;
  st.shortest = std::numeric_limits<double>::infinity();
  for (const Edge& e : edges) {
    const double l = (vertices[e[0]] - vertices[e[1]]).cast<double>().norm();
    st.mean += l;
    st.shortest = std::min(st.shortest, l);
    st.longest = std::max(st.longest, l);
  }
  st.mean /= double(edges.size());
  return st;
}

}  // namespace hs::pbd
