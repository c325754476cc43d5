#include "cardiac/heart_simulation.h"

#include <cassert>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "pbd/soft_body.h"

namespace hs::cardiac {
namespace {

pbd::SoftBodySettings softBodySettings(const TissueSettings& tissue) {
  pbd::SoftBodySettings s;
  s.density = tissue.density;
  s.stiffness = tissue.stiffness;
  s.volumeStiffness = tissue.volumeStiffness;
  s.volumeCompliance = tissue.volumeCompliance;
  s.areaCompliance = tissue.areaCompliance;
  s.edgeCompliance = tissue.edgeCompliance;
  s.edges = tissue.edges;
  s.areas = tissue.areas;
  return s;
}

// The wall particles must exist before the cycle can refer to them; this builds them and
// returns the first wall particle id.
Index buildWall(const Scenario& scenario, const LvModel& model, pbd::Particles& particles,
                pbd::ConstraintSet& constraints) {
  const Index first = pbd::addSoftBody(particles, constraints, model.mesh, model.surface,
                                       softBodySettings(scenario.tissue));
  for (Index v : model.pinned) particles.inverseMass[first + v] = 0;
  pbd::finalizeConstraints(constraints, particles.position);
  return first;
}

}  // namespace

HeartSimulation::HeartSimulation(const Scenario& scenario, int threads)
    : m_scenario(scenario), m_threads(threads) {
  if (!scenario.heart && !scenario.blood.enabled)
    throw std::invalid_argument("model.enabled: with no heart and no blood (blood.enabled = false) there is "
                                "nothing to simulate");
  m_solver.dt = scenario.simulation.dt;
  m_solver.iterations = scenario.simulation.iterations;
  m_solver.volumePasses = scenario.simulation.volumePasses;
  m_solver.gravity = scenario.simulation.gravity;
  m_solver.gravityScale[static_cast<std::size_t>(pbd::ParticleKind::Tissue)] = scenario.tissue.gravity ? 1 : 0;
  m_solver.damping[static_cast<std::size_t>(pbd::ParticleKind::Tissue)] = scenario.tissue.damping;
  m_solver.threads = threads;
  if (scenario.heart) {
    m_model.emplace(buildLvModel(scenario.geometry));
    m_firstWallParticle = buildWall(m_scenario, *m_model, m_particles, m_constraints);
    m_cycle.emplace(scenario.cycle, *m_model, m_firstWallParticle, scenario.simulation.dt);
    assert(m_firstWallParticle == 0 && "cavityVolume reads particle positions as model vertices");
    m_restVolume.reserve(m_model->mesh.tets.size());
    for (const pbd::Tet& t : m_model->mesh.tets) {
      const auto& x = m_model->mesh.vertices;
      m_restVolume.push_back(pbd::signedTetVolume(x[t[0]], x[t[1]], x[t[2]], x[t[3]]));
    }
  }
  m_firstBloodParticle = Index(m_particles.size());
  // Blood beyond this box is lost: the container, or the heart's rest bounding box grown by
  // a quarter of its long axis (blood that left through a vessel's open end).
  if (scenario.container.enabled) {
    const Vec3 r = Vec3::Constant(scenario.blood.radius);
    m_domainMin = scenario.container.min - r;
    m_domainMax = scenario.container.max + r;
  } else if (m_model) {
    m_domainMin = m_domainMax = m_model->mesh.vertices.front();
    for (const Vec3& v : m_model->mesh.vertices) {
      m_domainMin = m_domainMin.cwiseMin(v);
      m_domainMax = m_domainMax.cwiseMax(v);
    }
    const Vec3 grow = Vec3::Constant(Real(0.25) * m_model->longAxisLength);
    m_domainMin -= grow;
    m_domainMax += grow;
  } else {
    m_domainMin = Vec3::Constant(-std::numeric_limits<Real>::max());
    m_domainMax = Vec3::Constant(std::numeric_limits<Real>::max());
  }
  if (scenario.blood.enabled) {
    // The start block first: it checks the particle count against memory before anything
    // else is allocated; then the solver settings check the remaining parameters.
    const std::vector<pbd::Vec3> start = bloodStartPositions(scenario, m_model ? &*m_model : nullptr);
    if (m_model) {
      m_wallContact = std::make_unique<pbd::ParticleTetCollider>(m_model->mesh.tets, m_firstWallParticle);
      // Blood lives on the shell's inner side (the cavity and the vessel lumens): the inner
      // layer's vertices, 2i (lv_model.h).
      std::vector<std::uint8_t> wetted(m_model->mesh.vertices.size(), 0);
      for (std::size_t v = 0; v < wetted.size(); v += 2) wetted[v] = 1;
      m_wallContact->setWettedVertices(wetted);
      m_circulation = std::make_unique<Circulation>(*m_model, scenario.circulation, scenario.blood, scenario.cycle);
    }
    pbd::FluidStepSettings fluid = bloodSolverSettings(scenario, threads);
    if (m_model) {
      // The wall takes part in every density iteration (and once more after its own
      // constraints, in step()): blood squeezed by the beating wall must not be pushed
      // through it by its own pressure.
      fluid.afterIteration = [this](std::vector<pbd::Vec3>& x, std::span<const Index> ids, const pbd::Particles& p) {
        // Valves first, the wall last: the closed-valve disc has the lumen's radius, and the
        // wall's faceted lumen lies a little inside it, so the wall has the final word.
        m_circulation->gatePoints(p, x, ids);
        m_wallContact->resolvePoints(p, x, ids, wallContactSettings());
      };
    }
    m_fluid = std::make_unique<pbd::FluidSolver>(fluid);
    const Real inverseMass = Real(1) / m_fluid->settings().fluid.particleMass;
    for (const pbd::Vec3& x : start) m_particles.add(x, inverseMass, pbd::ParticleKind::Fluid);
    // Blood the start sites cannot hold begins in the body, waiting to enter (closed loop).
    const std::size_t waiting =
        scenario.blood.particles > 0 && std::size_t(scenario.blood.particles) > start.size()
            ? std::size_t(scenario.blood.particles) - start.size()
            : 0;
    for (std::size_t k = 0; k < waiting; ++k) m_particles.add(start.back(), inverseMass, pbd::ParticleKind::Fluid);
    if (waiting > 0) m_circulation->startWaiting(m_particles, m_firstBloodParticle, waiting);
    m_bloodIds.resize(m_particles.size() - m_firstBloodParticle);
    for (std::size_t k = 0; k < m_bloodIds.size(); ++k) m_bloodIds[k] = Index(k);
    m_bloodOrigin.resize(m_bloodIds.size(), FlowRegion::Outside);
    if (m_circulation)
      for (std::size_t k = 0; k < m_bloodIds.size(); ++k) {
        const Index i = m_firstBloodParticle + Index(k);
        m_bloodOrigin[k] = m_circulation->parked(i) ? FlowRegion::Parked
                                                    : m_circulation->classify(m_particles.position[i]);
      }
    reorderBlood();
  }
}

// Blood particles drift away from their memory neighbours as they flow; sorting them along a
// Z-order curve of the grid cells now and then keeps the fluid solver's gathers from the
// particle arrays cache-friendly (its own solve already runs in cell order).
void HeartSimulation::reorderBlood() {
  const std::vector<pbd::Vec3> x(m_particles.position.begin() + m_firstBloodParticle, m_particles.position.end());
  const std::vector<Index> order = pbd::mortonOrder(x, m_scenario.blood.supportRadius);
  pbd::permuteRange(m_particles, m_firstBloodParticle, order);
  pbd::applyOrder(m_bloodIds, order);
  if (m_circulation) m_circulation->permute(order);
}

void HeartSimulation::step() {
  if (m_fluid && m_steps > 0 && m_steps % kReorderInterval == 0) reorderBlood();
  if (m_cycle) m_lastPhase = m_cycle->phase();
  if (m_circulation) m_circulation->beginStep(m_particles, m_firstBloodParticle, m_lastPhase, m_solver.dt);
  pbd::StepHooks hooks;
  hooks.afterPrediction = [this](pbd::Particles& p) {
    if (m_cycle) m_cycle->apply(p.position, p.predicted);
    if (m_fluid) m_fluid->projectDensity(p);
  };
  if (m_wallContact) {
    hooks.afterProjection = [this](pbd::Particles& p) {
      m_circulation->gateParticles(p, m_firstBloodParticle);
      m_wallContact->resolve(p, m_firstBloodParticle, Index(p.size()), wallContactSettings());
    };
  }
  if (m_fluid) hooks.postProcessVelocities = [this](pbd::Particles& p) { m_fluid->postProcessVelocities(p); };
  pbd::step(m_constraints, m_particles, m_solver, hooks);
  if (m_circulation) m_circulation->endStep(m_particles, m_firstBloodParticle, m_fluid->pressures());
  ++m_steps;
}

const std::vector<Real>& HeartSimulation::pressures() const {
  static const std::vector<Real> none;
  return m_fluid ? m_fluid->pressures() : none;
}

pbd::ParticleTetSettings HeartSimulation::wallContactSettings() const {
  pbd::ParticleTetSettings contact;
  contact.radius = m_scenario.blood.radius;
  contact.threads = m_threads;
  contact.twoWay = m_scenario.circulation.twoWay;
  contact.slip = m_scenario.circulation.wallSlip;
  return contact;
}

BloodStats HeartSimulation::bloodStats() const {
  BloodStats stats = measureBlood(m_scenario, m_particles, m_domainMin, m_domainMax, m_threads);
  if (m_wallContact)
    stats.insideWall = m_wallContact->countInside(m_particles.position, m_firstBloodParticle, Index(m_particles.size()),
                                                  Real(0.01) * m_scenario.blood.radius, m_threads);
  return stats;
}

Real HeartSimulation::cavityVolume() const {
  // Model vertex v is particle m_firstWallParticle + v; the wall is the first body, so the
  // particle positions are the model's vertex positions.
  return cardiac::cavityVolume(*m_model, m_particles.position);
}

TissueStats HeartSimulation::tissueStats() const {
  TissueStats stats;
  if (!m_model) return stats;
  const auto& x = m_particles.position;
  const Index f = m_firstWallParticle;
  double sum = 0;
  const auto& tets = m_model->mesh.tets;
  for (std::size_t i = 0; i < tets.size(); ++i) {
    const pbd::Tet& t = tets[i];
    const Real v = pbd::signedTetVolume(x[f + t[0]], x[f + t[1]], x[f + t[2]], x[f + t[3]]);
    const Real error = std::abs(v - m_restVolume[i]) / m_restVolume[i];
    stats.volumeErrorMax = std::max(stats.volumeErrorMax, error);
    sum += double(error);
    if (!(v > Real(0)) && stats.invertedTets++ == 0) stats.firstInvertedTet = static_cast<Index>(i);
  }
  stats.volumeErrorMean = tets.empty() ? Real(0) : Real(sum / double(tets.size()));
  for (std::size_t i = 0; i < m_particles.size(); ++i) {
    if (!m_particles.position[i].allFinite() || !m_particles.velocity[i].allFinite()) {
      stats.finite = false;
      stats.firstNonFinite = static_cast<Index>(i);
      break;
    }
  }
  return stats;
}

Real HeartSimulation::restDeviationRelative() const {
  if (!m_model) return 0;
  Real worst = 0;
  for (std::size_t v = 0; v < m_model->mesh.vertices.size(); ++v) {
    worst = std::max(worst, (m_particles.position[m_firstWallParticle + v] - m_model->mesh.vertices[v]).norm());
  }
  return worst / m_model->longAxisLength;
}

}  // namespace hs::cardiac
