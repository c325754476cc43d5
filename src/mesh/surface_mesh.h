#pragma once
// Triangle surfaces as plain arrays: the generic geometry a surface-to-wall mesher needs
// (boundary loops, vertex normals and their smoothing, sub-surfaces, closest points and rays).
// Knows no hearts; the cardiac layer (cardiac/patient/patient_wall.h) names the loops.
#include <array>
#include <optional>
#include <vector>

#include "pbd/core/tet_mesh.h"

namespace hs::pbd {

using Vec3d = Eigen::Vector3d;

// Boundary loops: edges used by exactly one triangle, chained in the direction their triangle
// traverses them (so a loop of an outward-oriented surface runs clockwise seen from outside
// the hole). Loops in the order of their smallest directed edge; each starts at the tail of
// that edge. A chain that cannot close (orientation flips, non-manifold vertex) is returned as
// the open chain it is.
std::vector<std::vector<Index>> boundaryLoopVertices(const std::vector<Triangle>& triangles);

// Area-weighted vertex normals, n_i = normalize(sum_f (b - a) x (c - a)) over the triangles at
// i (twice the area times the unit normal); zero for a vertex without triangles.
std::vector<Vec3d> vertexNormals(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles);

// `iterations` Jacobi sweeps of n_i <- normalize(n_i + sum_(j ~ i) n_j) over the edge
// neighbours: normals that turn slowly, so that offsets along them do not cross where the
// surface is curved more than the offset (Jacobi: independent of the vertex order).
std::vector<Vec3d> smoothNormals(std::vector<Vec3d> normals, const std::vector<Triangle>& triangles,
                                 int iterations);
// The same over vertex neighbours already listed (vertexNeighbours), for a surface smoothed
// again every step.
std::vector<Vec3d> smoothNormals(std::vector<Vec3d> normals, const std::vector<std::vector<Index>>& neighbours,
                                 int iterations);

// The triangles `subset` of a surface with only the vertices they use, renumbered in the order
// of first use; `originalVertex[i]` is the old id of new vertex i.
struct SubSurface {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;
  std::vector<Index> originalVertex;
};
SubSurface extractSubSurface(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                             const std::vector<Index>& subset);

// Vertex neighbours through edges, each list sorted.
std::vector<std::vector<Index>> vertexNeighbours(std::size_t vertexCount,
                                                 const std::vector<Triangle>& triangles);

// The point of triangle abc closest to p (Ericson 2005, Real-Time Collision Detection, 5.1.5).
Vec3d closestPointOnTriangle(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c);

// The closest point of a fixed triangle surface to query points. Each triangle carries a
// bounding sphere (centroid, farthest corner); a triangle whose sphere lies farther than the best
// distance found so far cannot hold a closer point and is skipped. The bound is exact, so the
// answer is the brute-force one (tests/mesh/test_wall_extrusion.cpp checks it); the pruning
// only saves time. O(triangles) per query in the worst case.
class ClosestPointQuery {
 public:
  ClosestPointQuery(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles);
  Vec3d closestPoint(const Vec3d& p) const;

 private:
  std::vector<std::array<Vec3d, 3>> m_corners;
  std::vector<Vec3d> m_centre;
  std::vector<double> m_radius;
};

// Distance t > 0 along origin + t direction to the first triangle of the surface it meets
// (Moeller & Trumbore 1997), either side; nullopt when it meets none. Brute force: O(triangles).
std::optional<double> firstRayHit(const Vec3d& origin, const Vec3d& direction,
                                  const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles);

// Signed volume (1/6) sum (a x b) . c with every boundary loop closed by a fan from its
// centroid: positive when an open cup's triangles face out of the cavity it holds.
double cappedSignedVolume(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles);

// Number of connected pieces (triangles joined through shared vertices; unused vertices are
// not counted).
std::size_t connectedPieces(std::size_t vertexCount, const std::vector<Triangle>& triangles);

// The largest (by area) edge-connected set of triangles whose unit normals lie within
// `angleDeg` of its first triangle's and whose vertices lie within `planeTolerance` of its
// plane: a flat face of the surface (a truncated ventricle's base). Triangle ids, sorted; its
// area in `area`.
std::vector<Index> largestFlatRegion(const std::vector<Vec3>& vertices,
                                     const std::vector<Triangle>& triangles, double angleDeg,
                                     double planeTolerance, double* area = nullptr);

}  // namespace hs::pbd
