#pragma once
// Blood for a scenario: where its particles start, the PBF solver settings that follow from
// the scenario's clinical/physical parameters, and the measurements the runner reports.
// The fluid itself (density constraint, viscosity, collisions) is the engine's, pbd/fluid/.
#include <cstddef>
#include <vector>

#include "cardiac/anatomy/lv_model.h"
#include "cardiac/scenario.h"
#include "pbd/core/particles.h"
#include "pbd/fluid/fluid_setup.h"
#include "pbd/fluid/fluid_solver.h"
#include "pbd/fluid/fluid_stats.h"

namespace hs::cardiac {

using pbd::Vec3;

// The fluid's own parameters for the scenario's blood (the part of bloodSolverSettings that
// measurements need too).
pbd::FluidSettings bloodFluidSettings(const BloodSettings& blood);

// Solver settings for the scenario's blood (thesis 4.2 with the constants of Table 5.2):
//   m = rho0 d^3 (one particle per lattice cell at rest, docs/thesis-deviations.md),
//   XSPH c = gamma m / rho0 (thesis eq. 4.11), nu = mu / rho0,
//   eps = relaxation * sum |grad C|^2 of a particle at rest (pbd::latticeGradientSum),
//   walls = the container's six planes when it has plane walls.
// Throws std::invalid_argument, naming the key, for combinations the solver cannot run
// (viscosity too large for dt, particles that would overlap at rest).
pbd::FluidStepSettings bloodSolverSettings(const Scenario& scenario);

// Start positions: the lattice sites of [blood.block_min, blood.block_max] at blood.spacing,
// all of them (blood.particles = 0) or the first blood.particles sites, lowest y first.
// Throws std::invalid_argument when the block holds too few sites, when the start block is
// not inside the container, or when the particles would not fit in this machine's memory.
// blood.start = "heart" fills the cavity and both vessels (a radius from their walls);
// blood.start = "vessel" fills the inflow vessel of `model` (from its bottom up), then the
// cavity from the base down; it needs the model. With circulation.loop it may return fewer
// sites than blood.particles: the rest start outside the model, waiting to enter.
std::vector<pbd::Vec3> bloodStartPositions(const Scenario& scenario, const LvModel* model = nullptr);

// Rough bytes per blood particle of a run (state, solver buffers, neighbour lists of about
// `neighbours` entries), for the memory check above.
std::size_t bloodBytesPerParticle(std::size_t neighbours);

struct BloodStats {
  std::size_t particles = 0;
  // Particles outside the domain (the container or the heart's surroundings) or non-finite.
  std::size_t lost = 0;
  // Where the first of them is (the failure's message names it); not saved in checkpoints.
  Vec3 firstLostAt = Vec3::Zero();
  // |rho/rho0 - 1| over particles with a full neighbourhood (pbd::measureFluid).
  double densityErrorMean = 0;
  double densityErrorMax = 0;
  std::size_t fullNeighbourhood = 0;
  double maxSpeed = 0;  // m/s over all blood particles
  double meanNeighbours = 0;  // neighbours within the support radius per particle
  // Particles whose centre is more than 1% of their radius inside a wall tetrahedron.
  std::size_t insideWall = 0;
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);
};

// The blood's statistics from the fluid's (`fluid`, e.g. pbd::FluidSolver::measure) and the
// particles: those outside the box [domainMin, domainMax] or non-finite count as lost.
BloodStats measureBlood(const pbd::Particles& particles, const pbd::FluidStats& fluid, const Vec3& domainMin,
                        const Vec3& domainMax);

}  // namespace hs::cardiac
