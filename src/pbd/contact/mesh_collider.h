#pragma once
// Particles against a static triangle mesh (container walls, vessel walls): a fluid particle
// of radius r that moved from `previous` to `predicted` is put back at distance >= r from every
// triangle, and never passes through one.
//
// Method, per particle and solver iteration:
//  1. Tunnelling: the segment previous -> predicted is tested against the triangles (plane
//     heights, then barycentric coordinates of the crossing point); the particle stops at the
//     first crossing (Ericson 2005, "Real-Time Collision Detection", 5.3.6 in spirit).
//  2. Contacts: the most violated triangle (closest point, Ericson 5.1.5) pushes the particle
//     out to distance r; repeated until none is violated (a concave corner needs one push per
//     face). Choosing the deepest contact, ties to the lowest triangle index, makes the result
//     independent of the order in which candidates are visited, so the grid and the brute force
//     give bitwise the same answer.
// Triangles are two-sided: which side a particle belongs to is the side of the triangle's plane
// where it was after step 1, or where `previous` was if that point is on the plane (rounding),
// or the normal side if `previous` is on it too. After step 1 the path crossed no triangle, so
// this is the side the particle came from; unlike the side of `previous` alone it is also right
// for a particle that went around a free edge (a valve leaflet's tip) during the step.
//
// Acceleration: a uniform grid over the triangles (mesh_collider_grid.h). This file's source
// holds the collision response; the grid offers it candidates.
#include <vector>

#include "pbd/contact/mesh_collider_grid.h"
#include "pbd/core/tet_mesh.h"
#include "pbd/core/types.h"

namespace hs::pbd {

namespace detail {

// A non-degenerate triangle with the data the queries need, precomputed.
struct ColliderTriangle {
  Vec3 a, b, c;
  Vec3 normal;        // unit N / |N|, N = (b - a) x (c - a)
  Vec3 baryNormal;    // N / |N|^2: barycentric of a = baryNormal . ((c - b) x (p - b)), cyclic
  Vec3 boxLo, boxHi;  // bounding box widened by `slack`
  Real slack;         // rounding and barycentric tolerance, as a length
  Index id;           // index in the caller's triangle array
};

struct ColliderGeometry {
  std::vector<ColliderTriangle> triangles;  // in input order, degenerate ones left out
  Real coordScale = 0;                      // largest |coordinate| of a kept vertex: sets rounding tolerances
};

// Validates the input (std::invalid_argument naming the triangle or vertex) and keeps the
// triangles with non-zero area.
ColliderGeometry buildColliderGeometry(const std::vector<Vec3>& vertices,
                                       const std::vector<Triangle>& triangles);

}  // namespace detail

// The point of triangle abc closest to p.
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

class StaticMeshCollider {
 public:
  // Triangles index `vertices`. Throws std::invalid_argument (one line naming the triangle or
  // vertex and what was expected) for an index out of range, a non-finite vertex or a cellSize
  // that is not finite and > 0. Zero-area triangles are skipped. cellSize: grid cell edge,
  // about 2-4 particle radii; it is enlarged if the mesh would need more than
  // max(65536, 64 * triangles) cells (see cellSize()).
  StaticMeshCollider(std::vector<Vec3> vertices, std::vector<Triangle> triangles, Real cellSize);

  // Corrected predicted position: at distance >= radius (up to rounding, about 1e-6 of the
  // coordinates in float) from every triangle, on the side each triangle was approached from;
  // stopped before any triangle the segment previous -> predicted crosses. `previous` should be
  // valid (at least `radius` from the surface, or on its side). Non-finite input is returned
  // unchanged. Const, thread-safe, no heap allocation.
  Vec3 collide(const Vec3& previous, const Vec3& predicted, Real radius) const;

  // Triangles that may touch the box [lo, hi]: their widened bounding box overlaps it and their
  // plane passes through the overlap (within the same tolerance). For particles of radius r pass
  // the particle's box widened by r. Each triangle once, sorted by index; `out` is overwritten.
  void candidateTriangles(const Vec3& lo, const Vec3& hi, std::vector<Index>& out) const;
  // The same predicate for one triangle (false for a skipped, degenerate one): the brute-force
  // reference for candidateTriangles.
  bool triangleMayTouchBox(Index triangle, const Vec3& lo, const Vec3& hi) const;

  const std::vector<Vec3>& vertices() const { return m_vertices; }
  const std::vector<Triangle>& triangles() const { return m_triangles; }
  std::size_t activeTriangleCount() const { return m_geometry.triangles.size(); }  // non-degenerate
  Real cellSize() const { return Real(m_grid.cellSize()); }  // as used (>= the requested one)
  std::size_t cellCount() const { return m_grid.cellCount(); }
  std::size_t entryCount() const { return m_grid.entryCount(); }  // (cell, triangle) pairs

 private:
  std::vector<Vec3> m_vertices;
  std::vector<Triangle> m_triangles;
  detail::ColliderGeometry m_geometry;
  std::vector<Index> m_slotOf;  // input triangle -> position in m_geometry.triangles, or ~0
  detail::TriangleGrid m_grid;
};

// The same computation as StaticMeshCollider::collide over all triangles, without a grid
// (the reference for tests; validates and preprocesses the mesh on every call).
Vec3 collideBruteForce(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                       const Vec3& previous, const Vec3& predicted, Real radius);

}  // namespace hs::pbd
