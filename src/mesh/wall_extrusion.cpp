#include "mesh/wall_extrusion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace hs::pbd {

std::array<Tet, 3> splitPrism(const Triangle& bottom, const Triangle& top) {
  // The cut starts from the prism's smallest id; when it lies on the top, the prism is read
  // upside down with its winding reversed, which keeps it positive.
  const Index least = std::min({bottom[0], bottom[1], bottom[2], top[0], top[1], top[2]});
  const bool upsideDown = least == top[0] || least == top[1] || least == top[2];
  Triangle b = upsideDown ? Triangle{top[0], top[2], top[1]} : bottom;
  Triangle u = upsideDown ? Triangle{bottom[0], bottom[2], bottom[1]} : top;
  // Rotate both (keeping the winding) so that v0 is the smallest; its two sides are cut by the
  // diagonals v0-u1 and v0-u2, the third side (v1 v2 u2 u1) by the diagonal through its own
  // smallest id.
  while (b[0] != least) {
    b = {b[1], b[2], b[0]};
    u = {u[1], u[2], u[0]};
  }
  const Index v0 = b[0], v1 = b[1], v2 = b[2];
  const Index u0 = u[0], u1 = u[1], u2 = u[2];
  // Orientation checked on the unit prism (v0, v1, v2) = (0,0,0), (1,0,0), (0,1,0), lifted by
  // z = 1: each has 6V = 1 (tests/mesh/test_wall_extrusion.cpp).
  const Index sideLeast = std::min({v1, v2, u1, u2});
  if (sideLeast == v1 || sideLeast == u2) return {{{v0, u1, u2, u0}, {v0, v1, v2, u2}, {v0, v1, u2, u1}}};
  return {{{v0, u1, u2, u0}, {v0, v1, v2, u1}, {v0, u1, v2, u2}}};
}

std::array<Tet, 3> splitPrism(const Triangle& bottom, Index layerOffset) {
  return splitPrism(bottom, {bottom[0] + layerOffset, bottom[1] + layerOffset, bottom[2] + layerOffset});
}

