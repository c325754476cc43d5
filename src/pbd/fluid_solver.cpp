// Position Based Fluids step (Macklin & Mueller 2013, Algorithm 1), see fluid_solver.h.
#include "pbd/fluid_solver.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <utility>

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
      m_grid(gridSettingsFor(m_settings.base.threads)) {}

void FluidSolver::setSettings(const FluidStepSettings& settings) {
  m_settings = settings;
  m_kernels = makeSphKernels(m_settings.fluid.supportRadius);
  m_grid.setSettings(gridSettingsFor(m_settings.base.threads));
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

void FluidSolver::step(Particles& particles) {
  // PBF Algorithm 1 lines 1-4: v <- v + dt f_ext (gravity), p <- x + dt v.
  applyExternalForces(particles, m_settings.base);
  predictPositions(particles, m_settings.base);
  projectDensity(particles);
  // Lines 20-21: v <- (p - x)/dt, x <- p.
  updateVelocities(particles, m_settings.base);
  // Line 22: wall contacts, vorticity confinement and viscosity on the new velocities.
  postProcessVelocities(particles);
}

void FluidSolver::projectDensity(Particles& particles) {
  updateFluidIndices(particles);
  const int threads = m_settings.base.threads;
  const FluidSettings& fluid = m_settings.fluid;
  const Real radius = m_settings.particleRadius;
  const std::vector<Plane>& walls = m_settings.walls;
  const auto n = std::ptrdiff_t(m_fluid.size());
  const bool parallel = std::size_t(n) >= kParallelThreshold;
  m_gathered.resize(m_fluid.size());
#pragma omp parallel for schedule(static) num_threads(threads) if (parallel)
  for (std::ptrdiff_t s = 0; s < n; ++s) m_gathered[s] = particles.predicted[m_fluid[s]];

  // Lines 5-7: neighbours of the predicted positions, once per step, cell edge = h. The
  // solve then runs in the grid's cell order (slots).
  m_grid.build(m_gathered, fluid.supportRadius);
  m_grid.buildSlotNeighbourLists(fluid.supportRadius, m_lists);
  const std::vector<Index>& sorted = m_grid.sortedIndices();
  const StaticMeshCollider* const mesh = m_settings.mesh.get();
  const Real maxCorrection = fluid.maxCorrection;
  m_slotParticle.resize(m_fluid.size());
  m_p.resize(m_fluid.size());
  m_w.resize(m_fluid.size());
  m_x.resize(mesh ? m_fluid.size() : 0);
#pragma omp parallel for schedule(static) num_threads(threads) if (parallel)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const Index particle = m_fluid[sorted[k]];
    m_slotParticle[k] = particle;
    m_p[k] = m_grid.sortedPositions()[k];
    m_w[k] = particles.inverseMass[particle];
    if (mesh) m_x[k] = particles.position[particle];
  }

  m_lambdaSum.assign(m_fluid.size(), Real(0));
  const std::span<const Index> all(m_slots);
  for (int iteration = 0; iteration < m_settings.iterations; ++iteration) {
    // Lines 9-11: rho_i (PBF eq. 2) and lambda_i (eq. 11); lines 12-15: dp_i (eq. 12) and the
    // particle collisions (thesis eq. 4.6).
    computeLambdas(m_p, m_lists, all, m_kernels, fluid, m_density, m_lambda, threads, &m_pairGradient);
    computeDensityCorrections(m_p, m_lists, all, m_kernels, fluid, m_lambda, m_dp, threads, &m_pairGradient);
    // Lines 16-18: p_i <- p_i + dp_i (Jacobi: all dp from the same p), then collision
    // response against the walls, C = n.p - (d + r) >= 0 (thesis eq. 4.5).
#pragma omp parallel for schedule(static) num_threads(threads) if (parallel)
    for (std::ptrdiff_t s = 0; s < n; ++s) {
      m_lambdaSum[s] += m_lambda[s];
      if (m_w[s] <= Real(0)) continue;  // pinned
      Vec3 dp = m_dp[s];
      const Real dp2 = dp.squaredNorm();
      if (maxCorrection > Real(0) && dp2 > maxCorrection * maxCorrection) dp *= maxCorrection / std::sqrt(dp2);
      Vec3 p = m_p[s] + dp;
      for (const Plane& plane : walls) p += projectPlaneCollision(p, m_w[s], plane, radius);
      if (mesh) p = mesh->collide(m_x[s], p, radius);
      m_p[s] = p;
    }
    if (m_settings.afterIteration) m_settings.afterIteration(m_p, m_slotParticle, particles);
  }

  // Pressure (see pressures() in the header): p_i = -(rho0 / dt^2) sum over iterations of lambda_i.
  m_pressure.assign(particles.size(), Real(0));
  const Real pressureScale = -fluid.restDensity / (m_settings.base.dt * m_settings.base.dt);
#pragma omp parallel for schedule(static) num_threads(threads) if (parallel)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    particles.predicted[m_slotParticle[k]] = m_p[k];
    m_pressure[m_slotParticle[k]] = pressureScale * m_lambdaSum[k];
  }
}

