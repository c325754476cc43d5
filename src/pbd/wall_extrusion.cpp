#include "pbd/wall_extrusion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace hs::pbd {

std::array<Tet, 3> splitPrism(const Triangle& bottom, Index layerOffset) {
  // Rotate (keeping the winding) so that v0 has the smallest id; its two sides are cut by the
  // diagonals v0-v1' and v0-v2', the third side by the diagonal through min(v1, v2).
  Triangle t = bottom;
  while (!(t[0] < t[1] && t[0] < t[2])) t = {t[1], t[2], t[0]};
  const Index v0 = t[0], v1 = t[1], v2 = t[2];
  const Index u0 = v0 + layerOffset, u1 = v1 + layerOffset, u2 = v2 + layerOffset;
  // Orientation checked on the unit prism (v0, v1, v2) = (0,0,0), (1,0,0), (0,1,0), lifted by
  // z = 1: each has 6V = 1 (tests/pbd/test_wall_extrusion.cpp).
  if (v1 < v2) return {{{v0, u1, u2, u0}, {v0, v1, v2, u2}, {v0, v1, u2, u1}}};
  return {{{v0, u1, u2, u0}, {v0, v1, v2, u1}, {v0, u1, v2, u2}}};
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
      mesh.vertices.push_back((vertices[i].cast<double>() + d[i] * (thickness[i] * k / settings.layers)).cast<Real>());
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

}  // namespace

ExtrudedWall extrudeWall(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                         const std::vector<double>& thickness, const ExtrusionSettings& settings) {
  if (thickness.size() != vertices.size())
    throw std::invalid_argument("extrudeWall: " + std::to_string(thickness.size()) + " thicknesses for " +
                                std::to_string(vertices.size()) + " vertices");
  if (settings.layers < 1) throw std::invalid_argument("extrudeWall: layers must be >= 1");
  ExtrudedWall wall;
  wall.surfaceVertices = vertices.size();
  wall.thickness = thickness;
  wall.directions = smoothNormals(vertexNormals(vertices, triangles), triangles, settings.normalSmoothing);
  std::vector<bool> shrunk(vertices.size(), false);
  for (int round = 0;; ++round) {
    const std::vector<Index> bad = buildLayers(vertices, triangles, wall.thickness, wall.directions, settings, wall.mesh);
    if (bad.empty()) break;
    if (round == settings.maxShrinkRounds)
      throw std::runtime_error("extrudeWall: " + std::to_string(bad.size()) +
                               " surface vertices still have inverted or flat tets after shrinking the wall " +
                               std::to_string(round) + " times");
    for (Index v : bad) wall.thickness[v] *= settings.shrink, shrunk[v] = true;
  }
  wall.shrunkVertices = static_cast<int>(std::count(shrunk.begin(), shrunk.end(), true));
  const auto offset = static_cast<Index>(settings.layers * vertices.size());
  wall.innerSurface = triangles;
  for (const Triangle& f : triangles) wall.outerSurface.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
  return wall;
}

std::vector<double> thicknessToSurface(const std::vector<Vec3>& vertices, const std::vector<Vec3d>& directions,
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
      best = std::min(best, (closestPointOnTriangle(p, otherVertices[f[0]].cast<double>(), otherVertices[f[1]].cast<double>(),
                                                    otherVertices[f[2]].cast<double>()) - p).norm());
    t[i] = best;
  }
  return t;
}

}  // namespace hs::pbd
