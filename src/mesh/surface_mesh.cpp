#include "mesh/surface_mesh.h"

#include "pbd/core/closest_point.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace hs::pbd {

namespace {

Vec3d at(const std::vector<Vec3>& v, Index i) { return v[i].cast<double>(); }

}  // namespace

std::vector<std::vector<Index>> boundaryLoopVertices(const std::vector<Triangle>& triangles) {
  // Undirected edge -> (uses, the directed edge of its last use).
  std::map<std::pair<Index, Index>, std::pair<int, std::pair<Index, Index>>> uses;
  for (const Triangle& t : triangles)
    for (std::size_t k = 0; k < 3; ++k) {
      const Index a = t[k], b = t[(k + 1) % 3];
      auto& entry = uses[{std::min(a, b), std::max(a, b)}];
      ++entry.first;
      entry.second = {a, b};
    }
  std::vector<std::pair<Index, Index>> edges;
  for (const auto& [key, entry] : uses)
    if (entry.first == 1) edges.push_back(entry.second);
  std::sort(edges.begin(), edges.end());
  std::multimap<Index, std::size_t> outgoing;
  for (std::size_t e = 0; e < edges.size(); ++e) outgoing.emplace(edges[e].first, e);
  std::vector<bool> used(edges.size(), false);
  std::vector<std::vector<Index>> loops;
  for (std::size_t start = 0; start < edges.size(); ++start) {
    if (used[start]) continue;
    std::vector<Index> loop;
    std::size_t e = start;
    while (true) {
      used[e] = true;
      loop.push_back(edges[e].first);
      const Index next = edges[e].second;
      if (next == edges[start].first) break;
      std::size_t found = edges.size();
      for (auto [it, end] = outgoing.equal_range(next); it != end; ++it)
        if (!used[it->second]) {
          found = it->second;
          break;
        }
      if (found == edges.size()) {
        loop.push_back(next);  // an open chain: the surface's orientation flips here
        break;
      }
      e = found;
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

std::vector<Vec3d> vertexNormals(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles) {
  std::vector<Vec3d> n(vertices.size(), Vec3d::Zero());
  for (const Triangle& t : triangles) {
    const Vec3d a = at(vertices, t[0]);
    const Vec3d areaNormal = (at(vertices, t[1]) - a).cross(at(vertices, t[2]) - a);
    for (Index i : t) n[i] += areaNormal;
  }
  for (Vec3d& v : n)
    if (v.norm() > 0) v.normalize();
  return n;
}

std::vector<std::vector<Index>> vertexNeighbours(std::size_t vertexCount,
                                                 const std::vector<Triangle>& triangles) {
  std::vector<std::vector<Index>> nb(vertexCount);
  for (const Triangle& t : triangles)
    for (std::size_t k = 0; k < 3; ++k) {
      nb[t[k]].push_back(t[(k + 1) % 3]);
      nb[t[(k + 1) % 3]].push_back(t[k]);
    }
  for (auto& list : nb) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return nb;
}

std::vector<Vec3d> smoothNormals(std::vector<Vec3d> normals, const std::vector<Triangle>& triangles,
                                 int iterations) {
  const auto nb = vertexNeighbours(normals.size(), triangles);
  return smoothNormals(std::move(normals), nb, iterations);
}

std::vector<Vec3d> smoothNormals(std::vector<Vec3d> normals, const std::vector<std::vector<Index>>& nb,
                                 int iterations) {
  for (int it = 0; it < iterations; ++it) {
    std::vector<Vec3d> next(normals.size());
    for (std::size_t i = 0; i < normals.size(); ++i) {
      Vec3d sum = normals[i];
      for (Index j : nb[i]) sum += normals[j];
      next[i] = sum.norm() > 0 ? Vec3d(sum.normalized()) : normals[i];
    }
    normals = std::move(next);
  }
  return normals;
}

SubSurface extractSubSurface(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                             const std::vector<Index>& subset) {
  SubSurface s;
  std::vector<Index> newId(vertices.size(), ~Index(0));
  for (Index f : subset) {
    Triangle t = triangles[f];
    for (Index& i : t) {
      if (newId[i] == ~Index(0)) {
        newId[i] = static_cast<Index>(s.vertices.size());
        s.vertices.push_back(vertices[i]);
        s.originalVertex.push_back(i);
      }
      i = newId[i];
    }
    s.triangles.push_back(t);
  }
  return s;
}

Vec3d closestPointOnTriangle(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  return closestPointOnTriangleOf(p, a, b, c);
}

ClosestPointQuery::ClosestPointQuery(const std::vector<Vec3>& vertices,
                                     const std::vector<Triangle>& triangles) {
  for (const Triangle& t : triangles) {
    const std::array<Vec3d, 3> c{at(vertices, t[0]), at(vertices, t[1]), at(vertices, t[2])};
    const Vec3d centre = (c[0] + c[1] + c[2]) / 3.0;
    m_corners.push_back(c);
    m_centre.push_back(centre);
    m_radius.push_back(std::max({(c[0] - centre).norm(), (c[1] - centre).norm(), (c[2] - centre).norm()}));
  }
}

Vec3d ClosestPointQuery::closestPoint(const Vec3d& p) const {
  double best = std::numeric_limits<double>::infinity();
  Vec3d bestPoint = p;
  for (std::size_t f = 0; f < m_corners.size(); ++f) {
    if ((p - m_centre[f]).norm() - m_radius[f] >= best) continue;  // every point of f is at least this far
    const Vec3d q = closestPointOnTriangle(p, m_corners[f][0], m_corners[f][1], m_corners[f][2]);
    const double d = (q - p).norm();
    if (d < best) best = d, bestPoint = q;
  }
  return bestPoint;
}

std::optional<double> firstRayHit(const Vec3d& origin, const Vec3d& direction,
                                  const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles) {
  std::optional<double> best;
  for (const Triangle& t : triangles) {
    const Vec3d a = at(vertices, t[0]);
    const Vec3d e1 = at(vertices, t[1]) - a, e2 = at(vertices, t[2]) - a;
    const Vec3d pv = direction.cross(e2);
    const double det = e1.dot(pv);
    if (std::abs(det) < 1e-300) continue;
    const double inv = 1.0 / det;
    const Vec3d tv = origin - a;
    const double u = tv.dot(pv) * inv;
    if (u < 0 || u > 1) continue;
    const Vec3d qv = tv.cross(e1);
    const double v = direction.dot(qv) * inv;
    if (v < 0 || u + v > 1) continue;
    const double dist = e2.dot(qv) * inv;
    if (dist > 0 && (!best || dist < *best)) best = dist;
  }
  return best;
}

double cappedSignedVolume(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles) {
  double volume = 0;
  const auto add = [&](const Vec3d& a, const Vec3d& b, const Vec3d& c) { volume += a.cross(b).dot(c); };
  for (const Triangle& t : triangles) add(at(vertices, t[0]), at(vertices, t[1]), at(vertices, t[2]));
  for (const std::vector<Index>& loop : boundaryLoopVertices(triangles)) {
    Vec3d centroid = Vec3d::Zero();
    for (Index i : loop) centroid += at(vertices, i);
    centroid /= double(loop.size());
    // The fan (c, b, a) traverses each boundary edge a -> b the other way, as a neighbour would.
    for (std::size_t k = 0; k < loop.size(); ++k)
      add(centroid, at(vertices, loop[(k + 1) % loop.size()]), at(vertices, loop[k]));
  }
  return volume / 6.0;
}

std::size_t connectedPieces(std::size_t vertexCount, const std::vector<Triangle>& triangles) {
  // Union-find over vertices, path halving.
  std::vector<Index> parent(vertexCount);
  for (Index i = 0; i < vertexCount; ++i) parent[i] = i;
  const auto root = [&](Index i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::vector<bool> used(vertexCount, false);
  for (const Triangle& t : triangles)
    for (std::size_t k = 0; k < 3; ++k) {
      used[t[k]] = true;
      const Index a = root(t[k]), b = root(t[(k + 1) % 3]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  std::size_t pieces = 0;
  for (Index i = 0; i < vertexCount; ++i) pieces += used[i] && root(i) == i;
  return pieces;
}

std::vector<Index> largestFlatRegion(const std::vector<Vec3>& vertices,
                                     const std::vector<Triangle>& triangles, double angleDeg,
                                     double planeTolerance, double* area) {
  // Triangles across each edge.
  std::map<std::pair<Index, Index>, std::vector<Index>> byEdge;
  for (Index f = 0; f < triangles.size(); ++f)
    for (std::size_t k = 0; k < 3; ++k) {
      const Index a = triangles[f][k], b = triangles[f][(k + 1) % 3];
      byEdge[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  std::vector<Vec3d> normal(triangles.size());
  std::vector<double> triArea(triangles.size());
  for (Index f = 0; f < triangles.size(); ++f) {
    const Vec3d a = at(vertices, triangles[f][0]);
    const Vec3d n = (at(vertices, triangles[f][1]) - a).cross(at(vertices, triangles[f][2]) - a);
    triArea[f] = 0.5 * n.norm();
    normal[f] = n.norm() > 0 ? Vec3d(n.normalized()) : Vec3d::Zero();
  }
  const double cosLimit = std::cos(angleDeg * 3.14159265358979323846 / 180.0);
  std::vector<bool> taken(triangles.size(), false);
  std::vector<Index> best;
  double bestArea = 0;
  for (Index seed = 0; seed < triangles.size(); ++seed) {
    if (taken[seed] || triArea[seed] == 0) continue;
    const Vec3d n = normal[seed], p0 = at(vertices, triangles[seed][0]);
    std::vector<Index> region{seed}, stack{seed};
    taken[seed] = true;
    double regionArea = triArea[seed];
    while (!stack.empty()) {
      const Index f = stack.back();
      stack.pop_back();
      for (std::size_t k = 0; k < 3; ++k) {
        const Index a = triangles[f][k], b = triangles[f][(k + 1) % 3];
        for (Index g : byEdge[{std::min(a, b), std::max(a, b)}]) {
          if (taken[g] || normal[g].dot(n) < cosLimit) continue;
          bool onPlane = true;
          for (Index v : triangles[g])
            onPlane = onPlane && std::abs((at(vertices, v) - p0).dot(n)) <= planeTolerance;
          if (!onPlane) continue;
          taken[g] = true;
          region.push_back(g);
          stack.push_back(g);
          regionArea += triArea[g];
        }
      }
    }
    if (regionArea > bestArea) bestArea = regionArea, best = std::move(region);
  }
  std::sort(best.begin(), best.end());
  if (area) *area = bestArea;
  return best;
}

}  // namespace hs::pbd
