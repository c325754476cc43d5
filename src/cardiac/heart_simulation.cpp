#include "cardiac/heart_simulation.h"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "cardiac/motion/ecg.h"
#include "cardiac/motion/heart_activation.h"

namespace hs::cardiac {

// One step, stage by stage (docs/architecture.md). Each stage is a named call; the engine's
// stages (pbd::) know nothing of hearts, the cardiac ones call into the engine.
// One-way, the wall's constraints come before the blood: the wall does not feel the blood, so
// it ends the step where they leave it either way, and the blood's iterations see it there, not
// where the cycle alone put it; the contacts then find the wall as the iterations did, with no
// second grid to build. Two-way, they come after the density solve: the blood's push on the wall
// is its contact with the wall the constraints moved into it (with them first, the iterations
// had already cleared the blood from the wall's final place, and the blood moved `normal`'s
// cavity by 0.01 mL at most in 10 s instead of 0.76).
void HeartSimulation::step() {
  const auto start = std::chrono::steady_clock::now();
  const pbd::StepContext context =
      pbd::makeStepContext(m_scenario.simulation.dt, m_scenario.simulation.gravity, m_governor.threads(), m_steps);
  m_contactSettings.threads = m_sweptSettings.threads = context.threads;
  StageLaps laps(m_profile);
  beginStep(context);                                                       // reorder, valves, flow meter
  laps.lap(StepStage::Begin);
  applyExternalForces(context);                                             // filling pressure, gravity
  pbd::predictPositions(m_particles, context);                              // p = x + dt v
  laps.lap(StepStage::Forces);
  moveWall(context);                                                        // cardiac cycle, vessels' ends
  laps.lap(StepStage::MoveWall);
  const bool twoWay = m_contactSettings.twoWay;  // circulation.two_way, with a heart and blood
  if (!twoWay) projectWall(context, laps);                                  // the wall's own constraints
  solveBloodDensity(context, laps);                                         // PBF, valves and wall inside
  if (twoWay) projectWall(context, laps);
  resolveBloodContacts(context);                                            // valves, wall push-out
  laps.lap(StepStage::Contacts);
  pbd::updateVelocities(m_particles, m_solver, context);                    // v = (p - x)/dt, x = p
  if (m_fluid) m_fluid->postProcessVelocities(m_particles, context);        // viscosity, XSPH
  laps.lap(StepStage::Velocities);
  endStep(context);                                                         // flows, the loop
  laps.lap(StepStage::End);
  if (m_profile) ++m_profile->steps;
  ++m_steps;
  if (m_recordedBeat) m_recordedBeat->observe(time(), double(cavityVolume()));
  m_governor.record(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

void HeartSimulation::projectWall(const pbd::StepContext& context, StageLaps& laps) {
  pbd::projectConstraints(m_constraints, m_particles, m_solver, context);
  laps.lap(StepStage::WallConstraints);
}

void HeartSimulation::beginStep(const pbd::StepContext& context) {
  if (m_fluid && context.stepIndex > 0 && context.stepIndex % kReorderInterval == 0) reorderBlood();
  if (m_cycle) m_lastPhase = m_cycle->phase();
  if (m_lumped) advanceLumpedCirculation(context);
  if (!m_circulation) return;
  if (m_lumped) {
    const CirculationSample& lumped = m_lumped->last();
    // The valves and the flow meter sit in the orifices where the base has carried them.
    const double descent = m_drivenWall->baseDescent(m_drivenWall->contraction());
    const FlowPath moved = m_model->flowPath.descended(Real(descent));
    m_circulation->valves.follow(moved);
    m_circulation->meter.follow(moved);
    // The vessels' ends take the lumped flows; the atrium's push is the inflow's plug.
    if (m_ends) m_ends->setFlows(lumped.mitralFlow, lumped.aorticFlow, (descent - m_lastBaseDescent) / double(context.dt));
    m_lastBaseDescent = descent;
    // A regurgitant valve lets blood back in 3D as in the lumped model.
    m_circulation->valves.follow({lumped.mitralFlow != 0, lumped.aorticOpen || lumped.aorticFlow < 0});
  } else {
    m_circulation->valves.decide(m_lastPhase, m_circulation->meter.lastStep().valvePressures);
  }
  m_circulation->meter.begin(m_particles, m_firstBloodParticle);
}

// Blood particles drift away from their memory neighbours as they flow; sorting them along a
// Z-order curve of the grid cells now and then keeps the fluid solver's gathers from the
// particle arrays cache-friendly (its own solve already runs in cell order). Every column
// moves, the ids with them.
void HeartSimulation::reorderBlood() {
  const std::vector<pbd::Vec3> x(m_particles.position.begin() + m_firstBloodParticle, m_particles.position.end());
  pbd::permuteRange(m_particles, m_firstBloodParticle, pbd::mortonOrder(x, m_scenario.blood.supportRadius));
}

// The lumped heart over this step, with the activation the clocks give before they advance.
void HeartSimulation::advanceLumpedCirculation(const pbd::StepContext& context) {
  const Activation activation =
      heartActivation(*m_cycle, m_regionShares, m_beatTiming, m_scenario.circulation.atrialContraction, context.dt);
  const double end = double(context.stepIndex + 1) * double(context.dt);
  m_lumped->advance(end, double(context.dt), activation);
}

// The filling pressure before gravity (the order of the two sums is part of the state). With the
// lumped circulation the inflow's plug (VesselEnds) is the atrium's push instead.
void HeartSimulation::applyExternalForces(const pbd::StepContext& context) {
  if (m_circulation && !m_lumped) m_circulation->filling.apply(m_particles, m_firstBloodParticle, context);
  pbd::applyExternalForces(m_particles, m_solver, context);
}

// The wall's motion (chosen at set-up), then, with the lumped circulation and blood, the
// vessels' ends.
void HeartSimulation::moveWall(const pbd::StepContext& context) {
  if (m_wallMotion) m_wallMotion->move(m_particles.position, m_particles.predicted, context);
  if (!m_ends) return;  // only the lumped circulation's blood has ends
  m_ends->drive(m_particles, m_firstBloodParticle, context.dt);  // the lumped flows at the vessels' ends
  m_circulation->loop.meterInlet(m_ends->inflowSpeed() * context.dt, context.dt);
}

// PBF's density iterations. The wall takes part in every one (closed valves first, the wall
// last: the closed-valve disc has the lumen's radius and the wall's faceted lumen lies a
// little inside it, so the wall has the final word): blood squeezed by the beating wall must
// not be pushed through it by its own pressure.
void HeartSimulation::solveBloodDensity(const pbd::StepContext& context, StageLaps& laps) {
  if (!m_fluid) return;
  if (!m_wallContact) {
    m_fluid->projectDensity(m_particles, context);
    laps.lap(StepStage::DensityKernels);
    return;
  }
  m_fluid->beginDensitySolve(m_particles, context);
  laps.lap(StepStage::Neighbours);
  if (!m_lumenSurface.empty()) lendWallDensity(context);
  laps.lap(StepStage::WallLending);
  for (int iteration = 0; iteration < m_fluid->iterations(); ++iteration) {
    m_fluid->iterateDensity(context);
    laps.lap(StepStage::DensityKernels);
    std::vector<Vec3>& points = m_fluid->workingPositions();
    m_circulation->valves.gatePoints(m_particles, points, m_fluid->slotParticles());
    m_wallContact->resolvePoints(m_particles, points, m_fluid->slotParticles(), m_contactSettings);
    if (m_ends) m_ends->hold(points, m_fluid->slotParticles());
    laps.lap(StepStage::WallInIterations);
  }
  m_fluid->endDensitySolve(m_particles, context);
  laps.lap(StepStage::DensityKernels);
}

// The wall's surface where it is about to be (its predictions) lends density to the blood
// beside it for this step's iterations.
void HeartSimulation::lendWallDensity(const pbd::StepContext& context) {
  // Model vertex v is particle m_firstWallParticle + v = v (the wall is the first body).
  m_fluid->lendWallDensity(m_particles.predicted, m_lumenSurface, context.threads);
}

// After the wall's constraints have moved it: the valves and the wall once more on the blood's
// predictions (thesis 4.4; two-way, the wall takes its share of the push).
void HeartSimulation::resolveBloodContacts(const pbd::StepContext&) {
  if (!m_wallContact) return;
  m_circulation->valves.gateParticles(m_particles, m_firstBloodParticle);
  // Two-way, the blood's push on the wall is what this contact moves it by: its cavity's change.
  const bool twoWay = m_contactSettings.twoWay;
  const double before = twoWay ? double(cardiac::cavityVolume(*m_model, m_particles.predicted)) : 0.0;
  m_wallContact->resolve(m_particles, m_firstBloodParticle, Index(m_particles.size()), m_contactSettings);
  if (twoWay) m_lastBloodPush = double(cardiac::cavityVolume(*m_model, m_particles.predicted)) - before;
  if (m_ends) m_ends->hold(m_particles);
  // blood.wall_contact = continuous: each particle's whole step, from where it started to where
  // it is now, against the wall moving from its start to its prediction, so that no step
  // crosses the wall into the tissue, however fast or thin (docs/heart-blood.md).
  if (m_sweptContact)
    m_sweptContact->resolve(m_particles, m_firstBloodParticle, Index(m_particles.size()), m_sweptSettings);
}

// What crossed where, then the loop: blood past a vessel's end waits, waiting blood re-enters.
void HeartSimulation::endStep(const pbd::StepContext& context) {
  if (!m_circulation) return;
  Circulation& c = *m_circulation;
  // Measurements only: the smoothed velocity over the solve's neighbour lists, read by the
  // flow meter's Doppler readings and the monitor's kinetic energy.
  m_fluid->smoothedVelocities(m_particles, m_smoothedVelocity, context.threads);
  c.meter.measure(m_particles, m_firstBloodParticle, m_fluid->pressures(), c.valves.states(), context.threads,
                  m_smoothedVelocity);
  const BloodLoop::Turnover turnover =
      c.settings.loop ? c.loop.circulate(m_particles, m_firstBloodParticle) : BloodLoop::Turnover{};
  c.meter.recordLoop(turnover.returned, turnover.reentered, c.loop.waiting());
}

double HeartSimulation::ecgMillivolts() const {
  if (!m_lumped || !m_cycle || m_cycle->regions().empty()) return std::numeric_limits<double>::quiet_NaN();
  const BeatClock& main = m_cycle->regions().front().clock;
  const Real dt = m_scenario.simulation.dt;
  const int since = main.stepsSinceSystoleStarted(dt), until = main.stepsUntilSystole(dt);
  return syntheticEcg(time(), since >= 0 ? double(since) * double(dt) : -1.0,
                      until >= 0 ? double(until) * double(dt) : -1.0, m_beatTiming,
                      m_scenario.circulation.atrialContraction);
}

bool HeartSimulation::wallCanYield() const {
  if (!m_model) return false;
  for (std::size_t v = 0; v < m_model->mesh.vertices.size(); ++v)
    if (m_model->region[v] == Region::Myocardium && m_particles.inverseMass[m_firstWallParticle + v] > 0) return true;
  return false;
}

double HeartSimulation::vesselFill() const {
  if (!m_circulation) return 1;
  const BloodSettings& b = m_scenario.blood;
  // With the lumped circulation the base has carried the vessels' roots down (the sites moved
  // only then: this runs every step).
  VesselSites moved;
  if (m_lumped) moved = m_vesselSites.descended(m_model->flowPath, Real(m_lastBaseDescent));
  const VesselSites& sites = m_lumped ? moved : m_vesselSites;
  // Blood farther below the lowest site than a kernel support adds nothing to any site.
  std::vector<Vec3> blood;
  for (std::size_t i = m_firstBloodParticle; i < m_particles.size(); ++i)
    if (m_particles.active(i) && m_particles.position[i].y() >= sites.lowest - b.supportRadius)
      blood.push_back(m_particles.position[i]);
  const double inflow = vesselFillShare(sites.inflow, sites.inflowFull, blood, b.spacing, b.supportRadius);
  const double outflow = vesselFillShare(sites.outflow, sites.outflowFull, blood, b.spacing, b.supportRadius);
  return std::min(inflow, outflow);
}

const std::vector<Real>& HeartSimulation::pressures() const {
  static const std::vector<Real> none;
  return m_fluid ? m_fluid->pressures() : none;
}

BloodStats HeartSimulation::bloodStats() const {
  const pbd::FluidStats fluid = m_fluid->measure(m_particles, m_scenario.blood.spacing, m_threads);
  BloodStats stats = measureBlood(m_particles, fluid, m_domainMin, m_domainMax);
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
