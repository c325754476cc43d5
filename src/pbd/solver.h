#pragma once
// The position-based step of thesis Algorithm 1 (Bender et al. 2015), split into its phases
// so that a caller can insert its own work between them (the cardiac cycle moves wall
// vertices after prediction; blood adds density constraints; XSPH post-processes velocity):
//   applyExternalForces  v <- v + dt w f_ext        (lines 4-5)
//   predictPositions     p <- x + dt v              (lines 6-7)
//   projectConstraints   solverIterations of Gauss-Seidel projection (lines 8-11)
//   updateVelocities     v <- (p - x)/dt, x <- p    (lines 12-14)
// velocity post-processing (line 15) belongs to the caller.
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "pbd/block_schedule.h"
#include "pbd/constraint_group.h"
#include "pbd/constraints.h"
#include "pbd/particles.h"

namespace hs::pbd {

struct SolverSettings {
  Real dt = Real(0.005);       // s
  int iterations = 10;         // solverIterations
  int volumePasses = 0;        // extra sweeps of the volume constraints after the iterations
  Vec3 gravity = Vec3(0, Real(-9.81), 0);
  // Share of gravity each particle kind feels, indexed by ParticleKind (Tissue, Fluid).
  std::array<Real, 2> gravityScale{1, 1};
  // 1/s, per ParticleKind (Tissue, Fluid): v <- v * max(0, 1 - damping dt) after the update.
  // Viscous tissue is damped; a liquid's dissipation is its viscosity (fluid.h), not this.
  std::array<Real, 2> damping{0, 0};
  int threads = 1;             // OpenMP threads for projection and particle loops
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
};

void applyExternalForces(Particles& particles, const SolverSettings& settings);
void predictPositions(Particles& particles, const SolverSettings& settings);
void projectConstraints(ConstraintSet& constraints, Particles& particles,
                        const SolverSettings& settings);
void updateVelocities(Particles& particles, const SolverSettings& settings);

// Work a caller inserts into a step (thesis Fig. 4.1): after prediction (the cardiac cycle
// moving the wall; later the heart-blood coupling), and after the velocity update (Algorithm 1
// line 15: velocity post-processing such as XSPH viscosity, thesis eq. 4.11). Empty: skipped.
struct StepHooks {
  std::function<void(Particles&)> afterPrediction;
  // After the constraints, before the velocity update: contacts between bodies that must see
  // where the constraints put them (blood pushed out of the wall, thesis 4.4).
  std::function<void(Particles&)> afterProjection;
  std::function<void(Particles&)> postProcessVelocities;
};

// One whole step: the four phases in order, with the hooks between them.
void step(ConstraintSet& constraints, Particles& particles, const SolverSettings& settings,
          const StepHooks& hooks = {});

// FNV-1a 64-bit hash of the bytes of every position and velocity: equal states, equal hashes.
std::uint64_t stateHash(const Particles& particles);

}  // namespace hs::pbd
