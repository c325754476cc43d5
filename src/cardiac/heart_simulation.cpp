#include "cardiac/heart_simulation.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "cardiac/heart_activation.h"
#include "cardiac/patient_lv_model.h"
#include "cardiac/patient_vessels.h"
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

// The most a beating vertex may travel inward in one systole (cycle.contraction, physiological
// mode), as a share of the cavity's size (the radius of a sphere of the cavity's rest volume):
// beyond it the one-tet-thick wall folds and its tets invert. Measured on `normal` without the
// lumped circulation (docs/reliability.md): a third of it (0.0104 m) beats for 3 s, 0.011 m
// (0.35) inverts a tet at 0.24 s.
constexpr double kMaxContractionShare = 1.0 / 3.0;

void checkContraction(const CycleSettings& cycle, const LvModel& model) {
  if (!cycle.enabled || cycle.mode != TimingMode::Physiological) return;
  const double volume = double(cavityVolume(model, model.mesh.vertices));
  const double size = std::cbrt(3 * volume / (4 * std::numbers::pi));
  const double limit = kMaxContractionShare * size;
  if (double(cycle.contraction) <= limit) return;
  std::ostringstream message;
  message.precision(3);
  message << "cycle.contraction: " << double(cycle.contraction) << " m folds this wall; expected at most " << limit
          << " m, a third of the cavity's size (" << size << " m, the radius of a sphere of its volume)";
  throw std::invalid_argument(message.str());
}

}  // namespace

HeartSimulation::HeartSimulation(const Scenario& scenario, int threads)
    : m_scenario(scenario), m_threads(threads) {
  if (!scenario.heart && !scenario.blood.enabled)
    throw std::invalid_argument("model.enabled: with no heart and no blood (blood.enabled = false) there is "
                                "nothing to simulate");
  m_solver.iterations = scenario.simulation.iterations;
  m_solver.volumePasses = scenario.simulation.volumePasses;
  m_solver.gravityScale[static_cast<std::size_t>(pbd::ParticleKind::Tissue)] = scenario.tissue.gravity ? 1 : 0;
  m_solver.damping[static_cast<std::size_t>(pbd::ParticleKind::Tissue)] = scenario.tissue.damping;
  if (scenario.heart) buildHeart();
  m_firstBloodParticle = Index(m_particles.size());
  findDomain();
  if (scenario.blood.enabled) buildBlood();
}

// The wall: the LV model's vertices as the first particles, its constraints, the cycle.
void HeartSimulation::buildHeart() {
  std::optional<PatientWall> patientWall;
  if (m_scenario.patient.kind == ModelKind::Mesh) {
    patientWall.emplace(buildPatientShell(m_scenario.patient, m_scenario.geometry.wallThickness));
    m_model.emplace(lvModelFromPatientWall(*patientWall));
    if (m_scenario.blood.enabled) attachVessels();
  } else {
    m_model.emplace(buildLvModel(m_scenario.geometry));
  }
  const LvModel& model = *m_model;
  m_firstWallParticle = pbd::addSoftBody(m_particles, m_constraints, model.mesh, model.surface,
                                         softBodySettings(m_scenario.tissue));
  for (Index v : model.pinned) m_particles.inverseMass[m_firstWallParticle + v] = 0;
  pbd::finalizeConstraints(m_constraints, m_particles.position);
  if (patientWall && !m_scenario.motion.frameSurfaces.empty()) {
    buildRecordedBeat(*patientWall);
  } else if (m_scenario.circulation.lumped) {
    buildLumpedCirculation();
  } else {
    checkContraction(m_scenario.cycle, model);
    m_cycle.emplace(m_scenario.cycle, model, m_firstWallParticle);
    // The held shell (cycle.base_held) moves its beating vertices alone, except where the blood
    // must push them (two-way coupling): the blood's push is its contact with the wall the
    // constraints moved into it (step()), so they keep their mass and their constraints.
    if (m_cycle->kinematic() && !m_scenario.circulation.twoWay)
      for (const BeatingRegion& region : m_cycle->regions())
        for (Index p : region.particles) m_particles.inverseMass[p] = 0;
  }
  assert(m_firstWallParticle == 0 && "cavityVolume reads particle positions as model vertices");
  m_restVolume.reserve(model.mesh.tets.size());
  for (const pbd::Tet& t : model.mesh.tets) {
    const auto& x = model.mesh.vertices;
    m_restVolume.push_back(pbd::signedTetVolume(x[t[0]], x[t[1]], x[t[2]], x[t[3]]));
  }
}

