#pragma once
// Test surfaces: a sphere from a subdivided octahedron (outward triangles), optionally cut to
// the cap z < zCut (an open cup with one boundary loop).
#include <cmath>
#include <map>

#include "pbd/core/tet_mesh.h"

namespace hs::pbd::testing {

struct TestSurface {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;
};

inline TestSurface makeSphere(int subdivisions, double radius) {
  std::vector<Eigen::Vector3d> p = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<Triangle> t = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                             {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<Index, Index>, Index> mid;
    auto midpoint = [&](Index a, Index b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      if (auto it = mid.find(key); it != mid.end()) return it->second;
      p.push_back((p[a] + p[b]).normalized());
      return mid[key] = static_cast<Index>(p.size() - 1);
    };
    std::vector<Triangle> next;
    for (const Triangle& f : t) {
      const Index ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      next.insert(next.end(), {Triangle{f[0], ab, ca}, Triangle{ab, f[1], bc}, Triangle{ca, bc, f[2]},
                               Triangle{ab, bc, ca}});
    }
    t = std::move(next);
  }
  TestSurface out;
  for (const auto& q : p) out.vertices.push_back((q * radius).cast<Real>());
  out.triangles = t;
  return out;
}

// The triangles of `sphere` whose centroid has z < zCut, with unused vertices kept (they are
// harmless to the functions under test only when not referenced; callers compact if needed).
inline std::vector<Triangle> cupTriangles(const TestSurface& sphere, double zCut) {
  std::vector<Triangle> kept;
  for (const Triangle& f : sphere.triangles) {
    const double z =
        (sphere.vertices[f[0]].z() + sphere.vertices[f[1]].z() + sphere.vertices[f[2]].z()) / 3.0;
    if (z < zCut) kept.push_back(f);
  }
  return kept;
}

}  // namespace hs::pbd::testing
