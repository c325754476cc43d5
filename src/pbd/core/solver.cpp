#include "pbd/core/solver.h"

#include <omp.h>

#include <cstring>

namespace hs::pbd {
namespace {

// Below this many constraints + particles, a fork-join costs more than it saves.
constexpr std::size_t kParallelThreshold = 2048;
// Below this many movable constraints the sweeps run on one thread (projectConstraints).
constexpr std::size_t kParallelMovableConstraints = 4096;

// One projection applied in place; returns the lambda increment.
HS_KERNEL Real apply(const TetVolumeConstraint& c, Vec3* p, const Real* w, const ProjectionParams& params,
                  Real lambda) {
  const auto [i0, i1, i2, i3] = c.particles;
  const Correction4 r = projectTetVolume(p[i0], p[i1], p[i2], p[i3], w[i0], w[i1], w[i2], w[i3], c.restVolume,
                                         params, lambda);
  p[i0] += r.dx0;
  p[i1] += r.dx1;
  p[i2] += r.dx2;
  p[i3] += r.dx3;
  return r.deltaLambda;
}

HS_KERNEL Real apply(const TriangleAreaConstraint& c, Vec3* p, const Real* w, const ProjectionParams& params,
                  Real lambda) {
  const auto [i0, i1, i2] = c.particles;
  const Correction3 r = projectTriangleArea(p[i0], p[i1], p[i2], w[i0], w[i1], w[i2], c.restArea, params, lambda);
  p[i0] += r.dx0;
  p[i1] += r.dx1;
  p[i2] += r.dx2;
  return r.deltaLambda;
}

HS_KERNEL Real apply(const DistanceConstraint& c, Vec3* p, const Real* w, const ProjectionParams& params,
                  Real lambda) {
  const auto [i0, i1] = c.particles;
  const Correction2 r = projectDistance(p[i0], p[i1], w[i0], w[i1], c.restLength, params, lambda);
  p[i0] += r.dx0;
  p[i1] += r.dx1;
  return r.deltaLambda;
}

template <class Constraint>
HS_KERNEL bool immovable(const Constraint& c, const Real* w) {
  for (const Index i : c.particles)
    if (w[i] != Real(0)) return false;
  return true;
}

// The constraints of each block that can move something (some particle with w > 0), in the
// stored order. A kinematic or pinned wall leaves most of a heart's constraints with nothing to
// move; listing the rest when the inverse masses change spares every iteration the test.
template <class Constraint>
void listMovable(ConstraintGroup<Constraint>& group, const Particles& particles) {
  const Real* w = particles.inverseMass.data();
  group.movable.clear();
  group.movableStart.assign(1, 0);
  for (std::size_t block = 0; block + 1 < group.blockStart.size(); ++block) {
    for (std::size_t c = group.blockStart[block]; c < group.blockStart[block + 1]; ++c)
      if (!immovable(group.constraints[c], w)) group.movable.push_back(Index(c));
    group.movableStart.push_back(group.movable.size());
  }
}

// Projects a block's movable constraints of one group, in order (Gauss-Seidel). Blocks of one
// colour touch disjoint particles, so blocks may run on any thread without changing the result.
template <class Constraint>
void projectBlock(ConstraintGroup<Constraint>& group, std::size_t block, Particles& particles,
                  const ProjectionParams& params) {
  if (block + 1 >= group.movableStart.size()) return;  // the group has no constraint in this block
  Vec3* __restrict p = particles.predicted.data();
  const Real* __restrict w = particles.inverseMass.data();
  const Constraint* __restrict constraints = group.constraints.data();
  const Index* __restrict movable = group.movable.data();
  Real* __restrict lambda = group.lambda.data();
  // With zero compliance lambda never enters the update (plain PBD): skip its bookkeeping.
  const bool compliant = params.alphaTilde != Real(0);
  const std::size_t end = group.movableStart[block + 1];
  for (std::size_t k = group.movableStart[block]; k < end; ++k) {
    const Index c = movable[k];
    const Real deltaLambda = apply(constraints[c], p, w, params, compliant ? lambda[c] : Real(0));
    if (compliant) lambda[c] += deltaLambda;
  }
}

template <class Constraint>
ProjectionParams paramsOf(const ConstraintGroup<Constraint>& group, Real dt) {
  return {group.compliance / (dt * dt), group.stiffness};
}

// Visits the blocks colour by colour; the blocks of one colour are shared among the threads
// of the enclosing parallel region (which must all call this), one barrier per colour.
template <class ProjectOneBlock>
void sweep(const BlockSchedule& schedule, const ProjectOneBlock& projectOneBlock) {
  for (std::size_t colour = 0; colour < schedule.colourCount(); ++colour) {
    const auto begin = static_cast<std::ptrdiff_t>(schedule.colourStart[colour]);
    const auto end = static_cast<std::ptrdiff_t>(schedule.colourStart[colour + 1]);
#pragma omp for schedule(dynamic, 1)
    for (std::ptrdiff_t k = begin; k < end; ++k) projectOneBlock(schedule.blockOrder[k]);
  }
}

void projectPlanes(const ConstraintSet& constraints, Particles& particles) {
  if (constraints.planes.empty()) return;
  const auto n = static_cast<std::ptrdiff_t>(particles.size());
#pragma omp for schedule(static)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const Real w = particles.active(std::size_t(i)) ? particles.inverseMass[i] : Real(0);
    for (const Plane& plane : constraints.planes) {
      particles.predicted[i] += projectPlaneCollision(particles.predicted[i], w, plane, constraints.collisionRadius);
    }
  }
}

}  // namespace