// A patient's heart with blood gets the vessels it enters and leaves by (patient_vessels.h).
void HeartSimulation::attachVessels() {
  const LvGeometryParams& g = m_scenario.geometry;
  PatientVesselSizes sizes;
  sizes.inflowLength = g.inflowVesselLength;
  sizes.outflowLength = g.outflowVesselLength;
  sizes.wallThickness = g.vesselWallThickness;
  sizes.edge = Real(wallResolution(m_scenario.patient.resolution).edgeLength);
  try {
    attachPatientVessels(*m_model, sizes);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(patientModelFile(m_scenario.patient) + ": " + e.what());
  }
}

// The lumped circulation times the beat (the activation's length from the heart rate, irregular
// beats both ways), drives the wall through the cavity volume and starts from the wall's rest volume.
void HeartSimulation::buildLumpedCirculation() {
  const LvModel& model = *m_model;
  const CirculationSettings& c = m_scenario.circulation;
  if (m_scenario.cycle.mode != TimingMode::Physiological || !m_scenario.cycle.enabled)
    throw std::invalid_argument("circulation.lumped: the lumped circulation needs a beating heart with "
                                "cycle.mode = \"physiological\"");
  CycleSettings cycle = m_scenario.cycle;
  m_beatTiming = beatTimingForRate(double(cycle.heartRateBpm));
  // The clock's systole is the ventricle's activation, contraction and relaxation.
  const double activation = m_beatTiming.contraction + m_beatTiming.relaxation;
  cycle.systolicFraction = Real(std::min(0.9, activation * double(cycle.heartRateBpm) / 60.0));
  cycle.irregularBothWays = true;
  m_cycle.emplace(cycle, model, m_firstWallParticle);
  m_regionShares = regionShares(*m_cycle, model, m_firstWallParticle);
  // The lumped valves open and close on the lumped pressures: valves by pressure, whatever the
  // 3D blood's gauge says. Another mode would be silently ignored, so it is refused.
  if (c.valveMode != ValveMode::Pressure)
    throw std::invalid_argument(std::string("circulation.valves: with circulation.lumped = true the valves open and "
                                            "close on the lumped circulation's pressures; expected \"pressure\", got \"") +
                                (c.valveMode == ValveMode::Timing ? "timing" : "open") + "\"");
  // The vessels' ends pass the lumped flows in and out of the model: blood leaving through the
  // aorta must come back through the inflow vessel (open, `normal` lost blood at 0.16 s).
  if (m_scenario.blood.enabled && !c.loop)
    throw std::invalid_argument("circulation.loop: with circulation.lumped = true the vessels' ends pass the lumped "
                                "flows in and out of the model, which needs the closed loop; expected true");
  m_drivenWall.emplace(model, selectBeatingVertices(cycle, model), m_firstWallParticle, c.wallMotion);
  // The driven wall is kinematic: its motion is the contraction's, not its constraints'.
  for (Index v : m_drivenWall->drivenVertices()) m_particles.inverseMass[m_firstWallParticle + v] = 0;
  // Two-way coupling moves only vertices with mass: where the lumped circulation drives all of
  // them, the switch would change nothing, so it is refused rather than ignored.
  if (c.twoWay && !wallCanYield())
    throw std::invalid_argument(
        "circulation.two_way: the lumped circulation drives every vertex of this wall (its volume sets the "
        "wall's shape), so the blood cannot push it back; two-way coupling needs circulation.lumped = false or "
        "segments that do not beat (cycle.segments)");

  LumpedParameters p = c.lumpedParameters;
  constexpr double pi = std::numbers::pi;
  p.pulmonaryVenousPressure = double(c.atrialPressureMmHg) * kPascalPerMmHg;
  p.mitralArea = pi * double(model.params.mitralRadius) * double(model.params.mitralRadius);
  p.aorticRootArea = pi * double(model.params.aorticRadius) * double(model.params.aorticRadius);
  p.aorticArea = c.aorticValveArea > 0 ? double(c.aorticValveArea) : p.aorticRootArea;
  if (p.aorticArea > p.aorticRootArea * (1 + 1e-9))
    throw std::invalid_argument("circulation.aortic_valve_area_cm2: got " + std::to_string(p.aorticArea * 1e4) +
                                ", expected no more than the aortic vessel's lumen, " +
                                std::to_string(p.aorticRootArea * 1e4) + " cm^2 (model.aortic_radius)");
  if (m_scenario.blood.enabled) p.bloodDensity = double(m_scenario.blood.restDensity);
  m_lumped.emplace(p);
  m_lumped->startFrom(double(cardiac::cavityVolume(model, model.mesh.vertices)));
}