namespace {

// Builds the layers and tets for the given thickness; returns the surface vertices of bad tets.
std::vector<Index> buildLayers(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                               const std::vector<double>& thickness, const std::vector<Vec3d>& d,
                               const ExtrusionSettings& settings, TetMesh& mesh) {
  const auto n = static_cast<Index>(vertices.size());
  mesh.vertices.clear();
  mesh.tets.clear();
  for (int k = 0; k <= settings.layers; ++k)
    for (Index i = 0; i < n; ++i)
      mesh.vertices.push_back(
          (vertices[i].cast<double>() + d[i] * (thickness[i] * k / settings.layers)).cast<Real>());
  std::vector<Index> bad;
  for (int k = 0; k < settings.layers; ++k)
    for (const Triangle& f : triangles) {
      const Triangle bottom{f[0] + k * n, f[1] + k * n, f[2] + k * n};
      for (const Tet& t : splitPrism(bottom, n)) {
        mesh.tets.push_back(t);
        std::array<Vec3d, 4> x;
        double longest = 0;
        for (int j = 0; j < 4; ++j) x[j] = mesh.vertices[t[j]].cast<double>();
        for (int a = 0; a < 4; ++a)
          for (int b = a + 1; b < 4; ++b) longest = std::max(longest, (x[a] - x[b]).norm());
        const double sixV = (x[1] - x[0]).cross(x[2] - x[0]).dot(x[3] - x[0]);
        if (!(sixV > settings.flatVolume * longest * longest * longest))
          for (Index v : f) bad.push_back(v);
      }
    }
  // Positive tets are not enough: where the offsets cross (an offset deeper than the radius of
  // curvature) a triangle can come out turned by 180 degrees in its plane, which keeps every
  // volume positive while the wall overlaps itself. The offset edge e(s) = e_0 + s (t_j d_j -
  // t_i d_i) is linear in the offset s, so e(s) . e_0 stays above minEdgeScale |e_0|^2 for all
  // layers when it does at the outermost one.
  const auto outer = static_cast<Index>(settings.layers) * n;
  for (const Triangle& f : triangles)
    for (std::size_t k = 0; k < 3; ++k) {
      const Index i = f[k], j = f[(k + 1) % 3];
      const Vec3d e0 = (vertices[j] - vertices[i]).cast<double>();
      const Vec3d e1 = (mesh.vertices[j + outer] - mesh.vertices[i + outer]).cast<double>();
      if (!(e1.dot(e0) > settings.minEdgeScale * e0.squaredNorm())) bad.insert(bad.end(), {i, j});
    }
  std::sort(bad.begin(), bad.end());
  bad.erase(std::unique(bad.begin(), bad.end()), bad.end());
  return bad;
}

// Smallest dihedral angle of a tet, as the cosine's arc of its outward face normals (the same
// measure as measureQuality); -1 for a non-positive tet.
double minDihedral(const std::array<Vec3d, 4>& x) {
  if (!((x[1] - x[0]).cross(x[2] - x[0]).dot(x[3] - x[0]) > 0)) return -1;
  const std::array<Vec3d, 4> n = {
      (x[2] - x[1]).cross(x[3] - x[1]).normalized(), (x[3] - x[0]).cross(x[2] - x[0]).normalized(),
      (x[1] - x[0]).cross(x[3] - x[0]).normalized(), (x[2] - x[0]).cross(x[1] - x[0]).normalized()};
  double worst = 4;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      worst = std::min(worst, 3.141592653589793 - std::acos(std::clamp(n[i].dot(n[j]), -1.0, 1.0)));
  return worst;
}

// Smart Laplacian smoothing (Freitag & Ollivier-Gooch 1997, "Tetrahedral mesh improvement
// using swapping and smoothing", IJNME 40) of the offset layers: each vertex above the surface
// moves halfway toward the mean of its neighbours in the same layer, across its offset
// direction only (its layer's distance from the surface is kept), and only when the worst
// dihedral angle of its tets grows. The surface itself (layer 0) is never moved.
void smoothLayers(TetMesh& mesh, std::size_t n, const std::vector<std::vector<Index>>& neighbours,
                  const std::vector<Vec3d>& directions, int sweeps) {
  std::vector<std::vector<Index>> tetsAt(mesh.vertices.size());
  for (Index t = 0; t < mesh.tets.size(); ++t)
    for (Index v : mesh.tets[t]) tetsAt[v].push_back(t);
  const auto worstAround = [&](Index v) {
    double worst = 4;
    for (Index t : tetsAt[v]) {
      std::array<Vec3d, 4> x;
      for (int k = 0; k < 4; ++k) x[k] = mesh.vertices[mesh.tets[t][k]].cast<double>();
      worst = std::min(worst, minDihedral(x));
    }
    return worst;
  };
  for (int sweep = 0; sweep < sweeps; ++sweep)
    for (std::size_t v = n; v < mesh.vertices.size(); ++v) {
      const std::size_t i = v % n, layerStart = v - i;
      if (neighbours[i].empty()) continue;
      Vec3d mean = Vec3d::Zero();
      for (Index j : neighbours[i])
        mean += mesh.vertices[layerStart + j].cast<double>() / double(neighbours[i].size());
      const Vec3d p = mesh.vertices[v].cast<double>(), d = directions[i];
      const Vec3d move = 0.5 * ((mean - p) - d * d.dot(mean - p));
      const double before = worstAround(static_cast<Index>(v));
      mesh.vertices[v] = (p + move).cast<Real>();
      if (!(worstAround(static_cast<Index>(v)) > before)) mesh.vertices[v] = p.cast<Real>();
    }
}

}  // namespace

std::vector<Vec3d> offsetDirections(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                                    const ExtrusionSettings& settings) {
  const std::vector<Vec3d> raw = vertexNormals(vertices, triangles);
  std::vector<Vec3d> d = smoothNormals(raw, triangles, settings.normalSmoothing);
  // Smoothing turns a direction away from the faces at a crease; a prism over a face its
  // direction runs nearly along is a sliver. Each direction is turned back toward the face it
  // sees worst until it sees every face at its vertex at least at minFaceCosine (or gives up
  // after 20 steps: a vertex whose faces open wider than that cannot see them all).
  std::vector<std::vector<Vec3d>> faceNormals(vertices.size());
  for (const Triangle& t : triangles) {
    const Vec3d a = vertices[t[0]].cast<double>();
    const Vec3d n = (vertices[t[1]].cast<double>() - a).cross(vertices[t[2]].cast<double>() - a);
    if (n.norm() == 0) continue;
    for (Index i : t) faceNormals[i].push_back(n.normalized());
  }
  const auto worstCosine = [&](std::size_t i, const Vec3d& direction) {
    double worst = 1;
    for (const Vec3d& n : faceNormals[i]) worst = std::min(worst, n.dot(direction));
    return worst;
  };
  for (std::size_t i = 0; i < d.size(); ++i) {
    // Smoothing that went too far (a small closed surface averages to nothing) and now sees a
    // face from behind: start again from the unsmoothed normal where that sees the faces better.
    if (worstCosine(i, d[i]) < 0 && worstCosine(i, raw[i]) > worstCosine(i, d[i])) d[i] = raw[i];
    for (int step = 0; step < 20 && !faceNormals[i].empty(); ++step) {
      const Vec3d* worst = &faceNormals[i][0];
      for (const Vec3d& n : faceNormals[i])
        if (n.dot(d[i]) < worst->dot(d[i])) worst = &n;
      if (worst->dot(d[i]) >= settings.minFaceCosine) break;
      d[i] = (d[i] + 0.25 * *worst).normalized();
    }
  }
  return d;
}

