#include "viewer/app/simulation_runner.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>

#include "io/scenario/scenario_file.h"
#include "render/scene.h"

namespace hs::viewer {
namespace {

using Clock = std::chrono::steady_clock;

// Samples wait here only between two frames; a main thread that stopped taking them (a window
// being dragged) must not make the list grow without bound.
constexpr std::size_t kMaxPendingSamples = std::size_t(1) << 16;
constexpr double kLumpedSecondsKept = 20;  // s of simulated time

}  // namespace

std::vector<ScenarioChoice> builtinScenarioChoices() {
  std::vector<ScenarioChoice> choices;
  for (const std::string& name : io::builtinScenarioNames()) {
    ScenarioChoice choice{name, "", ScenarioGroup::HumanHeart};
    try {
      const cardiac::Scenario scenario = io::loadScenario(name);
      choice.description = scenario.description;
      // The thesis's models are metres across; a human left ventricle a few centimetres.
      constexpr double kHumanScaleMax = 0.2;  // m, the cavity's radius
      if (!scenario.heart)
        choice.group = ScenarioGroup::BloodOnly;
      else if (double(scenario.geometry.endoRadius) > kHumanScaleMax)
        choice.group = ScenarioGroup::ThesisModel;
    } catch (const std::exception& e) {
      choice.description = std::string("cannot be loaded: ") + e.what();
    }
    choices.push_back(choice);
  }
  return choices;
}

void setControls(const cardiac::Scenario& scenario, ViewerControls& controls) {
  controls.cycleEnabled = scenario.cycle.enabled;
  controls.heartRateBpm = float(scenario.cycle.heartRateBpm);
  controls.contraction = float(scenario.cycle.contraction);
  controls.beatingDuration = scenario.cycle.beatingDuration;
  controls.beatingDisplace = float(scenario.cycle.beatingDisplace);
  const BloodResolution resolution = controls.blood.resolution;  // the machine's, kept from scenario to scenario
  controls.blood = bloodControlsFrom(scenario, 0);
  controls.blood.resolution = resolution;
  controls.circulation = circulationControlsFrom(scenario);
}

cardiac::Scenario configuredScenario(const cardiac::Scenario& base, const ViewerControls& controls,
                                     const RegionEditor& region) {
  cardiac::Scenario s = base;
  s.cycle.enabled = controls.cycleEnabled;
  if (controls.heartRateBpm != float(s.cycle.heartRateBpm)) {
    s.cycle.mode = cardiac::TimingMode::Physiological;
    s.cycle.heartRateBpm = cardiac::Real(controls.heartRateBpm);
  }
  s.cycle.contraction = cardiac::Real(controls.contraction);
  s.cycle.beatingDuration = std::max(1, controls.beatingDuration);
  s.cycle.beatingDisplace = cardiac::Real(controls.beatingDisplace);
  region.configure(s);
  if (s.blood.enabled) applyBloodControls(controls.blood, s);
  if (s.circulation.lumped) applyCirculationControls(controls.circulation, s);
  return s;
}

void readStatus(const SimulationState& state, ViewerStatus& status) {
  const cardiac::HeartSimulation& sim = *state.sim;
  const cardiac::StepSample& step = state.monitor->last();
  const cardiac::Scenario& scenario = sim.scenario();
  status.scenarioName = scenario.name;
  status.time = sim.time();
  status.dt = double(scenario.simulation.dt);
  status.hasHeart = sim.hasHeart();
  status.hasBlood = sim.hasBlood();
  status.wallYields = sim.wallCanYield();
  status.physiological = scenario.cycle.mode == cardiac::TimingMode::Physiological;
  status.recordedBeat.clear();
  if (const cardiac::RecordedBeat* recorded = sim.recordedBeat()) {
    char text[80];
    std::snprintf(text, sizeof text, "%d frames over %.2f s (%.0f bpm)", recorded->frameCount(), recorded->period(),
                  60.0 / recorded->period());
    status.recordedBeat = text;
  }
  status.heartSize = float(scenario.geometry.endoRadius);
  // One phase, from the valves (cardiac/circulation/heart_phase.h): its name in the information
  // box (one line: the box keeps its size), its name with the atrial kick or a leak in the pump panel.
  const bool beating = sim.hasHeart() && scenario.cycle.enabled;
  const std::string phase = beating ? cardiac::heartPhaseLabel(step) : "";
  status.phase = !beating                                         ? ""
                 : step.heartPhase != cardiac::HeartPhase::None ? cardiac::heartPhaseName(step.heartPhase)
                 : step.phase == cardiac::Phase::Systole        ? "the wall contracts"
                                                                 : "the wall relaxes";
  status.cavity = sim.hasHeart() ? step.cavity : -1;
  status.resolution.particles = sim.hasBlood() ? int(sim.particles().size() - sim.firstBloodParticle()) : 0;
  status.resolution.spacing = double(scenario.blood.spacing);
  status.speedMax = render::defaultSpeedScale(scenario);
  status.pressureMax = render::defaultPressureScale(scenario);
  PumpStatus& pump = status.pump;
  pump.hasHeart = sim.hasHeart();
  pump.hasBlood = step.circulation;
  pump.beats = state.pump ? state.pump->readings() : BeatReadings{};
  pump.cycleOn = scenario.cycle.enabled;
  pump.phase = step.phase;
  pump.heartPhase = step.heartPhase;
  pump.phaseLabel = phase;
  pump.thesisTiming = scenario.cycle.mode == cardiac::TimingMode::Thesis;
  pump.valves = step.circulation ? step.flowStep.valves : cardiac::ValveStates{};
  pump.valveMode = scenario.circulation.valveMode;
  pump.flowComponents.reset();
  pump.flowBeat = 0;
  if (const cardiac::VentricleBlood* blood = state.monitor->ventricleBlood(); blood && !blood->beats().empty()) {
    pump.flowComponents = blood->beats().back().shares;
    pump.flowBeat = int(blood->beats().size());
  }
  readCirculationStatus(state, status.circulation);
}

void readCirculationStatus(const SimulationState& state, CirculationStatus& status) {
  const cardiac::HeartSimulation& sim = *state.sim;
  status = {};
  const cardiac::LumpedCirculation* lumped = sim.lumped();
  if (!lumped) return;
  status.lumped = true;
  // The wall beats with only part of its myocardium when a region is chosen: the lumped
  // ventricle's contractility is scaled by that share, and so is the line the loop meets.
  const cardiac::VolumeDrivenWall* wall = sim.drivenWall();
  status.relations = lumped->relations(wall ? wall->beatingShare() : 1);
  if (const cardiac::CirculationRecorder* recorder = state.monitor->circulation()) {
    const std::vector<cardiac::CoupledBeat>& beats = recorder->beats();
    for (auto it = beats.rbegin(); it != beats.rend(); ++it)
      if (it->complete) {
        status.lastBeat = it->lumped;
        break;
      }
  }
}

SimulationRunner::Access::Access(SimulationRunner& r) : runner(r) {
  runner.m_mainWaiting = true;
  lock = std::unique_lock(runner.m_mutex);
  runner.m_mainWaiting = false;
}

SimulationRunner::Access::~Access() {
  lock.unlock();
  runner.m_wake.notify_all();
}

SimulationRunner::SimulationRunner(int threads) : m_threads(threads), m_worker([this] { run(); }) {}

SimulationRunner::~SimulationRunner() {
  // As in access(): a worker that is behind steps on and on, and lets the lock go only when
  // asked to.
  m_mainWaiting = true;
  {
    const std::lock_guard lock(m_mutex);
    m_stop = true;
  }
  m_wake.notify_all();
  m_worker.join();
}

void SimulationRunner::start(const cardiac::Scenario& scenario,
                             const std::function<void(cardiac::HeartSimulation&)>& prepare) {
  auto sim = std::make_unique<cardiac::HeartSimulation>(scenario, m_threads);
  if (prepare) prepare(*sim);
  // The panel keeps its own bounded beat readout: the monitor lists no beats.
  cardiac::MonitorSettings settings;
  settings.beatList = false;
  // The lumped samples the circulation panel copies from: far more than its last beats, so a
  // frame that comes late (a window being dragged) finds what it missed.
  settings.lumpedSamples = std::size_t(kLumpedSecondsKept / double(scenario.simulation.dt)) + 1;
  auto monitor = std::make_unique<cardiac::RunMonitor>(*sim, settings);
  std::optional<PumpReadout> pump;
  if (sim->hasHeart()) pump.emplace(monitor->last().cavity, double(scenario.simulation.dt), settlingRuleFor(scenario));
  access([&](SimulationState& s) {
    s.monitor = std::move(monitor);  // before the simulation it watches goes
    s.sim = std::move(sim);
    s.pump = std::move(pump);
    s.newSamples.clear();
    s.message.clear();
    s.behind = false;
    s.paceFactor = 1;
    ++s.restarts;
  });
}

void SimulationRunner::run() {
  std::unique_lock lock(m_mutex);
  SimulationState& s = m_state;
  auto last = Clock::now();
  while (true) {
    // The main thread's turn comes first: it waits for the lock only for the step just done.
    m_wake.wait(lock, [&] { return m_stop || !m_mainWaiting; });
    if (m_stop) return;
    const auto now = Clock::now();
    const double wallSeconds = std::chrono::duration<double>(now - last).count();
    last = now;
    if (s.restarts != m_seenRestarts) {
      m_seenRestarts = s.restarts;
      m_pacer.reset();
      m_meter.reset();
    }
    if (s.sim && s.stepRequested) {
      s.stepRequested = false;
      s.playing = false;
      stepOnce();
      continue;
    }
    if (!s.sim || !s.playing) {
      // Paused: nothing is owed for the time spent here.
      m_pacer.reset();
      m_meter.reset();
      s.behind = false;
      m_wake.wait(lock, [&] { return m_stop || (s.sim && (s.playing || s.stepRequested)); });
      last = Clock::now();
      continue;
    }
    const double dt = double(s.sim->scenario().simulation.dt);
    const bool dropped = m_pacer.elapse(wallSeconds, s.speed, dt);
    double simulated = 0;
    if (m_pacer.due(dt)) {
      const auto before = Clock::now();
      stepOnce();
      m_pacer.stepped(dt);
      simulated = dt;
      s.simulatedSeconds += dt;
      s.steppingSeconds += std::chrono::duration<double>(Clock::now() - before).count();
    }
    m_meter.add(wallSeconds, simulated, dropped);
    s.paceFactor = m_meter.factor();
    s.behind = m_meter.behind(s.speed);
    if (!m_pacer.due(dt)) {
      // Ahead of wall time: sleep until the next step is due, or until the main thread changes
      // something (it notifies after every access).
      const double wait = std::min(m_pacer.secondsUntilDue(dt, s.speed), 0.5);
      m_wake.wait_for(lock, std::chrono::duration<double>(wait));
    }
  }
}

// One step under the lock, then what the panel shows of it; a failed health check pauses.
void SimulationRunner::stepOnce() {
  SimulationState& s = m_state;
  try {
    s.sim->step();
  } catch (const std::exception& e) {
    s.playing = false;
    s.message = std::string("the simulation stopped: ") + e.what();
    return;
  }
  if (const cardiac::Verdict& verdict = s.monitor->observe(); !verdict.healthy()) {
    s.playing = false;
    s.message = verdict.message() + "; Reset";
    return;
  }
  if (!s.sim->hasHeart()) return;
  const cardiac::StepSample& step = s.monitor->last();
  s.pump->record(step.startTime, step.phase, step.cavity, step.flows);
  if (s.newSamples.size() < kMaxPendingSamples) s.newSamples.push_back(pumpSample(step));
}

}  // namespace hs::viewer
