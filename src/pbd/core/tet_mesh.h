#pragma once
// A tetrahedral mesh as plain arrays, and the generic geometry every soft body needs:
// signed volumes, the oriented boundary surface, unique edges, closedness and quality.
#include <array>
#include <string>
#include <vector>

#include "pbd/core/types.h"

namespace hs::pbd {

using Tet = std::array<Index, 4>;
using Triangle = std::array<Index, 3>;
using Edge = std::array<Index, 2>;

struct TetMesh {
  std::vector<Vec3> vertices;
  std::vector<Tet> tets;  // positively oriented: signedVolume(...) > 0
};

// V = (1/6) (x1 - x0) x (x2 - x0) . (x3 - x0)  (thesis eq. 4.1 without the rest term)
Real signedTetVolume(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3);

// Faces that belong to exactly one tet, oriented with normals pointing out of the solid.
// Sorted deterministically (by their vertex ids).
std::vector<Triangle> boundaryFaces(const std::vector<Tet>& tets);

// Every edge of every tet once, as (smaller id, larger id), sorted.
std::vector<Edge> uniqueEdges(const std::vector<Tet>& tets);

// A triangle surface is closed and consistently oriented when every directed edge (a->b)
// appears exactly once and its reverse (b->a) appears exactly once too.
struct SurfaceCheck {
  bool closed = false;              // every edge shared by exactly two faces
  bool consistentlyOriented = false;  // the two faces traverse it in opposite directions
  std::size_t boundaryEdges = 0;    // edges used by only one face
  std::size_t nonManifoldEdges = 0;  // edges used by more than two faces
};
SurfaceCheck checkSurface(const std::vector<Triangle>& faces);

// Enclosed volume of a closed oriented surface, by the divergence theorem:
// V = (1/6) sum_f (a x b) . c over triangles (a, b, c).
Real enclosedVolume(const std::vector<Vec3>& vertices, const std::vector<Triangle>& faces);

struct MeshQuality {
  Real minDihedralDeg = 0;  // smallest dihedral angle over all tets (degrees)
  Real maxDihedralDeg = 0;  // largest dihedral angle over all tets (degrees)
  // Aspect ratio = longest edge / (2 sqrt(6) * inradius): 1 for a regular tet, larger is worse.
  Real maxAspectRatio = 0;
  Real meanAspectRatio = 0;
  Real minVolume = 0;  // smallest signed tet volume
  std::size_t invertedTets = 0;  // tets with signed volume <= 0
};
MeshQuality measureQuality(const TetMesh& mesh);

}  // namespace hs::pbd
