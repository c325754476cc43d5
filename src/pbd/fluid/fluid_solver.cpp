// Position Based Fluids step (Macklin & Mueller 2013, Algorithm 1), see fluid_solver.h.
#include "pbd/fluid/fluid_solver.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <utility>

#include "pbd/fluid/velocity_field.h"

namespace hs::pbd {
namespace {

// Below this many fluid particles a fork-join (about 0.7 us here) costs more than these
// streaming loops save; the same threshold as the neighbour loops of fluid.cpp.
constexpr std::size_t kParallelThreshold = 256;


NeighbourGridSettings gridSettingsFor(int threads) {
  NeighbourGridSettings s;
  s.threads = threads;
  return s;
}

}  // namespace

FluidSolver::FluidSolver(FluidStepSettings settings)
    : m_settings(std::move(settings)),
      m_kernels(makeSphKernels(m_settings.fluid.supportRadius)),
      m_wallTable(m_kernels) {}

void FluidSolver::setSettings(const FluidStepSettings& settings) {
  m_settings = settings;
  m_kernels = makeSphKernels(m_settings.fluid.supportRadius);
  m_wallTable = WallDensityTable(m_kernels);
}

void FluidSolver::updateFluidIndices(const Particles& particles) {
  if (m_indexedCount == particles.size()) return;
  m_fluid.clear();
  for (std::size_t i = 0; i < particles.size(); ++i)
    if (particles.kind[i] == ParticleKind::Fluid) m_fluid.push_back(Index(i));
  m_slots.resize(m_fluid.size());
  std::iota(m_slots.begin(), m_slots.end(), Index(0));
  m_indexedCount = particles.size();
}

void FluidSolver::step(Particles& particles, const StepContext& context) {
  // PBF Algorithm 1 lines 1-4: v <- v + dt f_ext (gravity), p <- x + dt v.
  applyExternalForces(particles, m_settings.base, context);
  predictPositions(particles, context);
  projectDensity(particles, context);
  // Lines 20-21: v <- (p - x)/dt, x <- p.
  updateVelocities(particles, m_settings.base, context);
  // Line 22: wall contacts, vorticity confinement and viscosity on the new velocities.
  postProcessVelocities(particles, context);
}

void FluidSolver::projectDensity(Particles& particles, const StepContext& context) {
  beginDensitySolve(particles, context);
  for (int iteration = 0; iteration < m_settings.iterations; ++iteration) iterateDensity(context);
  endDensitySolve(particles, context);
}

// Lines 5-7: neighbours of the predicted positions, once per step, cell edge = h. The solve
// then runs in the grid's cell order (slots).
void FluidSolver::beginDensitySolve(const Particles& particles, const StepContext& context) {
  updateFluidIndices(particles);
  const int threads = context.threads;
  const auto n = std::ptrdiff_t(m_fluid.size());
  const bool parallel = std::size_t(n) >= kParallelThreshold;
  m_gathered.resize(m_fluid.size());
#pragma omp parallel for schedule(static) num_threads(threads) if (parallel)
  for (std::ptrdiff_t s = 0; s < n; ++s) m_gathered[s] = particles.predicted[m_fluid[s]];
  m_grid.setSettings(gridSettingsFor(threads));
  m_grid.build(m_gathered, m_settings.fluid.supportRadius);
  m_grid.buildSlotNeighbourLists(m_settings.fluid.supportRadius, m_lists);
  gatherSlots(particles, threads);
  m_lambdaSum.assign(m_fluid.size(), Real(0));
}

// Slot k's particle, working position, inverse mass (0 for pinned and parked particles: the
// iterations leave them where they are) and, for mesh collisions, start-of-step position.
void FluidSolver::gatherSlots(const Particles& particles, int threads) {
  const std::vector<Index>& sorted = m_grid.sortedIndices();
  const bool mesh = m_settings.mesh != nullptr;
  const auto n = std::ptrdiff_t(m_fluid.size());
  m_slotParticle.resize(m_fluid.size());
  m_p.resize(m_fluid.size());
  m_w.resize(m_fluid.size());
  m_x.resize(mesh ? m_fluid.size() : 0);
#pragma omp parallel for schedule(static) num_threads(threads) if (std::size_t(n) >= kParallelThreshold)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const Index particle = m_fluid[sorted[k]];
    m_slotParticle[k] = particle;
    m_p[k] = m_grid.sortedPositions()[k];
    m_w[k] = particles.active(particle) ? particles.inverseMass[particle] : Real(0);
    if (mesh) m_x[k] = particles.position[particle];
  }
}