// [motion]: the recorded beat moves the endocardium (kinematic), the cycle's clock only keeps
// its time: a regular beat of the recording's period whose systole ends at the recording's
// smallest volume, so that the beats' EDV and ESV are the recording's.
void HeartSimulation::buildRecordedBeat(const PatientWall& wall) {
  const MotionSettings& motion = m_scenario.motion;
  m_recordedBeat.emplace(*m_model, wall, motion.frameSurfaces, double(motion.period), m_firstWallParticle);
  const double systole = m_recordedBeat->systolicFraction();
  if (!(systole >= 0.05 && systole <= 0.95))
    throw std::invalid_argument("motion.frames: the smallest recorded volume is at frame " +
                                std::to_string(int(std::lround(systole * motion.count))) + " of " +
                                std::to_string(motion.count) +
                                "; expected frame 0 at end-diastole and end-systole between 5% and 95% of the beat");
  CycleSettings cycle = m_scenario.cycle;
  cycle.mode = TimingMode::Physiological;
  cycle.heartRateBpm = Real(60.0 / double(motion.period));
  cycle.systolicFraction = Real(systole);
  m_cycle.emplace(cycle, *m_model, m_firstWallParticle);
  for (Index v : m_recordedBeat->drivenVertices()) m_particles.inverseMass[m_firstWallParticle + v] = 0;
}

