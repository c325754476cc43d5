#pragma once
// A particle fluid's velocity read on a plane, as 4D-flow MRI and PIV read a cut: a regular
// grid of nodes on the plane, the velocity at each node an SPH Shepard average of the particles'
// (Shepard 1968; Monaghan 2005, "Smoothed particle hydrodynamics", sec. 2.2):
//   v(x) = sum_j v_j W(|x - x_j|, h) / sum_j W(|x - x_j|, h)
// with the poly6 kernel (sph_kernels.h). Dividing by the kernel sum makes a uniform flow exact
// however irregular the particles, and the average over a support radius smooths the particle
// noise of PBF. The out-of-plane vorticity of the in-plane velocity, by central differences,
// and the vortex cores found in it are in vortex_cores.h. Pure functions on plain data.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pbd/core/particles.h"

namespace hs::pbd {

using Vec3d = Eigen::Vector3d;

// Nodes (i, j), i < columns, j < rows, at origin + i spacing u + j spacing v. u and v are
// orthonormal; the plane's normal is n = u x v (the sense of positive vorticity).
struct PlaneGrid {
  Vec3d origin = Vec3d::Zero();
  Vec3d u = Vec3d::UnitX(), v = Vec3d::UnitY();
  double spacing = 0;  // m
  int columns = 0, rows = 0;
  [[nodiscard]] Vec3d normal() const { return u.cross(v); }
  [[nodiscard]] Vec3d node(double i, double j) const { return origin + i * spacing * u + j * spacing * v; }
  [[nodiscard]] std::size_t index(int i, int j) const { return std::size_t(j) * std::size_t(columns) + std::size_t(i); }
  [[nodiscard]] std::size_t size() const { return std::size_t(columns) * std::size_t(rows); }
};

// The in-plane velocity (m/s, components along u and v) at each node (PlaneGrid::index). A node
// is `filled` when the fluid covers enough of its kernel's support: sum_j V_j W >= minFill, with
// V_j the particle's rest volume (the sum is 1 deep inside fluid at rest density, about 1/2 on
// a flat wall or free surface, 0 where there is no fluid); elsewhere the velocity is 0.
struct PlaneField {
  PlaneGrid grid;
  std::vector<double> vu, vv;
  std::vector<double> fill;             // sum_j V_j W (dimensionless)
  std::vector<std::uint8_t> filled;     // 1 where fill >= minFill
  [[nodiscard]] bool isFilled(int i, int j) const {
    return i >= 0 && j >= 0 && i < grid.columns && j < grid.rows && filled[grid.index(i, j)] != 0;
  }
};

// What sampleOnPlane() reads: the particles [first, size) that are active, each of rest volume
// `particleVolume` (m^3), averaged with support radius `h` (m).
struct PlaneSampling {
  Index first = 0;
  double particleVolume = 0;
  double h = 0;
  double minFill = 0.3;
};

// One pass over the particles: those within h of the plane add to the nodes within h of them
// (O(N) plus the slab's particles times (2h / spacing)^2). Sums in particle order: the same
// result on any thread count.
PlaneField sampleOnPlane(const PlaneGrid& grid, const Particles& particles, const PlaneSampling& sampling);

}  // namespace hs::pbd