void FluidSolver::postProcessVelocities(Particles& particles) {
  if (m_slotParticle.empty() || m_lists.offsets.size() != m_slotParticle.size() + 1) return;
  const int threads = m_settings.base.threads;
  const auto n = std::ptrdiff_t(m_slotParticle.size());
  const bool parallel = std::size_t(n) >= kParallelThreshold;
  const std::span<const Index> all(m_slots);
  const std::vector<Plane>& walls = m_settings.walls;
  // Contact threshold: the projection leaves a touching particle at exactly r from the wall.
  const Real touching = m_settings.particleRadius * (1 + Real(1e-3));
  m_v.resize(m_slotParticle.size());
  // Positions: x = p after the velocity update, so m_p already holds them.
#pragma omp parallel for schedule(static) num_threads(threads) if (parallel)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
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
  const Real dt = m_settings.base.dt;
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

std::vector<Vec3> fluidBlock(const Vec3& lower, const Vec3& upper, Real spacing) {
  std::array<int, 3> count{};
  for (int a = 0; a < 3; ++a) {
    // Whole cells only; the small tolerance keeps (upper - lower) = k d from losing a cell
    // to rounding.
    const Real cells = (upper[a] - lower[a]) / spacing;
    count[std::size_t(a)] = std::max(0, int(std::floor(cells + Real(1e-4))));
  }
  std::vector<Vec3> x;
  x.reserve(std::size_t(count[0]) * std::size_t(count[1]) * std::size_t(count[2]));
  for (int k = 0; k < count[2]; ++k)
    for (int j = 0; j < count[1]; ++j)
      for (int i = 0; i < count[0]; ++i)
        x.push_back(lower + spacing * Vec3(Real(i) + Real(0.5), Real(j) + Real(0.5), Real(k) + Real(0.5)));
  return x;
}

std::vector<Plane> boxWalls(const Vec3& lower, const Vec3& upper) {
  std::vector<Plane> walls;
  for (int a = 0; a < 3; ++a) {
    Plane low, high;
    low.normal = Vec3::Unit(a);  // n.x >= lower
    low.offset = lower[a];
    high.normal = -Vec3::Unit(a);  // -n.x >= -upper
    high.offset = -upper[a];
    walls.push_back(low);
    walls.push_back(high);
  }
  return walls;
}

Index latticeNeighbourCount(Real supportRadius, Real spacing) {
  const int reach = int(std::ceil(supportRadius / spacing)) + 1;
  const Real h2 = supportRadius * supportRadius;
  Index count = 0;
  for (int k = -reach; k <= reach; ++k)
    for (int j = -reach; j <= reach; ++j)
      for (int i = -reach; i <= reach; ++i) {
        if (i == 0 && j == 0 && k == 0) continue;
        if ((spacing * Vec3(Real(i), Real(j), Real(k))).squaredNorm() < h2) ++count;
      }
  return count;
}

FluidStats measureFluid(const Particles& particles, const FluidSettings& fluid, Real spacing, int threads) {
  std::vector<Index> indices;
  std::vector<Vec3> x;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (particles.kind[i] != ParticleKind::Fluid) continue;
    indices.push_back(Index(i));
    x.push_back(particles.position[i]);
  }
  FluidStats stats;
  stats.fluidCount = x.size();
  // 90% of an interior lattice particle's neighbours, rounded up.
  stats.fullThreshold =
      Index(std::ceil(Real(0.9) * Real(latticeNeighbourCount(fluid.supportRadius, spacing))));
  if (x.empty()) return stats;
  for (const Index i : indices) stats.maxSpeed = std::max(stats.maxSpeed, particles.velocity[i].norm());
  // The solver's own grid and slot lists (cell order, no per-list sort): the statistics are
  // sums over particles and do not depend on their order but for rounding.
  NeighbourGrid grid(gridSettingsFor(threads));
  grid.build(x, fluid.supportRadius);
  NeighbourLists lists;
  grid.buildSlotNeighbourLists(fluid.supportRadius, lists);
  const std::vector<Vec3>& slotPositions = grid.sortedPositions();
  std::vector<Index> all(x.size());
  std::iota(all.begin(), all.end(), Index(0));
  std::vector<Real> density;
  computeDensities(slotPositions, lists, all, makeSphKernels(fluid.supportRadius), fluid, density, threads);
  double sumAbs = 0, sumSigned = 0;
  for (std::size_t s = 0; s < x.size(); ++s) {
    if (lists.offsets[s + 1] - lists.offsets[s] < stats.fullThreshold) continue;
    const Real c = density[s] / fluid.restDensity - Real(1);
    ++stats.fullCount;
    sumAbs += double(std::abs(c));
    sumSigned += double(c);
    stats.densityErrorMax = std::max(stats.densityErrorMax, std::abs(c));
  }
  stats.meanNeighbours = Real(double(lists.indices.size()) / double(x.size()));
  if (stats.fullCount > 0) {
    stats.densityErrorMean = Real(sumAbs / double(stats.fullCount));
    stats.densitySignedMean = Real(sumSigned / double(stats.fullCount));
  }
  return stats;
}

}  // namespace hs::pbd
