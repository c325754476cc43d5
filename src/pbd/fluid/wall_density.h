#pragma once
// The density a wall lends the fluid next to it (Harada et al. 2007, "wall weight functions";
// Koschier & Bender 2017, "density maps", in their planar limit). PBF sums the density over
// fluid neighbours only, so a particle at a wall misses the half of its support that lies
// beyond it: it reads under-dense, the unilateral constraint leaves it alone, and blood packs
// tighter along walls than inside (a small cavity, mostly wall layer, then holds more particles
// per volume than a large one). Treating the space beyond the wall as fluid at rest density
// gives the missing part. For a plane at distance d from particle i, with m = rho0 s^3 (one
// particle per lattice cell):
//   rho_wall(d)    = rho0 D(d),    D(d) = integral over the half-space beyond of W_poly6
//                                       = int_d^h W(r) 2 pi r (r - d) dr
//   grad_i C_wall  = -G(d) n,      G(d) = int_d^h |W_spiky'(r)| pi (r^2 - d^2) dr
// (n the unit normal from the wall toward the particle; 2 pi r (r - d) is the area of the sphere
// of radius r beyond the plane, pi (r^2 - d^2) its projection on n). Both vanish at d >= h.
#include <array>
#include <span>
#include <vector>

#include "pbd/contact/mesh_collider.h"
#include "pbd/core/tet_mesh.h"
#include "pbd/core/types.h"
#include "pbd/fluid/sph_kernels.h"
#include "pbd/grid/cell_grid.h"

namespace hs::pbd {

// D(d) and G(d) tabulated on [0, h]; linear interpolation between samples.
class WallDensityTable {
 public:
  explicit WallDensityTable(const SphKernels& kernels, int samples = 256);
  // Share of a full support that lies beyond a wall at distance d (D above); 1/2 at d = 0.
  [[nodiscard]] Real density(Real d) const { return lookup(m_density, d); }
  // |grad_i C| of the wall's share (G above), 1/m.
  [[nodiscard]] Real gradient(Real d) const { return lookup(m_gradient, d); }
  [[nodiscard]] Real supportRadius() const { return m_h; }

 private:
  [[nodiscard]] Real lookup(const std::vector<Real>& table, Real d) const;
  Real m_h;
  Real m_step;
  std::vector<Real> m_density, m_gradient;
};

// The nearest wall within a particle's support: distance and unit normal toward the particle;
// normal zero where no wall is within `reach`.
struct WallProximity {
  Real distance = 0;
  Vec3 normal = Vec3::Zero();
};

// The triangles binned for findNearestWalls: a uniform grid (cells of edge `reach`) in
// which each triangle is listed in every cell its box grown by `reach` touches, so that a point's
// own cell lists every triangle within reach of it. Binned again by each update() (a moving wall),
// into buffers kept from the last one.
class WallTriangleGrid {
 public:
  void update(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles, Real reach, int threads);
  [[nodiscard]] bool valid() const { return m_valid; }
  [[nodiscard]] Real reach() const { return m_reach; }
  [[nodiscard]] const CellIndexing& cells() const { return m_cells; }
  [[nodiscard]] const CellGrid& grid() const { return m_grid; }
  [[nodiscard]] const std::vector<std::array<Vec3, 2>>& boxes() const { return m_boxes; }
  // Per grid entry (in the grid's entry order), coordinate `axis` of its triangle's box corners:
  // a cell's candidates' boxes as contiguous arrays, read by a loop the compiler vectorises.
  [[nodiscard]] const Real* entryLo(int axis) const { return m_entryLo[std::size_t(axis)].data(); }
  [[nodiscard]] const Real* entryHi(int axis) const { return m_entryHi[std::size_t(axis)].data(); }
  // Per grid entry, its triangle's plane n . x = c (component 0-2 of n, then c; n of unit length,
  // zero for a degenerate triangle). Every entry array has kWallBoundsPadding zeros after its
  // last entry.
  [[nodiscard]] const Real* entryPlane(int component) const { return m_entryPlane[std::size_t(component)].data(); }
  // The slack of every bound: |n . p - c| - slack and the box's distance less it bound the
  // distance from p to a triangle whatever the rounding (wall_bounds.h; boundSlack in the .cpp).
  [[nodiscard]] Real slack() const { return m_slack; }

 private:
  CellIndexing m_cells;
  CellGrid m_grid;
  std::vector<std::array<Vec3, 2>> m_boxes;  // each triangle's box
  std::array<std::vector<Real>, 3> m_entryLo, m_entryHi;
  std::vector<std::array<Real, 4>> m_planes;  // each triangle's n and c
  std::array<std::vector<Real>, 4> m_entryPlane;
  Real m_slack = 0;
  Real m_reach = 0;
  bool m_valid = false;
};

// For each point, the closest point on the triangles within the grid's reach (closest point on
// each triangle near it, Ericson 5.1.5), from the triangles listed in the point's cell. A
// triangle is no nearer than its box or its plane: the triangle with the nearest such bound is
// tried first, and then only those whose bound does not exceed the best distance so far (inside a
// curved cavity the planes of the nearest triangle's neighbours pass farther than it).
// The result is the minimum over all triangles (ties to the lowest id) whatever the grid.
void findNearestWalls(const WallTriangleGrid& grid, const std::vector<Vec3>& vertices,
                      const std::vector<Triangle>& triangles, std::span<const Vec3> points,
                      std::vector<WallProximity>& out, int threads);
// The same with a grid of its own, made for this call.
void findNearestWalls(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                      std::span<const Vec3> points, Real reach, std::vector<WallProximity>& out, int threads);

// The same over every triangle, without a grid: the reference for tests.
WallProximity nearestWallBruteForce(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                                    const Vec3& point, Real reach);

// The wall's share of particle i's density constraint while its position moves from `start` (where
// `proximity` was found) to p: the plane is kept, so d = d0 + n . (p - start).
struct WallDensityInput {
  const WallDensityTable* table = nullptr;
  const std::vector<WallProximity>* proximity = nullptr;  // per position index
  const std::vector<Vec3>* start = nullptr;               // per position index
};

// Distance of position p (index i) from its wall, or a negative number where it has none.
inline Real wallDistance(const WallDensityInput& walls, Index i, const Vec3& p) {
  const WallProximity& w = (*walls.proximity)[i];
  if (w.normal.squaredNorm() == Real(0)) return Real(-1);
  return std::max(Real(0), w.distance + w.normal.dot(p - (*walls.start)[i]));
}

}  // namespace hs::pbd
