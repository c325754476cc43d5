#include "viewer/simulation_runner.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>

namespace hs::viewer {
namespace {

using Clock = std::chrono::steady_clock;

// Samples wait here only between two frames; a main thread that stopped taking them (a window
// being dragged) must not make the list grow without bound.
constexpr std::size_t kMaxPendingSamples = std::size_t(1) << 16;

}  // namespace

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

void SimulationRunner::start(const cardiac::Scenario& scenario) {
  auto sim = std::make_unique<cardiac::HeartSimulation>(scenario, m_threads);
  const double dt = double(scenario.simulation.dt);
  std::optional<PumpReadout> pump;
  if (sim->hasHeart()) pump.emplace(double(sim->cavityVolume()), dt);
  access([&](SimulationState& s) {
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
      stepOnce();
      m_pacer.stepped(dt);
      simulated = dt;
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

// One step under the lock, then what the panel shows of it.
void SimulationRunner::stepOnce() {
  SimulationState& s = m_state;
  cardiac::HeartSimulation& sim = *s.sim;
  const double start = sim.time();
  try {
    sim.step();
  } catch (const std::exception& e) {
    s.playing = false;
    s.message = std::string("the simulation stopped: ") + e.what();
    return;
  }
  double cavity = 0;
  if (sim.hasHeart()) {
    cavity = double(sim.cavityVolume());
    const cardiac::Circulation* circulation = sim.circulation();
    const cardiac::ValveFlows flows = circulation ? circulation->meter.lastStepFlows() : cardiac::ValveFlows{};
    s.pump->record(start, sim.lastPhase(), cavity, flows);
    PumpSample sample;
    sample.time = sim.time();
    sample.cavity = cavity;
    if (circulation) {
      setFlowRates(sample, flows, sim.time() - start);
      const cardiac::FlowStep& f = circulation->meter.lastStep();
      sample.pressureLv = f.pressure[std::size_t(cardiac::FlowRegion::Ventricle)];
      sample.pressureInflow = f.pressure[std::size_t(cardiac::FlowRegion::InflowVessel)];
      sample.pressureOutflow = f.pressure[std::size_t(cardiac::FlowRegion::OutflowVessel)];
    }
    if (s.newSamples.size() < kMaxPendingSamples) s.newSamples.push_back(sample);
  }
  const cardiac::TissueStats tissue = sim.tissueStats();
  if (!tissue.finite || !std::isfinite(cavity)) {
    s.playing = false;
    char text[160];
    std::snprintf(text, sizeof text,
                  "simulation became invalid at t = %.3f s (particle %lld not finite); Reset", sim.time(),
                  static_cast<long long>(tissue.firstNonFinite));
    s.message = text;
  }
}

}  // namespace hs::viewer
