#include "cardiac/heart_simulation.h"

#include <cassert>
#include <cmath>
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

namespace {
// Blood (the PBF stage) is not simulated yet: asking for it must not be silently ignored.
const Scenario& checkSupported(const Scenario& scenario) {
  if (scenario.blood.enabled)
    throw std::invalid_argument("blood.enabled: blood is not simulated in this version yet; set it to false");
  return scenario;
}
}  // namespace

HeartSimulation::HeartSimulation(const Scenario& scenario, int threads)
    : m_scenario(checkSupported(scenario)),
      m_model(buildLvModel(scenario.geometry)),
      m_firstWallParticle(buildWall(m_scenario, m_model, m_particles, m_constraints)),
      m_cycle(scenario.cycle, m_model, m_firstWallParticle, scenario.simulation.dt) {
  m_solver.dt = scenario.simulation.dt;
  m_solver.iterations = scenario.simulation.iterations;
  m_solver.volumePasses = scenario.simulation.volumePasses;
  m_solver.gravity = scenario.simulation.gravity;
  m_solver.gravityScale[static_cast<std::size_t>(pbd::ParticleKind::Tissue)] = scenario.tissue.gravity ? 1 : 0;
  m_solver.damping = scenario.tissue.damping;
  m_solver.threads = threads;
  assert(m_firstWallParticle == 0 && "cavityVolume reads particle positions as model vertices");
  m_restVolume.reserve(m_model.mesh.tets.size());
  for (const pbd::Tet& t : m_model.mesh.tets) {
    const auto& x = m_model.mesh.vertices;
    m_restVolume.push_back(pbd::signedTetVolume(x[t[0]], x[t[1]], x[t[2]], x[t[3]]));
  }
}

void HeartSimulation::step() {
  m_lastPhase = m_cycle.phase();
  pbd::StepHooks hooks;
  hooks.afterPrediction = [this](pbd::Particles& p) { m_cycle.apply(p.position, p.predicted); };
  pbd::step(m_constraints, m_particles, m_solver, hooks);
  ++m_steps;
}

Real HeartSimulation::cavityVolume() const {
  // Model vertex v is particle m_firstWallParticle + v; the wall is the first body, so the
  // particle positions are the model's vertex positions.
  return cardiac::cavityVolume(m_model, m_particles.position);
}

TissueStats HeartSimulation::tissueStats() const {
  TissueStats stats;
  const auto& x = m_particles.position;
  const Index f = m_firstWallParticle;
  double sum = 0;
  for (std::size_t i = 0; i < m_model.mesh.tets.size(); ++i) {
    const pbd::Tet& t = m_model.mesh.tets[i];
    const Real v = pbd::signedTetVolume(x[f + t[0]], x[f + t[1]], x[f + t[2]], x[f + t[3]]);
    const Real error = std::abs(v - m_restVolume[i]) / m_restVolume[i];
    stats.volumeErrorMax = std::max(stats.volumeErrorMax, error);
    sum += double(error);
    if (!(v > Real(0)) && stats.invertedTets++ == 0) stats.firstInvertedTet = static_cast<Index>(i);
  }
  stats.volumeErrorMean = m_model.mesh.tets.empty() ? Real(0) : Real(sum / double(m_model.mesh.tets.size()));
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
  Real worst = 0;
  for (std::size_t v = 0; v < m_model.mesh.vertices.size(); ++v) {
    worst = std::max(worst, (m_particles.position[m_firstWallParticle + v] - m_model.mesh.vertices[v]).norm());
  }
  return worst / m_model.longAxisLength;
}

}  // namespace hs::cardiac
