#pragma once
// One Position Based Fluids step for the Fluid-kind particles of a Particles set (Macklin &
// Mueller 2013, "Position Based Fluids", Algorithm 1; thesis section 4.2):
//   v <- v + dt g,  p <- x + dt v                     (Alg. 1 lines 1-4, solver.h phases)
//   find neighbours of p once per step                 (Alg. 1 lines 5-7, neighbour_grid.h)
//   iterations times:                                  (Alg. 1 lines 8-19)
//     rho_i, lambda_i (PBF eq. 2, 11), dp_i (eq. 12)   (fluid.h, Jacobi)
//     p_i <- p_i + dp_i, then the wall planes          (collision response, thesis eq. 4.5)
//   v <- (p - x)/dt, x <- p                            (Alg. 1 lines 20-21, solver.h)
//   wall contacts, vorticity confinement, viscosity   (Alg. 1 line 22; PBF eq. 15-17)
//
// The density solve works on compact arrays holding only the fluid particles, in the cell
// order of the neighbour grid (slot k is particle slotParticles()[k]): the grid sorts the
// particles by cell every step, so neighbours are close in memory and each CSR list is
// already in increasing slot order. Tissue particles never enter the density estimate. All
// loops are per-particle gathers, so the result is bitwise identical for any thread count.
// After warm-up a step allocates nothing: every buffer keeps its capacity.
//
// Mixed sets: step() runs the solver.h stages over the whole set, so tissue particles in the
// same set are integrated too (gravity, prediction, velocity update, no constraints). A world
// with more bodies lists its own step (cardiac/heart_simulation.cpp) from the stages below:
// beginDensitySolve, iterations() x iterateDensity (with its own contacts on
// workingPositions() after each), endDensitySolve, and postProcessVelocities after the
// velocity update. Parked particles (Particles::state) take no part; pinned ones do not move.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "pbd/contact/mesh_collider.h"
#include "pbd/core/constraints.h"
#include "pbd/core/particles.h"
#include "pbd/core/solver.h"
#include "pbd/core/step_context.h"
#include "pbd/fluid/fluid.h"
#include "pbd/fluid/fluid_stats.h"
#include "pbd/fluid/sph_kernels.h"
#include "pbd/grid/neighbour_grid.h"

namespace hs::pbd {

struct FluidStepSettings {
  SolverSettings base;          // gravityScale and damping for step(); base.iterations unused
  int iterations = 4;           // density solver iterations per step (PBF Algorithm 1 line 8)
  FluidSettings fluid;          // rho0, m, h, eps, s_corr, XSPH c
  Real particleRadius = Real(0.08);  // m, distance kept from the walls (thesis: 0.08 m)
  std::vector<Plane> walls;     // normals point into the fluid's allowed half-space
  // Static triangle-mesh walls (a container, a vessel): after the planes, every particle is
  // kept particleRadius from the mesh on the side it came from (mesh_collider.h). Shared,
  // read-only: copies of the settings use the same mesh.
  std::shared_ptr<const StaticMeshCollider> mesh;
};

class FluidSolver {
 public:
  explicit FluidSolver(FluidStepSettings settings = {});

  const FluidStepSettings& settings() const { return m_settings; }
  void setSettings(const FluidStepSettings& settings);

  // One whole step (see the header comment).
  void step(Particles& particles, const StepContext& context);

  // The stages, for a world that lists its own step. beginDensitySolve gathers the fluid's
  // predicted positions into slot order and builds the neighbour lists; iterateDensity is one
  // Jacobi density iteration (PBF Alg. 1 lines 9-18) on the working positions; a world's
  // contacts with bodies the solver does not know (the heart wall) act on workingPositions()
  // between iterations, as collisions do in Algorithm 1; endDensitySolve writes the positions
  // back and the pressures. projectDensity is the three with nothing between the iterations.
  // postProcessVelocities (wall contacts, vorticity confinement, viscosity) uses the lists of
  // the last solve and reads the particles' positions after the velocity update.
  void beginDensitySolve(const Particles& particles, const StepContext& context);
  void iterateDensity(const StepContext& context);
  [[nodiscard]] std::vector<Vec3>& workingPositions() { return m_p; }
  // Walls lend density to the fluid beside them (wall_density.h) for the rest of this solve:
  // each working position's nearest wall within the support is found now, and kept as a plane.
  void lendWallDensity(const std::vector<Vec3>& wallVertices, const std::vector<Triangle>& wallTriangles, int threads);
  void endDensitySolve(Particles& particles, const StepContext& context);
  void projectDensity(Particles& particles, const StepContext& context);
  void postProcessVelocities(Particles& particles, const StepContext& context);
  [[nodiscard]] int iterations() const { return m_settings.iterations; }