void FluidSolver::iterateDensity(const StepContext& context) {
  const int threads = context.threads;
  const FluidSettings& fluid = m_settings.fluid;
  const Real radius = m_settings.particleRadius;
  const std::vector<Plane>& walls = m_settings.walls;
  const StaticMeshCollider* const mesh = m_settings.mesh.get();
  const Real maxCorrection = fluid.maxCorrection;
  const auto n = std::ptrdiff_t(m_slotParticle.size());
  const std::span<const Index> all(m_slots);
  // Lines 9-11: rho_i (PBF eq. 2) and lambda_i (eq. 11); lines 12-15: dp_i (eq. 12) and the
  // particle collisions (thesis eq. 4.6).
  const WallDensityInput wallInput{&m_wallTable, &m_wallProximity, &m_wallStart};
  const WallDensityInput* const lending = m_wallsLend ? &wallInput : nullptr;
  computeLambdas(m_p, m_lists, all, m_kernels, fluid, m_density, m_lambda, threads, &m_pairGradient, lending);
  computeDensityCorrections(m_p, m_lists, all, m_kernels, fluid, m_lambda, m_dp, threads, &m_pairGradient, lending);
  // Lines 16-18: p_i <- p_i + dp_i (Jacobi: all dp from the same p), then collision
  // response against the walls, C = n.p - (d + r) >= 0 (thesis eq. 4.5).
#pragma omp parallel for schedule(static) num_threads(threads) if (std::size_t(n) >= kParallelThreshold)
  for (std::ptrdiff_t s = 0; s < n; ++s) {
    m_lambdaSum[s] += m_lambda[s];
    if (m_w[s] <= Real(0)) continue;  // pinned or parked
    Vec3 dp = m_dp[s];
    const Real dp2 = dp.squaredNorm();
    if (maxCorrection > Real(0) && dp2 > maxCorrection * maxCorrection) dp *= maxCorrection / std::sqrt(dp2);
    Vec3 p = m_p[s] + dp;
    for (const Plane& plane : walls) p += projectPlaneCollision(p, m_w[s], plane, radius);
    if (mesh) p = mesh->collide(m_x[s], p, radius);
    m_p[s] = p;
  }
}

void FluidSolver::lendWallDensity(const std::vector<Vec3>& wallVertices, const std::vector<Triangle>& wallTriangles,
                                  int threads) {
  m_wallGrid.update(wallVertices, wallTriangles, m_kernels.h, threads);
  findNearestWalls(m_wallGrid, wallVertices, wallTriangles, m_p, m_wallProximity, threads);
  m_wallStart = m_p;
  m_wallsLend = true;
}

void FluidSolver::endDensitySolve(Particles& particles, const StepContext& context) {
  m_wallsLend = false;
  // Pressure (see pressures() in the header): p_i = -(rho0 / dt^2) sum over iterations of lambda_i.
  m_pressure.assign(particles.size(), Real(0));
  const Real pressureScale = -m_settings.fluid.restDensity / (context.dt * context.dt);
  const auto n = std::ptrdiff_t(m_slotParticle.size());
#pragma omp parallel for schedule(static) num_threads(context.threads) if (std::size_t(n) >= kParallelThreshold)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    particles.predicted[m_slotParticle[k]] = m_p[k];
    m_pressure[m_slotParticle[k]] = pressureScale * m_lambdaSum[k];
  }
}

FluidStats FluidSolver::measure(const Particles& particles, Real spacing, int threads) const {
  if (m_indexedCount != particles.size() || m_slotParticle.size() != m_fluid.size() ||
      m_lists.offsets.size() != m_slotParticle.size() + 1)
    return measureFluid(particles, m_settings.fluid, spacing, threads);
  std::vector<Vec3> x(m_slotParticle.size());
  for (std::size_t k = 0; k < x.size(); ++k) x[k] = particles.position[m_slotParticle[k]];
  FluidStats stats = measureDensityOnLists(x, m_lists, m_settings.fluid, spacing, threads);
  for (const Index i : m_slotParticle) stats.maxSpeed = std::max(stats.maxSpeed, particles.velocity[i].norm());
  return stats;
}

