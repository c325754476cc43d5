#pragma once
// The position-based step of thesis Algorithm 1 (Bender et al. 2015), split into its stages
// so that a world can list its own step in order (the cardiac cycle moves wall vertices after
// prediction; blood adds density constraints; XSPH post-processes velocity). Each stage takes
// the step's StepContext (dt, gravity, threads):
//   applyExternalForces  v <- v + dt w f_ext        (lines 4-5)
//   predictPositions     p <- x + dt v              (lines 6-7)
//   projectConstraints   solverIterations of Gauss-Seidel projection (lines 8-11)
//   updateVelocities     v <- (p - x)/dt, x <- p    (lines 12-14)
// velocity post-processing (line 15) belongs to the caller.
#include <array>
#include <cstdint>
#include <vector>

#include "pbd/core/block_schedule.h"
#include "pbd/core/constraint_group.h"
#include "pbd/core/constraints.h"
#include "pbd/core/particles.h"
#include "pbd/core/step_context.h"

namespace hs::pbd {

struct SolverSettings {
  int iterations = 10;         // solverIterations
  int volumePasses = 0;        // extra sweeps of the volume constraints after the iterations
  // Share of gravity each particle kind feels, indexed by ParticleKind (Tissue, Fluid).
  std::array<Real, 2> gravityScale{1, 1};
  // 1/s, per ParticleKind (Tissue, Fluid): v <- v * max(0, 1 - damping dt) after the update.
  // Viscous tissue is damped; a liquid's dissipation is its viscosity (fluid.h), not this.
  std::array<Real, 2> damping{0, 0};
};

// The constraints of one simulated world. Projection order within an iteration: block colour
// by block colour (block_schedule.h); inside a block its edges, then triangle areas, then tet
// volumes (volume last: it is the one the wall must keep best); then collision planes.
struct ConstraintSet {
  ConstraintGroup<DistanceConstraint> distances;
  ConstraintGroup<TriangleAreaConstraint> areas;
  ConstraintGroup<TetVolumeConstraint> volumes;
  BlockSchedule schedule;
  std::vector<Plane> planes;
  Real collisionRadius = 0;  // particle radius used against planes
  // The inverse masses the groups' movable lists were made for: the lists are made again only
  // when these change (a wall made kinematic, a vertex pinned) or the schedule is rebuilt.
  std::vector<Real> movableListedFor;
};

// Parked particles (Particles::state) are left alone by every stage; pinned ones (w = 0) feel
// no forces and no constraint corrections.
void applyExternalForces(Particles& particles, const SolverSettings& settings, const StepContext& context);
void predictPositions(Particles& particles, const StepContext& context);
void projectConstraints(ConstraintSet& constraints, Particles& particles, const SolverSettings& settings,
                        const StepContext& context);
void updateVelocities(Particles& particles, const SolverSettings& settings, const StepContext& context);

// A step of a world with constraints only (a soft body on its own): the four stages in order.
// Worlds with more (blood, a beating wall) list their own order, cardiac/heart_simulation.cpp.
void step(ConstraintSet& constraints, Particles& particles, const SolverSettings& settings,
          const StepContext& context);

// FNV-1a 64-bit hash of the bytes of every position and velocity: equal states, equal hashes.
std::uint64_t stateHash(const Particles& particles);

}  // namespace hs::pbd