ExtrudedWall extrudeWall(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                         const std::vector<double>& thickness, const ExtrusionSettings& settings) {
  if (thickness.size() != vertices.size())
    throw std::invalid_argument("extrudeWall: " + std::to_string(thickness.size()) + " thicknesses for " +
                                std::to_string(vertices.size()) + " vertices");
  if (settings.layers < 1) throw std::invalid_argument("extrudeWall: layers must be >= 1");
  ExtrudedWall wall;
  wall.surfaceVertices = vertices.size();
  wall.thickness = thickness;
  wall.directions = offsetDirections(vertices, triangles, settings);
  std::vector<bool> shrunk(vertices.size(), false);
  const std::vector<std::vector<Index>> neighbours = vertexNeighbours(vertices.size(), triangles);
  for (int round = 0;; ++round) {
    const std::vector<Index> bad =
        buildLayers(vertices, triangles, wall.thickness, wall.directions, settings, wall.mesh);
    if (bad.empty()) break;
    if (round == settings.maxShrinkRounds)
      throw std::runtime_error(
          "extrudeWall: " + std::to_string(bad.size()) +
          " surface vertices still have inverted or flat tets after shrinking the wall " +
          std::to_string(round) + " times");
    for (Index v : bad) wall.thickness[v] *= settings.shrink, shrunk[v] = true;
    // Thickness that steps from one vertex to the next skews the prisms between them: the
    // neighbours give way too, t_i <- min(t_i, (t_i + mean_(j ~ i) t_j) / 2), twice.
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<double> next = wall.thickness;
      for (std::size_t i = 0; i < next.size(); ++i) {
        if (neighbours[i].empty()) continue;
        double mean = 0;
        for (Index j : neighbours[i]) mean += wall.thickness[j] / double(neighbours[i].size());
        next[i] = std::min(next[i], 0.5 * (wall.thickness[i] + mean));
      }
      wall.thickness = std::move(next);
    }
  }
  smoothLayers(wall.mesh, vertices.size(), neighbours, wall.directions, settings.smoothingSweeps);
  for (std::size_t i = 0; i < shrunk.size(); ++i) shrunk[i] = shrunk[i] || wall.thickness[i] < thickness[i];
  wall.shrunkVertices = static_cast<int>(std::count(shrunk.begin(), shrunk.end(), true));
  const auto offset = static_cast<Index>(settings.layers * vertices.size());
  wall.innerSurface = triangles;
  for (const Triangle& f : triangles)
    wall.outerSurface.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
  return wall;
}

std::vector<double> thicknessToSurface(const std::vector<Vec3>& vertices,
                                       const std::vector<Vec3d>& directions,
                                       const std::vector<Vec3>& otherVertices,
                                       const std::vector<Triangle>& otherTriangles) {
  std::vector<double> t(vertices.size(), 0);
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const Vec3d p = vertices[i].cast<double>();
    if (const auto hit = firstRayHit(p, directions[i], otherVertices, otherTriangles)) {
      t[i] = *hit;
      continue;
    }
    double best = std::numeric_limits<double>::infinity();
    for (const Triangle& f : otherTriangles)
      best = std::min(best, (closestPointOnTriangle(p, otherVertices[f[0]].cast<double>(),
                                                    otherVertices[f[1]].cast<double>(),
                                                    otherVertices[f[2]].cast<double>()) -
                             p)
                                .norm());
    t[i] = best;
  }
  return t;
}

}  // namespace hs::pbd