void FluidSolver::smoothedVelocities(const Particles& particles, std::vector<Vec3>& smoothed, int threads,
                                     std::span<const std::uint8_t> wanted) {
  smoothed.assign(particles.size(), Vec3::Zero());
  if (m_indexedCount != particles.size() || m_slotParticle.size() != m_fluid.size() ||
      m_lists.offsets.size() != m_slotParticle.size() + 1)
    return;
  const auto n = std::ptrdiff_t(m_slotParticle.size());
  m_smoothX.resize(m_slotParticle.size());
  m_smoothV.resize(m_slotParticle.size());
  m_smoothVolume.resize(m_slotParticle.size());
  // V_j = m / rho0: one mass for the whole fluid (PBF); 0 for a parked particle.
  const Real volume = m_settings.fluid.particleMass / m_settings.fluid.restDensity;
#pragma omp parallel for schedule(static) num_threads(threads) if (std::size_t(n) >= kParallelThreshold)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const Index i = m_slotParticle[k];
    m_smoothX[k] = particles.position[i];
    m_smoothV[k] = particles.velocity[i];
    m_smoothVolume[k] = particles.active(i) ? volume : Real(0);
  }
  // Parked particles are not evaluated (their entries stay 0): nothing reads them.
  m_smoothSubset.clear();
  for (std::size_t k = 0; k < m_slotParticle.size(); ++k) {
    const Index i = m_slotParticle[k];
    if (particles.active(i) && (wanted.empty() || wanted[i])) m_smoothSubset.push_back(Index(k));
  }
  shepardAverage(m_smoothX, m_smoothV, m_smoothVolume, m_lists, m_smoothSubset, m_kernels, m_smoothOut, threads);
  for (const Index k : m_smoothSubset) smoothed[m_slotParticle[k]] = m_smoothOut[k];
}

void FluidSolver::postProcessVelocities(Particles& particles, const StepContext& context) {
  if (m_slotParticle.empty() || m_lists.offsets.size() != m_slotParticle.size() + 1) return;
  const int threads = context.threads;
  const auto n = std::ptrdiff_t(m_slotParticle.size());
  const bool parallel = std::size_t(n) >= kParallelThreshold;
  const std::span<const Index> all(m_slots);
  const std::vector<Plane>& walls = m_settings.walls;
  // Contact threshold: the projection leaves a touching particle at exactly r from the wall.
  const Real touching = m_settings.particleRadius * (1 + Real(1e-3));
  m_v.resize(m_slotParticle.size());
  // Positions after the velocity update (x = p), read back from the particles: a world may
  // have moved the predictions after the density solve (the heart's wall push-out), so the
  // working positions of the solve are not the final ones.
#pragma omp parallel for schedule(static) num_threads(threads) if (parallel)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    m_p[k] = particles.position[m_slotParticle[k]];
    Vec3 v = particles.velocity[m_slotParticle[k]];
    // Inelastic wall contact (Mueller et al. 2007, "Position based dynamics", section 3.5:
    // colliding particles' velocities are modified for restitution): a particle touching a
    // wall keeps no velocity into it. Otherwise the projection's push turns into a velocity
    // towards the wall at the next step and wall particles jitter at rest.
    for (const Plane& plane : walls) {
      const Real vn = v.dot(plane.normal);
      if (vn < Real(0) && plane.normal.dot(m_p[k]) - plane.offset <= touching) v -= vn * plane.normal;
    }
    m_v[k] = v;
  }
  const FluidSettings& fluid = m_settings.fluid;
  const Real dt = context.dt;
  if (fluid.vorticityConfinement > Real(0)) {
    // PBF eq. 15-16, before the viscosity (Macklin & Mueller Algorithm 1 line 22).
    applyVorticityConfinement(m_p, m_v, m_lists, all, m_kernels, fluid, dt, m_vorticity, m_vNew, threads);
    m_v.swap(m_vNew);
  }
  // XSPH (PBF eq. 17, thesis eq. 4.11) and the physical viscosity, fluid.h.
  pbd::applyViscosity(m_p, m_v, m_lists, all, m_kernels, fluid, dt, m_vNew, threads);
#pragma omp parallel for schedule(static) num_threads(threads) if (parallel)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    if (m_w[k] > Real(0)) particles.velocity[m_slotParticle[k]] = m_vNew[k];
  }
}

}  // namespace hs::pbd
