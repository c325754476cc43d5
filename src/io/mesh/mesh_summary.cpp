#include "io/mesh/mesh_summary.h"

#include <algorithm>
#include <cmath>

#include "mesh/surface_mesh.h"

namespace hs::io {
namespace {

using Vec3d = Eigen::Vector3d;

Vec3d at(const std::vector<pbd::Vec3>& vertices, pbd::Index i) { return vertices[i].cast<double>(); }

// V = (1/6) sum (a x b) . c over oriented triangles (divergence theorem).
double signedVolume(const std::vector<pbd::Vec3>& v, const std::vector<pbd::Triangle>& triangles) {
  double volume = 0;
  for (const pbd::Triangle& t : triangles) volume += at(v, t[0]).cross(at(v, t[1])).dot(at(v, t[2]));
  return volume / 6.0;
}

}  // namespace

std::vector<BoundaryLoop> boundaryLoops(const std::vector<pbd::Vec3>& vertices,
                                        const std::vector<pbd::Triangle>& triangles) {
  std::vector<BoundaryLoop> loops;
  for (const std::vector<pbd::Index>& chain : pbd::boundaryLoopVertices(triangles)) {
    BoundaryLoop loop;
    loop.vertices = chain.size();
    Vec3d area = Vec3d::Zero();
    for (std::size_t i = 0; i < chain.size(); ++i) {
      const Vec3d a = at(vertices, chain[i]), b = at(vertices, chain[(i + 1) % chain.size()]);
      loop.perimeter += (b - a).norm();
      area += a.cross(b);
    }
    loop.capArea = 0.5 * area.norm();
    loops.push_back(loop);
  }
  return loops;
}

MeshSummary summarizeMesh(const ImportedMesh& mesh) {
  MeshSummary s;
  s.vertices = mesh.vertices.size();
  s.triangles = mesh.triangles.size();
  s.tets = mesh.tets.size();
  for (int k = 0; k < 3; ++k) {
    s.min[k] = mesh.vertices.empty() ? 0 : HUGE_VAL;
    s.max[k] = mesh.vertices.empty() ? 0 : -HUGE_VAL;
  }
  for (const pbd::Vec3& p : mesh.vertices)
    for (int k = 0; k < 3; ++k) {
      s.min[k] = std::min(s.min[k], double(p[k]));
      s.max[k] = std::max(s.max[k], double(p[k]));
    }
  for (int k = 0; k < 3; ++k) s.size = std::max(s.size, s.max[k] - s.min[k]);
  // A heart is 5-20 cm long: its largest extent (with room for a slice or a whole heart) says
  // the unit: 0.02-0.5 in metres, 2-30 in centimetres, 30-500 in millimetres; else no guess.
  if (s.size >= 0.02 && s.size < 0.5) s.unitGuess = "m", s.millilitresPerCubicUnit = 1e6;
  else if (s.size >= 2 && s.size < 30) s.unitGuess = "cm", s.millilitresPerCubicUnit = 1;
  else if (s.size >= 30 && s.size < 500) s.unitGuess = "mm", s.millilitresPerCubicUnit = 1e-3;
  for (const SurfaceMarker& m : mesh.markers) {
    std::string label = m.number >= 0 || m.name.empty() ? std::to_string(m.number) : std::string();
    if (!m.name.empty()) label += (label.empty() ? "" : " ") + m.name;
    s.markers.emplace_back(label, m.triangles.size());
  }
  if (!mesh.tets.empty()) {
    for (const pbd::Tet& t : mesh.tets) {
      const Vec3d x0 = at(mesh.vertices, t[0]);
      s.tetVolume += (at(mesh.vertices, t[1]) - x0).cross(at(mesh.vertices, t[2]) - x0).dot(at(mesh.vertices, t[3]) - x0) / 6.0;
    }
    s.quality = pbd::measureQuality(pbd::TetMesh{mesh.vertices, mesh.tets});
    return s;
  }
  const pbd::SurfaceCheck check = pbd::checkSurface(mesh.triangles);
  s.closed = check.boundaryEdges == 0;
  s.nonManifoldEdges = check.nonManifoldEdges;
  if (s.closed) {
    s.enclosedVolume = std::abs(signedVolume(mesh.vertices, mesh.triangles));
    return s;
  }
  s.loops = boundaryLoops(mesh.vertices, mesh.triangles);
  // Each loop closed by a fan from its centroid c: triangles (c, b, a) traverse the boundary
  // edge a -> b the other way, as a neighbouring triangle of a closed surface would.
  std::vector<pbd::Vec3> vertices = mesh.vertices;
  std::vector<pbd::Triangle> capped = mesh.triangles;
  for (const std::vector<pbd::Index>& chain : pbd::boundaryLoopVertices(mesh.triangles)) {
    Vec3d centroid = Vec3d::Zero();
    for (pbd::Index i : chain) centroid += at(mesh.vertices, i);
    vertices.push_back((centroid / double(chain.size())).cast<pbd::Real>());
    const auto c = static_cast<pbd::Index>(vertices.size() - 1);
    for (std::size_t i = 0; i < chain.size(); ++i) capped.push_back({c, chain[(i + 1) % chain.size()], chain[i]});
  }
  s.cappedVolume = std::abs(signedVolume(vertices, capped));
  return s;
}

}  // namespace hs::io
