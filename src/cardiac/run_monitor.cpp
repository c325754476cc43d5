#include "cardiac/run_monitor.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "pbd/core/solver.h"
#include "pbd/core/tet_mesh.h"

namespace hs::cardiac {
namespace {

const char* regionName(Region region) {
  switch (region) {
    case Region::Myocardium: return "myocardium";
    case Region::BasePlate: return "base plate";
    case Region::InflowVessel: return "inflow vessel";
    case Region::OutflowVessel: return "outflow vessel";
  }
  return "?";
}

}  // namespace

std::string Verdict::message() const {
  std::ostringstream s;
  s << "simulation became invalid at step " << step << " (t = " << time << " s): " << issue.what;
  return s.str();
}

std::string tetLocation(const LvModel& model, std::span<const Vec3> positions, Index tet) {
  const Index v = model.mesh.tets[tet][0];
  const Vec3& x = positions[v];
  std::ostringstream s;
  s.precision(3);
  s << "x = " << x.x() << ", y = " << x.y() << ", z = " << x.z() << " m, ";
  if (model.region[v] == Region::Myocardium) s << "AHA segment " << int(model.segment[v]);
  else s << regionName(model.region[v]);
  return s.str();
}

HealthIssue checkTissue(const TissueStats& tissue, bool cavityFinite, const LvModel* model,
                        std::span<const Vec3> positions) {
  if (!tissue.finite || !cavityFinite)
    return {HealthCheck::NonFinite,
            "particle " + std::to_string(tissue.firstNonFinite) + " has a non-finite position or velocity"};
  if (tissue.invertedTets == 0) return {};
  std::string what = std::to_string(tissue.invertedTets) + " wall tetrahedra inverted (first: tet " +
                     std::to_string(tissue.firstInvertedTet);
  if (model) what += " at " + tetLocation(*model, positions, tissue.firstInvertedTet);
  return {HealthCheck::InvertedTets, what + ")"};
}

HealthIssue checkBlood(const BloodStats& blood, const HealthLimits& limits) {
  if (blood.lost > limits.bloodLost) {
    std::ostringstream s;
    s.precision(3);
    const Vec3& x = blood.firstLostAt;
    s << blood.lost << " of " << blood.particles << " blood particles lost outside the domain (first at x = " << x.x()
      << ", y = " << x.y() << ", z = " << x.z() << " m; blood.loss_allowed = " << limits.bloodLost << ")";
    return {HealthCheck::BloodLost, s.str()};
  }
  if (blood.insideWall > limits.bloodInsideWall)
    return {HealthCheck::BloodInsideWall, std::to_string(blood.insideWall) + " of " +
                                              std::to_string(blood.particles) +
                                              " blood particles inside the wall's tetrahedra (limit " +
                                              std::to_string(limits.bloodInsideWall) + ")"};
  return {};
}

void RunExtremes::add(const StepSample& sample, bool heart) {
  smoothedSpeedMax = std::max(smoothedSpeedMax, sample.smoothedSpeedMax);
  if (heart) {
    volumeErrorMax = std::max(volumeErrorMax, double(sample.tissue.volumeErrorMax));
    volumeErrorMeanSum += double(sample.tissue.volumeErrorMean);
    surfaceTurnMax = std::max(surfaceTurnMax, sample.surfaceTurn);
    bloodPushMax = std::max(bloodPushMax, std::abs(sample.bloodPush));
    bloodPushSum += std::abs(sample.bloodPush);
    cavityMin = std::min(cavityMin, sample.cavity);
    cavityMax = std::max(cavityMax, sample.cavity);
  }
  if (!sample.blood) return;
  const BloodStats& blood = *sample.blood;
  bloodLostMax = std::max(bloodLostMax, blood.lost);
  bloodInsideWallMax = std::max(bloodInsideWallMax, blood.insideWall);
  bloodSpeedMax = std::max(bloodSpeedMax, blood.maxSpeed);
  if (sample.time > lastSecondFrom) {
    densityErrorMeanSum += blood.densityErrorMean;
    densityErrorMax = std::max(densityErrorMax, blood.densityErrorMax);
    ++lastSecondSteps;
  }
}

RunMonitor::RunMonitor(const HeartSimulation& sim, MonitorSettings settings)
    : m_sim(sim),
      m_settings(settings),
      m_beats(sim.hasHeart() && settings.pump ? double(sim.cavityVolume()) : 0.0,
              double(sim.scenario().simulation.dt)) {
  m_extremes.lastSecondFrom = settings.endTime - 1.0;
  m_last.step = sim.stepCount();
  m_last.startTime = m_last.time = sim.time();
  m_last.phase = sim.lastPhase();
  if (sim.hasHeart() && settings.pump) m_last.cavity = double(sim.cavityVolume());
  if (sim.lumped() && settings.pump)
    m_circulation.emplace(double(sim.scenario().simulation.dt), settings.lumpedSamples);
  if (sim.circulation() && sim.hasBlood() && settings.pump) {
    m_ventricleBlood.emplace(sim.particles(), sim.firstBloodParticle());
    m_echo.emplace();
  }
  if (sim.lumped() && sim.hasBlood() && settings.pump) m_fillingVortex.emplace();
  // The wall's surface hinges that are smooth at rest (bent by less than kSmoothHinge) and their
  // angles (the model's vertices are the first particles, heart_simulation.h), to find creases:
  // a crease is a fold where the surface was smooth. The modelled corners (the base's rim, the
  // vessels' roots, about 90 degrees) open and close with the motion by design and are left out.
  if (sim.hasHeart() && settings.pump) {
    constexpr double kSmoothHinge = 30 * std::numbers::pi / 180;
    const LvModel& model = sim.model();
    for (const pbd::Hinge& h : pbd::surfaceHinges(model.surface)) {
      const double rest = pbd::hingeAngle(h, model.mesh.vertices);
      if (std::abs(rest) >= kSmoothHinge) continue;
      m_hinges.push_back(h);
      m_restHingeAngles.push_back(rest);
    }
  }
}

bool RunMonitor::check(const TissueStats& tissue, double cavity) {
  m_verdict.step = m_sim.stepCount();
  m_verdict.time = m_sim.time();
  const LvModel* model = m_sim.hasHeart() ? &m_sim.model() : nullptr;
  m_verdict.issue = checkTissue(tissue, std::isfinite(cavity), model, m_sim.particles().position);
  return m_verdict.healthy();
}

bool RunMonitor::bloodLimited() const {
  return m_settings.limits.bloodLost != HealthLimits::kUnlimited ||
         m_settings.limits.bloodInsideWall != HealthLimits::kUnlimited;
}

const Verdict& RunMonitor::checkNow() {
  const double cavity = m_sim.hasHeart() ? double(m_sim.cavityVolume()) : 0.0;
  if (check(m_sim.tissueStats(), cavity) && m_sim.hasBlood() && bloodLimited())
    m_verdict.issue = checkBlood(m_sim.bloodStats(), m_settings.limits);
  return m_verdict;
}

const Verdict& RunMonitor::observe() {
  StepSample sample;
  sample.step = m_sim.stepCount();
  sample.startTime = m_last.time;
  sample.time = m_sim.time();
  sample.phase = m_sim.lastPhase();
  sample.tissue = m_sim.tissueStats();
  if (m_sim.hasHeart() && m_settings.pump) {
    sample.cavity = double(m_sim.cavityVolume());
    sample.surfaceTurn = pbd::largestHingeTurn(m_hinges, m_restHingeAngles, m_sim.particles().position);
    sample.bloodPush = m_sim.lastBloodPush();
  }
  if (!check(sample.tissue, sample.cavity)) return m_verdict;
  gather(sample);
  sample.heartPhase = heartPhaseAfter(m_last.heartPhase, phaseSignals(sample));
  // No sound at the first step: its phase is read without the one before.
  if (m_last.heartPhase != HeartPhase::None) sample.heartSound = heartSoundAt(m_last.heartPhase, sample.heartPhase);
  if (sample.lumped) sample.ecg = m_sim.ecgMillivolts();
  if (m_ventricleBlood && sample.circulation) observeBlood(sample);
  if (m_fillingVortex && sample.lumped) watchFillingVortex(sample);
  ++m_observed;
  m_extremes.add(sample, m_sim.hasHeart() && m_settings.pump);
  if (m_sim.hasHeart() && m_settings.beatList) m_beats.record(sample.startTime, sample.phase, sample.cavity, sample.flows);
  if (m_circulation) recordCirculation(sample);
  if (sample.blood) m_verdict.issue = checkBlood(*sample.blood, m_settings.limits);
  m_last = std::move(sample);
  return m_verdict;
}

// The figures the settings ask for; blood statistics (a pass over every particle and its
// neighbours) only when a limit or a reader needs them.
void RunMonitor::gather(StepSample& sample) const {
  if (m_sim.hasBlood() && (m_settings.everyColumn || bloodLimited())) sample.blood = m_sim.bloodStats();
  if (!m_sim.hasHeart()) return;
  if (m_settings.everyColumn) sample.restDeviation = m_sim.restDeviationRelative();
  if (const Circulation* circulation = m_sim.circulation(); circulation && m_settings.pump) {
    sample.circulation = true;
    sample.flows = circulation->meter.lastStepFlows();
    sample.flowStep = circulation->meter.lastStep();
    sample.vesselFill = m_sim.vesselFill();
  }
  if (const LumpedCirculation* lumped = m_sim.lumped(); lumped && m_settings.pump) {
    sample.lumped = lumped->last();
    sample.contraction = m_sim.drivenWall()->contraction();
    sample.baseDescent = m_sim.drivenWall()->baseDescent(sample.contraction);
  }
}

// The blood's own figures from the smoothed velocity: the ventricle's kinetic energy, the cycle's
// Doppler peaks (the A wave while the lumped atrium contracts) and the largest smoothed speed.
void RunMonitor::observeBlood(StepSample& sample) {
  const pbd::Particles& particles = m_sim.particles();
  const std::vector<Vec3>& smoothed = m_sim.smoothedVelocities();
  if (smoothed.size() != particles.size()) return;  // no step measured yet
  sample.ventricleKineticEnergy = m_ventricleBlood->observe(particles, m_sim.circulation()->meter.regions(), smoothed,
                                                            m_last.heartPhase, sample.heartPhase, sample.time);
  const bool atrialKick = sample.lumped && sample.lumped->atrialActivation > 0;
  m_echo->observe(sample.flowStep.aorticEcho, sample.flowStep.mitralEcho, m_last.heartPhase, sample.heartPhase,
                  atrialKick, sample.time);
  // Not the vessels' far ends: the lumped model's boundary, drawn grey (render/scene.h).
  Real fastest = 0;
  for (std::size_t i = m_sim.firstBloodParticle(); i < particles.size(); ++i)
    if (const Real s2 = smoothed[i].squaredNorm(); s2 > fastest && particles.active(i) && !m_sim.bloodInVesselEnd(Index(i)))
      fastest = s2;
  sample.smoothedSpeedMax = std::sqrt(double(fastest));
}

void RunMonitor::recordCirculation(const StepSample& sample) {
  CoupledStep step;
  step.startTime = sample.startTime;
  step.time = sample.time;
  step.phase = sample.phase;
  step.cavity = sample.cavity;
  step.lumped = *sample.lumped;
  step.lumped.ecg = sample.ecg;
  step.aorticForward = sample.flows.aorticForward;
  step.aorticBackward = sample.flows.aorticBackward;
  step.aorticJet = sample.flowStep.aorticJet;
  step.vesselFill = sample.vesselFill;
  m_circulation->record(step);
}

// Early filling: the heart's phase is filling and the atrium has not begun its kick (the E
// wave, heart_phase.h). The field is read only on a step whose lumped mitral flow is the beat's
// largest yet (filling_vortex.h): the cut's grid half a blood spacing fine, the Shepard average
// over the blood's own support radius, a node filled where the blood covers 30% of its support
// (a node on the wall has about half).
void RunMonitor::watchFillingVortex(const StepSample& sample) {
  const bool early = sample.heartPhase == HeartPhase::Filling && sample.lumped->atrialActivation <= 0;
  if (!m_fillingVortex->step(early, sample.lumped->mitralFlow)) return;
  const LvModel& model = m_sim.model();
  const std::vector<Vec3>& positions = m_sim.particles().position;
  const LongAxisCut cut = longAxisCut(model, model.flowPath.descended(Real(sample.baseDescent)), positions);
  const BloodSettings& blood = m_sim.scenario().blood;
  const pbd::PlaneGrid grid = longAxisGrid(cut, model, positions, 0.5 * double(blood.spacing));
  const pbd::PlaneSampling sampling{m_sim.firstBloodParticle(), double(m_sim.circulation()->meter.particleVolume()),
                                    double(blood.supportRadius), 0.3};
  m_fillingVortex->keep(
      readEVortex(cut, pbd::sampleOnPlane(grid, m_sim.particles(), sampling), sample.time, sample.lumped->mitralFlow));
}

RunSummary RunMonitor::summary() const {
  RunSummary r;
  r.steps = m_observed;
  r.time = m_sim.time();
  r.stateHash = pbd::stateHash(m_sim.particles());
  r.heart = m_sim.hasHeart();
  r.blood = m_sim.hasBlood();
  r.beats = m_beats;
  r.circulation = m_circulation;
  r.ventricleBlood = m_ventricleBlood;
  r.echo = m_echo;
  r.smoothedSpeedMax = m_extremes.smoothedSpeedMax;
  r.fillingVortex = m_fillingVortex;
  const RunExtremes& e = m_extremes;
  if (r.heart) {
    const LvModel& model = m_sim.model();
    const pbd::MeshQuality quality = pbd::measureQuality(model.mesh);
    r.vertices = model.mesh.vertices.size();
    r.tets = model.mesh.tets.size();
    r.surfaceTriangles = model.surface.size();
    r.volumeErrorMax = e.volumeErrorMax;
    r.surfaceTurnMax = e.surfaceTurnMax;
    r.twoWay = m_sim.scenario().circulation.twoWay && m_sim.hasBlood();
    r.bloodPushMax = e.bloodPushMax;
    r.bloodPushMean = m_observed > 0 ? e.bloodPushSum / double(m_observed) : 0.0;
    r.volumeErrorMean = m_observed > 0 ? e.volumeErrorMeanSum / double(m_observed) : 0.0;
    r.invertedTets = m_sim.tissueStats().invertedTets;
    r.restDeviation = m_sim.restDeviationRelative();
    r.minDihedralDeg = quality.minDihedralDeg;
    r.maxAspectRatio = quality.maxAspectRatio;
    r.restCavity = cavityVolume(model, model.mesh.vertices);
    r.cavityMin = m_observed > 0 ? e.cavityMin : double(m_sim.cavityVolume());
    r.cavityMax = m_observed > 0 ? e.cavityMax : double(m_sim.cavityVolume());
    if (const RecordedBeat* recorded = m_sim.recordedBeat()) {
      r.motionFrameVolumes = recorded->frameVolumes();
      r.motionPeriod = recorded->period();
      r.motionVolumeErrorMax = recorded->volumeErrorMax();
    }
  }
  if (r.blood) {
    const BloodStats& b = r.bloodFinal = m_sim.bloodStats();
    r.bloodLost = std::max(e.bloodLostMax, b.lost);
    r.bloodInsideWall = std::max(e.bloodInsideWallMax, b.insideWall);
    const bool window = e.lastSecondSteps > 0;
    r.densityErrorMean = window ? e.densityErrorMeanSum / double(e.lastSecondSteps) : b.densityErrorMean;
    r.densityErrorMax = window ? e.densityErrorMax : b.densityErrorMax;
    r.bloodSpeedMax = std::max(e.bloodSpeedMax, b.maxSpeed);
  }
  return r;
}

void Verdict::save(pbd::StateWriter& w) const { w.fields(issue.check, issue.what, step, time); }

void Verdict::load(pbd::StateReader& r) { r.fields(issue.check, issue.what, step, time); }

PhaseSignals phaseSignals(const StepSample& s) {
  PhaseSignals signals;
  if (s.lumped) {
    signals.valves = true;
    signals.mitralOpen = s.lumped->mitralOpen;
    signals.aorticOpen = s.lumped->aorticOpen;
    signals.contracting = s.lumped->ventricularActivation > 0;
  } else if (s.circulation) {
    signals.valves = true;
    signals.mitralOpen = s.flowStep.valves.mitralOpen;
    signals.aorticOpen = s.flowStep.valves.aorticOpen;
    signals.contracting = s.phase == Phase::Systole;
  }
  return signals;
}

std::string heartPhaseLabel(const StepSample& s) {
  PhaseDetail detail;
  detail.wallContracting = s.phase == Phase::Systole;
  if (s.lumped) {
    detail.atrialKick = s.lumped->atrialActivation > 0;
    detail.mitralLeak = s.lumped->mitralFlow < 0;
    detail.aorticLeak = s.lumped->aorticFlow < 0;
  } else {
    detail.mitralLeak = s.flows.mitralBackward > 0;
    detail.aorticLeak = s.flows.aorticBackward > 0;
  }
  return heartPhaseLabel(s.heartPhase, detail);
}

void StepSample::save(pbd::StateWriter& w) const {
  w.fields(step, startTime, time, phase, heartPhase, heartSound, ecg, cavity, tissue, restDeviation, blood, flows, flowStep, circulation, lumped,
           contraction, baseDescent, vesselFill, surfaceTurn, bloodPush, ventricleKineticEnergy, smoothedSpeedMax);
}

void StepSample::load(pbd::StateReader& r) {
  r.fields(step, startTime, time, phase, heartPhase, heartSound, ecg, cavity, tissue, restDeviation, blood, flows, flowStep, circulation, lumped,
           contraction, baseDescent, vesselFill, surfaceTurn, bloodPush, ventricleKineticEnergy, smoothedSpeedMax);
}

void RunExtremes::save(pbd::StateWriter& w) const {
  w.fields(volumeErrorMax, volumeErrorMeanSum, surfaceTurnMax, bloodPushMax, bloodPushSum, cavityMin, cavityMax, bloodLostMax, bloodInsideWallMax, bloodSpeedMax,
           smoothedSpeedMax, lastSecondFrom, densityErrorMeanSum, densityErrorMax, lastSecondSteps);
}

void RunExtremes::load(pbd::StateReader& r) {
  r.fields(volumeErrorMax, volumeErrorMeanSum, surfaceTurnMax, bloodPushMax, bloodPushSum, cavityMin, cavityMax, bloodLostMax, bloodInsideWallMax, bloodSpeedMax,
           smoothedSpeedMax, lastSecondFrom, densityErrorMeanSum, densityErrorMax, lastSecondSteps);
}

void RunMonitor::save(pbd::StateWriter& w) const {
  w.section("run monitor");
  w.fields(m_verdict, m_last, m_beats, m_circulation.has_value());
  if (m_circulation) m_circulation->save(w);
  w.put(m_ventricleBlood.has_value());
  if (m_ventricleBlood) {
    m_ventricleBlood->save(w);
    m_echo->save(w);
  }
  w.put(m_fillingVortex.has_value());
  if (m_fillingVortex) m_fillingVortex->save(w);
  w.fields(m_extremes, m_observed);
}

void RunMonitor::load(pbd::StateReader& r) {
  r.section("run monitor");
  r.fields(m_verdict, m_last, m_beats);
  const std::size_t at = r.offset();
  bool circulation = false;
  r.get(circulation);
  if (circulation != m_circulation.has_value())
    throw pbd::StateError(circulation ? "run monitor: a circulation record saved, but this monitor keeps none"
                                      : "run monitor: the circulation record is missing",
                          at);
  if (m_circulation) m_circulation->load(r);
  bool ventricleBlood = false;
  r.get(ventricleBlood);
  if (ventricleBlood != m_ventricleBlood.has_value())
    throw pbd::StateError("run monitor: the ventricle's blood figures are saved for a run without blood or missing",
                          r.offset());
  if (m_ventricleBlood) {
    m_ventricleBlood->load(r);
    m_echo->load(r);
  }
  bool fillingVortex = false;
  r.get(fillingVortex);
  if (fillingVortex != m_fillingVortex.has_value())
    throw pbd::StateError("run monitor: the filling vortex's figures are saved for a run without them or missing",
                          r.offset());
  if (m_fillingVortex) m_fillingVortex->load(r);
  r.fields(m_extremes, m_observed);
  // The density error is averaged over the last second before this run's end: a window that
  // begins after the checkpoint starts empty; one that began before it keeps what it holds.
  const double from = m_settings.endTime - 1.0;
  if (from != m_extremes.lastSecondFrom && m_sim.time() <= from) {
    m_extremes.densityErrorMeanSum = m_extremes.densityErrorMax = 0;
    m_extremes.lastSecondSteps = 0;
  }
  m_extremes.lastSecondFrom = from;
}

}  // namespace hs::cardiac
