#pragma once
// Inside or outside a closed triangle surface, by the parity of its crossings of a vertical ray
// (the Jordan curve theorem in 3D): a point is inside when the surface crosses the ray from it
// toward +y an odd number of times. Knows no hearts.
//
// Each triangle is tested in its projection on the xz plane with the rasteriser's fill rule
// (a point on an edge shared by two triangles that lie on its two sides belongs to exactly one
// of them, Pineda 1988), so a ray through an edge or a corner is counted once, not twice or
// never. Triangles seen edge-on (zero projected area) never count: a ray along one meets its
// neighbours instead. The answer for a point exactly on the surface is either.
#include <cstdint>
#include <vector>

#include "pbd/core/tet_mesh.h"
#include "pbd/core/types.h"

namespace hs::pbd {

// The crossing rule for one triangle: does it cross the ray from p toward +y?
bool crossesUpwardRay(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p);

// Brute force over every triangle: the reference for SurfaceInside.
bool insideClosedSurface(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles, const Vec3& p);

// The same test over the triangles whose xz footprint meets the point's column: a grid of square
// columns (`columnSize` wide) over the surface's xz box, built once for a fixed surface. Before
// that, a grid of cubes of the same size over the surface's box answers for the cubes that no
// triangle's box touches: no surface crosses them, so all their points share the answer of
// their centre, found once. Exactly the brute force's answer either way.
class SurfaceInside {
 public:
  SurfaceInside(std::vector<Vec3> vertices, std::vector<Triangle> triangles, Real columnSize);
  [[nodiscard]] bool contains(const Vec3& p) const;
  [[nodiscard]] const std::vector<Vec3>& vertices() const { return m_vertices; }
  [[nodiscard]] const std::vector<Triangle>& triangles() const { return m_triangles; }

 private:
  [[nodiscard]] bool columnOf(Real x, Real z, std::size_t& column) const;
  // The parity over the triangles of p's column.
  [[nodiscard]] bool columnTest(const Vec3& p, std::size_t column) const;

  enum class CubeState : std::uint8_t { Outside, Inside, Crossed };

  std::vector<Vec3> m_vertices;
  std::vector<Triangle> m_triangles;
  Real m_minX = 0, m_minZ = 0, m_columnSize = 1;
  std::size_t m_columnsX = 0, m_columnsZ = 0;
  std::vector<Index> m_columnStart;  // CSR: the triangles of column k are m_items[start[k], start[k+1])
  std::vector<Index> m_items;
  Real m_minY = 0;
  std::size_t m_cubesY = 0;
  std::vector<CubeState> m_cubes;  // (column, layer) -> column * m_cubesY + layer
};

}  // namespace hs::pbd
