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
// Mixed sets: step() runs the solver.h phases over the whole set, so tissue particles in the
// same set are integrated too (gravity, prediction, velocity update, no constraints). A world
// with tissue should call applyExternalForces/predictPositions itself and use
// projectDensity() between prediction and the velocity update and postProcessVelocities()
// after it.
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "pbd/constraints.h"
#include "pbd/fluid.h"
#include "pbd/mesh_collider.h"
#include "pbd/neighbour_grid.h"
#include "pbd/particles.h"
#include "pbd/solver.h"
#include "pbd/sph_kernels.h"

namespace hs::pbd {

struct FluidStepSettings {
  SolverSettings base;          // dt, gravity (and gravityScale), threads; base.iterations unused
  int iterations = 4;           // density solver iterations per step (PBF Algorithm 1 line 8)
  FluidSettings fluid;          // rho0, m, h, eps, s_corr, XSPH c
  Real particleRadius = Real(0.08);  // m, distance kept from the walls (thesis: 0.08 m)
  std::vector<Plane> walls;     // normals point into the fluid's allowed half-space
  // Static triangle-mesh walls (a container, a vessel): after the planes, every particle is
  // kept particleRadius from the mesh on the side it came from (mesh_collider.h). Shared,
  // read-only: copies of the settings use the same mesh.
  std::shared_ptr<const StaticMeshCollider> mesh;
  // Called after every density iteration with the working positions (slot order) and the
  // particle of each slot: contacts with moving bodies the solver does not know (the heart
  // wall) take part in the iterations, as collisions do in PBF's Algorithm 1.
  std::function<void(std::vector<Vec3>& positions, std::span<const Index> slotParticles, const Particles& particles)>
      afterIteration;
};

class FluidSolver {
 public:
  explicit FluidSolver(FluidStepSettings settings = {});

  const FluidStepSettings& settings() const { return m_settings; }
  void setSettings(const FluidStepSettings& settings);

  // One whole step (see the header comment).
  void step(Particles& particles);

  // The phases, for a caller that integrates a mixed set itself. projectDensity expects
  // particles.predicted to hold the predicted positions; it builds the neighbour lists and
  // runs the iterations. postProcessVelocities (wall contacts, vorticity confinement,
  // viscosity) uses the lists of the last projectDensity.
  void projectDensity(Particles& particles);
  void postProcessVelocities(Particles& particles);

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

 private:
  static constexpr std::size_t kNotIndexed = ~std::size_t(0);

  void updateFluidIndices(const Particles& particles);

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
};

// A cubic lattice of spacing d filling the box [lower, upper]: one particle at the centre of
// each whole cell of edge d, x = lower + d (i + 1/2), so particles keep d/2 from every face.
std::vector<Vec3> fluidBlock(const Vec3& lower, const Vec3& upper, Real spacing);

// Six inward-facing planes of the box [lower, upper] (walls for FluidStepSettings).
std::vector<Plane> boxWalls(const Vec3& lower, const Vec3& upper);

struct FluidStats {
  std::size_t fluidCount = 0;
  std::size_t fullCount = 0;         // fluid particles with a full neighbourhood
  Index fullThreshold = 0;           // neighbour count that counts as full
  Real densityErrorMean = 0;         // mean |rho/rho0 - 1| over full-neighbourhood particles
  Real densityErrorMax = 0;          // max  |rho/rho0 - 1| over them
  Real densitySignedMean = 0;        // mean (rho/rho0 - 1) over them (compression > 0)
  Real maxSpeed = 0;                 // max |v| over all fluid particles
  Real meanNeighbours = 0;           // neighbours within h per fluid particle
};

// Neighbour count (|r| < h, self excluded) of an interior particle of a cubic lattice of
// spacing d.
Index latticeNeighbourCount(Real supportRadius, Real spacing);

// Density error and speed of the fluid particles at their current positions. A particle has
// a full neighbourhood when it has at least 90% of latticeNeighbourCount(h, spacing)
// neighbours (free-surface and wall particles lack neighbours and are under-dense by design).
FluidStats measureFluid(const Particles& particles, const FluidSettings& fluid, Real spacing,
                        int threads = 1);

}  // namespace hs::pbd