  // Forget the cached fluid index list (call after changing kinds without changing the
  // particle count; a change of count is detected automatically).
  void invalidateFluidIndices() { m_indexedCount = kNotIndexed; }

  std::span<const Index> fluidIndices() const { return m_fluid; }
  // Diagnostics of the last projectDensity, in slot order: the particle of each slot,
  // neighbour lists (of slots) built on the predicted positions, and densities of the last
  // iteration (before its dp).
  std::span<const Index> slotParticles() const { return m_slotParticle; }
  const NeighbourLists& neighbourLists() const { return m_lists; }
  const std::vector<Real>& densities() const { return m_density; }
  // Pressure (Pa) of each particle in the last projectDensity, indexed by particle (0 for
  // non-fluid particles). The density solve is a pressure solve in disguise: PBF's correction
  // dx_i = (m/rho0) sum_j (lambda_i + lambda_j) grad W_ij (eq. 12) equals dt^2 times the
  // symmetric SPH pressure acceleration -m sum_j (p_i + p_j)/rho0^2 grad W_ij (Monaghan 2005
  // eq. 3.13 at rho = rho0) when p_i = -(rho0/dt^2) lambda_i; summed over the iterations it
  // is the pressure that kept the fluid at rest density during the step. Gauge: 0 at a free
  // surface; with the one-sided constraint (unilateralDensity) it is never negative.
  const std::vector<Real>& pressures() const { return m_pressure; }
  // The fluid's density error and speed at the particles' current positions, over the
  // neighbour lists of the last solve (no grid of its own; fluid_stats.h,
  // measureDensityOnLists). Before the first solve, or after the fluid set changed, it builds
  // a grid (measureFluid).
  FluidStats measure(const Particles& particles, Real spacing, int threads) const;
  // The smoothed velocity v~ (velocity_field.h) at the particles' current positions and
  // velocities, over the neighbour lists of the last solve, written to smoothed[i] by particle
  // index (resized to particles.size(); entries of particles not evaluated are 0). `wanted`,
  // by particle index: evaluate only where nonzero (empty: every active fluid particle). A parked
  // particle weighs nothing (V = 0) and is not evaluated. All 0 before the first solve or after
  // the fluid set changed.
  // A measurement: the particles are not touched.
  void smoothedVelocities(const Particles& particles, std::vector<Vec3>& smoothed, int threads,
                          std::span<const std::uint8_t> wanted = {});

 private:
  static constexpr std::size_t kNotIndexed = ~std::size_t(0);

  void updateFluidIndices(const Particles& particles);
  void gatherSlots(const Particles& particles, int threads);

  FluidStepSettings m_settings;
  SphKernels m_kernels;
  NeighbourGrid m_grid;

  std::size_t m_indexedCount = kNotIndexed;  // particle count m_fluid was built for
  std::vector<Index> m_fluid;      // the fluid particles, in particle order
  std::vector<Vec3> m_gathered;    // their predicted positions, in that order (grid input)
  std::vector<Index> m_slots;      // 0 .. fluid count - 1: the subset for fluid.h
  std::vector<Index> m_slotParticle;  // particle index of each slot (cell order)
  std::vector<Vec3> m_p;           // slot predicted positions
  std::vector<Vec3> m_x;           // slot start-of-step positions (mesh collisions only)
  std::vector<Real> m_w;           // slot inverse masses
  NeighbourLists m_lists;          // over slots
  std::vector<Real> m_density;
  std::vector<Real> m_lambda;
  std::vector<Real> m_lambdaSum;   // slot: sum of lambda over the iterations of the step
  std::vector<Real> m_pressure;    // particle: see pressures()
  std::vector<Real> m_pairGradient;  // spiky gradient scale per list entry, reused in a pass
  std::vector<Vec3> m_dp;
  std::vector<Vec3> m_v;           // slot velocities (viscosity input)
  std::vector<Vec3> m_vNew;        // viscosity output
  std::vector<Vec3> m_vorticity;   // vorticity confinement work array
  WallDensityTable m_wallTable;    // for the kernels' support
  WallTriangleGrid m_wallGrid;     // the wall's triangles (lendWallDensity), buffers kept
  std::vector<WallProximity> m_wallProximity;  // slot: nearest wall, during a solve that lends
  std::vector<Vec3> m_wallStart;   // slot: where it was found
  bool m_wallsLend = false;
  // smoothedVelocities' slot arrays, kept so that a step's measurement allocates nothing.
  std::vector<Vec3> m_smoothX, m_smoothV, m_smoothOut;
  std::vector<Real> m_smoothVolume;
  std::vector<Index> m_smoothSubset;
};

}  // namespace hs::pbd