void applyExternalForces(Particles& particles, const SolverSettings& settings, const StepContext& context) {
  const auto n = static_cast<std::ptrdiff_t>(particles.size());
  const Vec3 dv = context.dt * context.gravity;
#pragma omp parallel for schedule(static) num_threads(context.threads) \
    if (static_cast<std::size_t>(n) >= kParallelThreshold)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    if (particles.dynamic(std::size_t(i)))
      particles.velocity[i] += settings.gravityScale[static_cast<std::size_t>(particles.kind[i])] * dv;
  }
}

void predictPositions(Particles& particles, const StepContext& context) {
  const auto n = static_cast<std::ptrdiff_t>(particles.size());
#pragma omp parallel for schedule(static) num_threads(context.threads) \
    if (static_cast<std::size_t>(n) >= kParallelThreshold)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    particles.predicted[i] = particles.position[i] + context.dt * particles.velocity[i];
  }
}

void projectConstraints(ConstraintSet& constraints, Particles& particles, const SolverSettings& settings,
                        const StepContext& context) {
  // XPBD multipliers start each step at zero; plain PBD groups (no compliance) never read them.
  auto resetLambdas = [](auto& group) {
    if (group.compliance != Real(0)) std::fill(group.lambda.begin(), group.lambda.end(), Real(0));
  };
  resetLambdas(constraints.distances);
  resetLambdas(constraints.areas);
  resetLambdas(constraints.volumes);
  const std::size_t constraintCount = constraints.distances.size() + constraints.areas.size() +
                                      constraints.volumes.size() + constraints.planes.size();
  if (constraintCount == 0) return;  // e.g. blood only: its constraints are the fluid solver's
  if (constraints.movableListedFor != particles.inverseMass) {
    listMovable(constraints.distances, particles);
    listMovable(constraints.areas, particles);
    listMovable(constraints.volumes, particles);
    constraints.movableListedFor = particles.inverseMass;
  }
  const std::size_t movable =
      constraints.distances.movable.size() + constraints.areas.movable.size() + constraints.volumes.movable.size();
  if (movable == 0 && constraints.planes.empty()) return;  // e.g. a wall the cycle moves as a whole
  // One parallel region for all iterations: threads meet at the end of each colour. Few
  // movable constraints are swept faster by one thread: a recorded beat leaves 1,663 of its
  // default wall's 17,754 to the constraints (the annuli's rims), 27 us a sweep on one thread;
  // its 10 sweeps took 0.27 ms a step on one thread and 0.39 on two (0.31 with the rims split
  // evenly between the two regions), the meetings costing more than the second thread saved.
  const bool parallel = movable >= kParallelMovableConstraints ||
                        (!constraints.planes.empty() && particles.size() >= kParallelThreshold);
#pragma omp parallel num_threads(context.threads) if (parallel)
  {
    const ProjectionParams distance = paramsOf(constraints.distances, context.dt);
    const ProjectionParams area = paramsOf(constraints.areas, context.dt);
    const ProjectionParams volume = paramsOf(constraints.volumes, context.dt);
    const BlockSchedule& schedule = constraints.schedule;
    for (int iteration = 0; iteration < settings.iterations; ++iteration) {
      sweep(schedule, [&](std::size_t block) {
        projectBlock(constraints.distances, block, particles, distance);
        projectBlock(constraints.areas, block, particles, area);
        projectBlock(constraints.volumes, block, particles, volume);
      });
      projectPlanes(constraints, particles);
    }
    // Incompressibility passes: extra sweeps over the volume constraints alone, so the
    // constraint the wall must keep best is also among the last satisfied; contacts stay last.
    for (int pass = 0; pass < settings.volumePasses; ++pass) {
      sweep(schedule, [&](std::size_t block) { projectBlock(constraints.volumes, block, particles, volume); });
      projectPlanes(constraints, particles);
    }
  }
}

void updateVelocities(Particles& particles, const SolverSettings& settings, const StepContext& context) {
  const auto n = static_cast<std::ptrdiff_t>(particles.size());
  const Real invDt = context.inverseDt;
  const std::array<Real, 2> keep{std::max(Real(0), Real(1) - settings.damping[0] * context.dt),
                                 std::max(Real(0), Real(1) - settings.damping[1] * context.dt)};
#pragma omp parallel for schedule(static) num_threads(context.threads) \
    if (static_cast<std::size_t>(n) >= kParallelThreshold)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const Real k = keep[static_cast<std::size_t>(particles.kind[i])];
    particles.velocity[i] = (k * invDt) * (particles.predicted[i] - particles.position[i]);
    particles.position[i] = particles.predicted[i];
  }
}

void step(ConstraintSet& constraints, Particles& particles, const SolverSettings& settings,
          const StepContext& context) {
  applyExternalForces(particles, settings, context);
  predictPositions(particles, context);
  projectConstraints(constraints, particles, settings, context);
  updateVelocities(particles, settings, context);
}

std::uint64_t stateHash(const Particles& particles) {
  std::uint64_t hash = 1469598103934665603ull;  // FNV-1a offset basis
  auto mix = [&hash](const void* data, std::size_t bytes) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) {
      hash ^= b[i];
      hash *= 1099511628211ull;  // FNV prime
    }
  };
  for (std::size_t i = 0; i < particles.size(); ++i) {
    mix(particles.position[i].data(), 3 * sizeof(Real));
    mix(particles.velocity[i].data(), 3 * sizeof(Real));
  }
  return hash;
}

}  // namespace hs::pbd
