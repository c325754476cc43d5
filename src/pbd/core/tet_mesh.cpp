#include "pbd/core/tet_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace hs::pbd {

namespace {

using Vec3d = Eigen::Vector3d;

Vec3d toDouble(const Vec3& v) { return v.cast<double>(); }

// The four faces of a positive tet (x0, x1, x2, x3), each wound so that its normal points
// away from the opposite vertex: (x1 - x0) x (x2 - x0) points toward x3, hence (0, 2, 1).
constexpr std::array<std::array<int, 3>, 4> kOutwardFaces = {{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}};

// Rotates a triangle so its smallest id comes first; the cyclic order (orientation) is kept.
Triangle canonicalRotation(const Triangle& f) {
  if (f[1] < f[0] && f[1] < f[2]) return {f[1], f[2], f[0]};
  if (f[2] < f[0] && f[2] < f[1]) return {f[2], f[0], f[1]};
  return f;
}

Triangle sortedIds(Triangle f) {
  std::sort(f.begin(), f.end());
  return f;
}

}  // namespace

Real signedTetVolume(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3) {
  return (x1 - x0).cross(x2 - x0).dot(x3 - x0) / Real(6);
}

std::vector<Triangle> boundaryFaces(const std::vector<Tet>& tets) {
  // Pair every oriented face with its sorted key; a key seen once is on the boundary.
  std::vector<std::pair<Triangle, Triangle>> faces;
  faces.reserve(tets.size() * 4);
  for (const Tet& t : tets) {
    for (const auto& f : kOutwardFaces) {
      const Triangle face = {t[f[0]], t[f[1]], t[f[2]]};
      faces.emplace_back(sortedIds(face), face);
    }
  }
  std::sort(faces.begin(), faces.end());
  std::vector<Triangle> result;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].first == faces[i].first) ++j;
    if (j - i == 1) result.push_back(canonicalRotation(faces[i].second));
    i = j;
  }
  std::sort(result.begin(), result.end());
  return result;
}

std::vector<Edge> uniqueEdges(const std::vector<Tet>& tets) {
  std::vector<Edge> edges;
  edges.reserve(tets.size() * 6);
  for (const Tet& t : tets) {
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) edges.push_back({std::min(t[i], t[j]), std::max(t[i], t[j])});
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

SurfaceCheck checkSurface(const std::vector<Triangle>& faces) {
  // Directed edges sorted by their undirected key, so all uses of one edge are adjacent.
  struct Use {
    Edge key;
    bool forward;  // traversed from the smaller id to the larger one
    bool operator<(const Use& o) const { return key != o.key ? key < o.key : forward < o.forward; }
  };
  std::vector<Use> uses;
  uses.reserve(faces.size() * 3);
  for (const Triangle& f : faces) {
    for (int k = 0; k < 3; ++k) {
      const Index a = f[k];
      const Index b = f[(k + 1) % 3];
      if (a == b) continue;
      uses.push_back({{std::min(a, b), std::max(a, b)}, a < b});
    }
  }
  std::sort(uses.begin(), uses.end());
  SurfaceCheck check;
  check.consistentlyOriented = true;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i + 1;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    const std::size_t count = j - i;
    if (count == 1) ++check.boundaryEdges;
    if (count > 2) ++check.nonManifoldEdges;
    // Two uses must run in opposite directions; more than two cannot be consistent.
    if (count > 2 || (count == 2 && uses[i].forward == uses[i + 1].forward))
      check.consistentlyOriented = false;
    i = j;
  }
  check.closed = check.boundaryEdges == 0 && check.nonManifoldEdges == 0;
  return check;
}

Real enclosedVolume(const std::vector<Vec3>& vertices, const std::vector<Triangle>& faces) {
  double sum = 0;
  for (const Triangle& f : faces) {
    sum += toDouble(vertices[f[0]]).cross(toDouble(vertices[f[1]])).dot(toDouble(vertices[f[2]]));
  }
  return Real(sum / 6.0);
}

MeshQuality measureQuality(const TetMesh& mesh) {
  MeshQuality q;
  if (mesh.tets.empty()) return q;
  double minDihedral = std::numeric_limits<double>::max();
  double maxDihedral = 0;
  double maxAspect = 0;
  double sumAspect = 0;
  double minVolume = std::numeric_limits<double>::max();
  for (const Tet& t : mesh.tets) {
    std::array<Vec3d, 4> x;
    for (int i = 0; i < 4; ++i) x[i] = toDouble(mesh.vertices[t[i]]);
    const double volume = (x[1] - x[0]).cross(x[2] - x[0]).dot(x[3] - x[0]) / 6.0;
    minVolume = std::min(minVolume, volume);
    if (volume <= 0) ++q.invertedTets;
    // Area vectors of the faces opposite each vertex (outward for a positive tet).
    std::array<Vec3d, 4> areaVec;
    double areaSum = 0;
    // Face opposite vertex k, wound outward for a positive tet.
    areaVec[0] = 0.5 * (x[2] - x[1]).cross(x[3] - x[1]);
    areaVec[1] = 0.5 * (x[3] - x[0]).cross(x[2] - x[0]);
    areaVec[2] = 0.5 * (x[1] - x[0]).cross(x[3] - x[0]);
    areaVec[3] = 0.5 * (x[2] - x[0]).cross(x[1] - x[0]);
    double longestEdge = 0;
    for (int i = 0; i < 4; ++i) {
      areaSum += areaVec[i].norm();
      for (int j = i + 1; j < 4; ++j) {
        longestEdge = std::max(longestEdge, (x[i] - x[j]).norm());
        // The dihedral angle at the edge shared by the faces opposite i and j is
        // pi minus the angle between their outward normals.
        const double c = areaVec[i].normalized().dot(areaVec[j].normalized());
        const double angle = std::numbers::pi - std::acos(std::clamp(c, -1.0, 1.0));
        minDihedral = std::min(minDihedral, angle);
        maxDihedral = std::max(maxDihedral, angle);
      }
    }
    // Inradius r = 3 V / (sum of face areas); a regular tet has longest edge = 2 sqrt(6) r.
    const double inradius = 3.0 * std::abs(volume) / std::max(areaSum, std::numeric_limits<double>::min());
    const double aspect = inradius > 0 ? longestEdge / (2.0 * std::sqrt(6.0) * inradius)
                                       : std::numeric_limits<double>::infinity();
    maxAspect = std::max(maxAspect, aspect);
    sumAspect += aspect;
  }
  constexpr double kDeg = 180.0 / std::numbers::pi;
  q.minDihedralDeg = Real(minDihedral * kDeg);
  q.maxDihedralDeg = Real(maxDihedral * kDeg);
  q.maxAspectRatio = Real(maxAspect);
  q.meanAspectRatio = Real(sumAspect / double(mesh.tets.size()));
  q.minVolume = Real(minVolume);
  return q;
}

}  // namespace hs::pbd