// Blood beyond this box is lost: the container, or the heart's rest bounding box grown by a
// quarter of its long axis (blood that left through a vessel's open end).
void HeartSimulation::findDomain() {
  if (m_scenario.container.enabled) {
    const Vec3 r = Vec3::Constant(m_scenario.blood.radius);
    m_domainMin = m_scenario.container.min - r;
    m_domainMax = m_scenario.container.max + r;
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
}

// The blood particles after the wall, its solver and, with a heart, the wall contact and the
// circulation.
void HeartSimulation::buildBlood() {
  // A start block beyond the domain would be lost at the first step (after filling a lattice
  // sized for another scene): refused before any work.
  const BloodSettings& b = m_scenario.blood;
  if (b.start == BloodSettings::Start::Block &&
      ((b.blockMin.array() < m_domainMin.array()).any() || (b.blockMax.array() > m_domainMax.array()).any())) {
    std::ostringstream message;
    message.precision(3);
    const auto box = [&](const Vec3& lo, const Vec3& hi) {
      message << "[" << lo.x() << ", " << lo.y() << ", " << lo.z() << "]..[" << hi.x() << ", " << hi.y() << ", "
              << hi.z() << "] m";
    };
    message << "blood.block_min, blood.block_max: the start block ";
    box(b.blockMin, b.blockMax);
    message << " reaches outside the domain the blood may stay in, ";
    box(m_domainMin, m_domainMax);
    message << (m_model ? " (around the heart); put it inside or choose another blood.start"
                        : " (the container); put it inside");
    throw std::invalid_argument(message.str());
  }
  // The start block first: it checks the particle count against memory before anything else
  // is allocated; then the solver settings check the remaining parameters.
  const std::vector<pbd::Vec3> start = bloodStartPositions(m_scenario, m_model ? &*m_model : nullptr);
  if (m_model) {
    m_wallContact = std::make_unique<pbd::ParticleTetCollider>(m_model->mesh.tets, m_firstWallParticle);
    // Blood lives on the shell's inner side (the cavity and the vessel lumens): the inner
    // layer's vertices, 2i (lv_model.h).
    std::vector<std::uint8_t> wetted(m_model->mesh.vertices.size(), 0);
    for (std::size_t v = 0; v < wetted.size(); v += 2) wetted[v] = 1;
    m_wallContact->setWettedVertices(wetted);
    // Two-way, the blood pushes the myocardium back; the base plate and the vessels, thin and
    // light, are held as the body holds them (many particles pressing on one light vertex at
    // once over-push it: an outflow-vessel tet inverted at 0.2 s of `normal`, docs/heart-blood.md).
    std::vector<std::uint8_t> yielding(m_model->mesh.vertices.size(), 0);
    for (std::size_t v = 0; v < yielding.size(); ++v) yielding[v] = m_model->region[v] == Region::Myocardium;
    m_wallContact->setYieldingVertices(std::move(yielding));
    // The wall's whole boundary (outward, particle ids: the wall is the first body), for the
    // swept check of every blood step against the moving wall (pbd/swept_contact.h).
    if (m_scenario.blood.wallContact == BloodSettings::WallContact::Continuous)
      m_sweptContact = std::make_unique<pbd::SweptContact>(pbd::boundaryFaces(m_model->mesh.tets), m_particles.position);
    // The faces blood touches, all of whose vertices are wetted: they lend it their density.
    for (const pbd::Triangle& t : m_model->surface)
      if (wetted[t[0]] && wetted[t[1]] && wetted[t[2]]) m_lumenSurface.push_back(t);
    m_circulation.emplace(*m_model, m_scenario);
    if (m_lumped) m_ends.emplace(m_model->flowPath, m_scenario.blood);
    // The vessels' fill is measured on their lumens between the ends' buffers.
    m_vesselSites = vesselSites(m_scenario, *m_model);
    if (m_ends) m_vesselSites.drop([&](const Vec3& site) { return m_ends->inBuffer(site); });
    if (m_lumped && m_scenario.circulation.aorticValveArea > 0)
      m_circulation->valves.narrowAorticOpening(std::sqrt(m_scenario.circulation.aorticValveArea / std::numbers::pi_v<Real>));
  }
  m_fluid = std::make_unique<pbd::FluidSolver>(bloodSolverSettings(m_scenario));
  const Real inverseMass = Real(1) / m_fluid->settings().fluid.particleMass;
  for (const pbd::Vec3& x : start) m_particles.add(x, inverseMass, pbd::ParticleKind::Fluid);
  // Blood the start sites cannot hold begins in the body, waiting to enter (closed loop).
  const std::size_t wanted = m_scenario.blood.particles > 0 ? std::size_t(m_scenario.blood.particles) : 0;
  const std::size_t waiting = wanted > start.size() ? wanted - start.size() : 0;
  for (std::size_t k = 0; k < waiting; ++k) m_particles.add(start.back(), inverseMass, pbd::ParticleKind::Fluid);
  if (waiting > 0) m_circulation->loop.startWaiting(m_particles, m_firstBloodParticle, waiting);
  recordBloodOrigins();
  reorderBlood();
}

// Where each blood particle starts (bloodOrigin), by id, before any reordering.
void HeartSimulation::recordBloodOrigins() {
  if (!m_circulation) return;
  const FlowPath& path = m_model->flowPath;
  m_bloodOrigin.resize(m_particles.size() - m_firstBloodParticle);
  for (std::size_t i = m_firstBloodParticle; i < m_particles.size(); ++i)
    m_bloodOrigin[i - m_firstBloodParticle] =
        m_particles.active(i) ? path.classify(m_particles.position[i], m_scenario.blood.radius, m_scenario.blood.spacing)
                              : FlowRegion::Parked;
}

// Blood particles drift away from their memory neighbours as they flow; sorting them along a
// Z-order curve of the grid cells now and then keeps the fluid solver's gathers from the
// particle arrays cache-friendly (its own solve already runs in cell order). Every column
// moves, the ids with them.
void HeartSimulation::reorderBlood() {
  const std::vector<pbd::Vec3> x(m_particles.position.begin() + m_firstBloodParticle, m_particles.position.end());
  pbd::permuteRange(m_particles, m_firstBloodParticle, pbd::mortonOrder(x, m_scenario.blood.supportRadius));
}

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
  const pbd::StepContext context =
      pbd::makeStepContext(m_scenario.simulation.dt, m_scenario.simulation.gravity, m_threads, m_steps);
  StageLaps laps(m_profile);
  beginStep(context);                                                       // reorder, valves, flow meter
  laps.lap(StepStage::Begin);
  applyExternalForces(context);                                             // filling pressure, gravity
  pbd::predictPositions(m_particles, context);                              // p = x + dt v
  laps.lap(StepStage::Forces);
  moveWall(context);                                                        // cardiac cycle, vessels' ends
  laps.lap(StepStage::MoveWall);
  const bool twoWay = m_scenario.circulation.twoWay;
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

void HeartSimulation::moveWall(const pbd::StepContext& context) {
  if (!m_cycle) return;
  if (m_recordedBeat) {
    m_cycle->advanceClocks(context.dt);
    m_recordedBeat->drive(double(context.stepIndex + 1) * double(context.dt), m_particles.predicted);
    return;
  }
  if (!m_drivenWall) {
    m_cycle->apply(m_particles.position, m_particles.predicted, context);
    return;
  }
  m_cycle->advanceClocks(context.dt);
  m_drivenWall->drive(m_particles.position, m_particles.predicted, m_lumped->last().lvVolume);
  if (!m_ends) return;  // no blood
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
  const pbd::ParticleTetSettings contact = wallContactSettings(context);
  m_fluid->beginDensitySolve(m_particles, context);
  laps.lap(StepStage::Neighbours);
  if (m_scenario.blood.wallDensity) lendWallDensity(context);
  laps.lap(StepStage::WallLending);
  for (int iteration = 0; iteration < m_fluid->iterations(); ++iteration) {
    m_fluid->iterateDensity(context);
    laps.lap(StepStage::DensityKernels);
    std::vector<Vec3>& points = m_fluid->workingPositions();
    m_circulation->valves.gatePoints(m_particles, points, m_fluid->slotParticles());
    m_wallContact->resolvePoints(m_particles, points, m_fluid->slotParticles(), contact);
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
void HeartSimulation::resolveBloodContacts(const pbd::StepContext& context) {
  if (!m_wallContact) return;
  m_circulation->valves.gateParticles(m_particles, m_firstBloodParticle);
  // Two-way, the blood's push on the wall is what this contact moves it by: its cavity's change.
  const bool twoWay = m_scenario.circulation.twoWay;
  const double before = twoWay ? double(cardiac::cavityVolume(*m_model, m_particles.predicted)) : 0.0;
  m_wallContact->resolve(m_particles, m_firstBloodParticle, Index(m_particles.size()), wallContactSettings(context));
  if (twoWay) m_lastBloodPush = double(cardiac::cavityVolume(*m_model, m_particles.predicted)) - before;
  if (m_ends) m_ends->hold(m_particles);
  // blood.wall_contact = continuous: each particle's whole step, from where it started to where
  // it is now, against the wall moving from its start to its prediction, so that no step
  // crosses the wall into the tissue, however fast or thin (docs/heart-blood.md).
  if (m_sweptContact) {
    pbd::SweptContactSettings swept;
    swept.radius = m_scenario.blood.radius;
    swept.slip = m_scenario.circulation.wallSlip;
    swept.threads = context.threads;
    m_sweptContact->resolve(m_particles, m_firstBloodParticle, Index(m_particles.size()), swept);
  }
}

// What crossed where, then the loop: blood past a vessel's end waits, waiting blood re-enters.
void HeartSimulation::endStep(const pbd::StepContext&) {
  if (!m_circulation) return;
  Circulation& c = *m_circulation;
  c.meter.measure(m_particles, m_firstBloodParticle, m_fluid->pressures(), c.valves.states(), m_threads);
  const BloodLoop::Turnover turnover =
      c.settings.loop ? c.loop.circulate(m_particles, m_firstBloodParticle) : BloodLoop::Turnover{};
  c.meter.recordLoop(turnover.returned, turnover.reentered, c.loop.waiting());
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

pbd::ParticleTetSettings HeartSimulation::wallContactSettings(const pbd::StepContext& context) const {
  pbd::ParticleTetSettings contact;
  contact.radius = m_scenario.blood.radius;
  contact.threads = context.threads;
  contact.twoWay = m_scenario.circulation.twoWay;
  contact.slip = m_scenario.circulation.wallSlip;
  return contact;
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
