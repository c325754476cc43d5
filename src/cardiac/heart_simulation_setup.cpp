// HeartSimulation's set-up: the wall, the circulation that drives it, the blood, chosen once from
// the scenario (the step, heart_simulation.cpp, asks the scenario nothing it could ask here).
#include "cardiac/heart_simulation.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <memory>

#include "cardiac/motion/heart_activation.h"
#include "cardiac/patient/patient_lv_model.h"
#include "cardiac/patient/patient_vessels.h"
#include "pbd/core/soft_body.h"

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

// The vessels a patient's heart with blood gets (patient_vessels.h), sized by the scenario.
PatientVesselSizes vesselSizes(const Scenario& scenario, const std::string& resolution) {
  const LvGeometryParams& g = scenario.geometry;
  PatientVesselSizes sizes;
  sizes.inflowLength = g.inflowVesselLength;
  sizes.outflowLength = g.outflowVesselLength;
  sizes.wallThickness = g.vesselWallThickness;
  sizes.edge = Real(wallResolution(resolution).edgeLength);
  return sizes;
}

// Whether the wall at `resolution` follows the scenario's recording: built as the run would
// build it (with the vessels when there is blood) and driven through one beat (findFold).
// A resolution whose wall or vessels cannot be built at all does not follow it either.
bool wallFollowsRecording(const Scenario& scenario, const std::string& resolution) {
  PatientModelSettings patient = scenario.patient;
  patient.resolution = resolution;
  try {
    const PatientWall wall = buildPatientShell(patient, scenario.geometry.wallThickness);
    LvModel model = lvModelFromPatientWall(wall);
    if (scenario.blood.enabled) attachPatientVessels(model, vesselSizes(scenario, resolution));
    const RecordedBeat beat(model, wall, scenario.motion.frameSurfaces, double(scenario.motion.period), 0);
    const RecordedFold fold = beat.findFold(double(scenario.simulation.dt));
    return fold.tets == 0 && fold.triangles == 0;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

// One line for a recording the wall cannot follow: which frames, how many tets of which AHA
// segments, and which of the other resolutions would follow it (each tried as above).
std::string refusal(const Scenario& scenario, const RecordedFold& fold) {
  const std::string& resolution = scenario.patient.resolution;
  std::ostringstream s;
  s.precision(3);
  s << "motion.frames: the " << resolution << " wall (" << wallResolution(resolution).edgeLength * 1e3
    << " mm edges) cannot follow frames " << fold.firstFrame;
  if (fold.lastFrame != fold.firstFrame) s << "-" << fold.lastFrame;
  s << " of the recording: ";
  if (fold.triangles > 0) s << fold.triangles << " endocardial triangles turn over (the surface folds)";
  if (fold.triangles > 0 && fold.tets > 0) s << " and ";
  if (fold.tets > 0) s << fold.tets << " tetrahedra turn inside out";
  s << " in AHA segment" << (fold.segments.size() > 1 ? "s " : " ");
  for (std::size_t k = 0; k < fold.segments.size(); ++k) s << (k ? ", " : "") << fold.segments[k];
  s << ", the first at t = " << fold.firstTime << " s; ";
  std::vector<std::string> follow;
  for (const std::string other : {"coarse", "default", "fine"})
    if (other != resolution && wallFollowsRecording(scenario, other)) follow.push_back(other);
  if (follow.empty()) return s.str() + "no wall resolution (coarse, default, fine) follows it";
  s << "model.mesh_resolution = \"" << follow[0] << "\" follows it";
  if (follow.size() > 1) s << " (and \"" << follow[1] << "\")";
  return s.str();
}

}  // namespace

HeartSimulation::HeartSimulation(const Scenario& scenario, int threads)
    : m_scenario(scenario), m_threads(threads), m_governor(threads) {
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
  chooseWallMotion();
  assert(m_firstWallParticle == 0 && "cavityVolume reads particle positions as model vertices");
  m_restVolume.reserve(model.mesh.tets.size());
  for (const pbd::Tet& t : model.mesh.tets) {
    const auto& x = model.mesh.vertices;
    m_restVolume.push_back(pbd::signedTetVolume(x[t[0]], x[t[1]], x[t[2]], x[t[3]]));
  }
}

// The one thing that moves the wall each step (wall_motion.h): a recorded beat, the lumped
// circulation's volume, or the cycle alone.
void HeartSimulation::chooseWallMotion() {
  if (m_recordedBeat)
    m_wallMotion = std::make_unique<RecordedBeatMotion>(*m_cycle, *m_recordedBeat);
  else if (m_drivenWall)
    m_wallMotion = std::make_unique<VolumeFollowingMotion>(*m_cycle, *m_drivenWall, *m_lumped);
  else
    m_wallMotion = std::make_unique<PrescribedCycleMotion>(*m_cycle);
}

// A patient's heart with blood gets the vessels it enters and leaves by (patient_vessels.h).
void HeartSimulation::attachVessels() {
  try {
    attachPatientVessels(*m_model, vesselSizes(m_scenario, m_scenario.patient.resolution));
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
  // The recording drives the whole wall, so a tet it would turn inside out is found here, before
  // the first step, rather than by the run stopping at it.
  const RecordedFold fold = m_recordedBeat->findFold(double(m_scenario.simulation.dt));
  if (fold.tets > 0 || fold.triangles > 0) throw std::invalid_argument(refusal(m_scenario, fold));
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
    // swept check of every blood step against the moving wall (pbd/contact/swept_contact.h).
    if (b.wallContact == BloodSettings::WallContact::Continuous)
      m_sweptContact = std::make_unique<pbd::SweptContact>(pbd::boundaryFaces(m_model->mesh.tets), m_particles.position);
    // blood.wall_density: the faces blood touches, all of whose vertices are wetted, lend it
    // their density (none: the wall lends none).
    if (b.wallDensity)
      for (const pbd::Triangle& t : m_model->surface)
        if (wetted[t[0]] && wetted[t[1]] && wetted[t[2]]) m_lumenSurface.push_back(t);
    m_circulation.emplace(*m_model, m_scenario);
    m_contactSettings.radius = b.radius;
    m_contactSettings.twoWay = m_scenario.circulation.twoWay;
    m_contactSettings.slip = m_scenario.circulation.wallSlip;
    m_sweptSettings.radius = b.radius;
    m_sweptSettings.slip = m_scenario.circulation.wallSlip;
    if (m_lumped) m_ends.emplace(m_model->flowPath, m_scenario.blood);
    // The vessels' fill is measured on their lumens between the ends' buffers.
    m_vesselSites = vesselSites(m_scenario, *m_model);
    if (m_ends) m_vesselSites.drop([&](const Vec3& site) { return m_ends->inBuffer(site); });
    if (m_lumped && m_scenario.circulation.aorticValveArea > 0) {
      const Real opening = std::sqrt(m_scenario.circulation.aorticValveArea / std::numbers::pi_v<Real>);
      m_circulation->valves.narrowAorticOpening(opening);
      m_circulation->meter.narrowAorticOpening(opening);
    }
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

}  // namespace hs::cardiac
