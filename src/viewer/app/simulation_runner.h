#pragma once
// The viewer's simulation thread. It steps the simulation at real-time pace (pacing.h) while
// the main thread draws; after each step a cardiac::RunMonitor checks the simulation's health
// (as `heartsim run` does) and gathers the step's figures, which feed the pump's readout
// (pump_readout.h) and the plots.
//
// Sharing: everything the two threads share is in SimulationState, guarded by one mutex. The
// worker holds it for one step at a time; the main thread reads and writes the state only
// inside access(), which first tells the worker to let it in, so it waits at most for the step
// in progress (a plain mutex would let the worker take it again at once, step after step).
// The main thread copies what it draws (render::buildScene, the status, new plot samples)
// inside one access() per frame, then draws without the lock.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "cardiac/heart_simulation.h"
#include "cardiac/run_monitor.h"
#include "viewer/app/pacing.h"
#include "viewer/panels/ui_panel.h"
#include "viewer/plots/pump_readout.h"
#include "viewer/region/region_editor.h"

namespace hs::viewer {

struct SimulationState {
  std::unique_ptr<cardiac::HeartSimulation> sim;
  std::unique_ptr<cardiac::RunMonitor> monitor;  // of `sim`
  std::optional<PumpReadout> pump;     // with a heart
  std::vector<PumpSample> newSamples;  // recorded since the main thread last took them
  bool playing = true;
  double speed = 1;            // simulated seconds per wall second
  bool stepRequested = false;  // one step, then pause
  // Written by the worker.
  double paceFactor = 1;  // simulated seconds per wall second achieved
  bool behind = false;    // cannot keep up with `speed`
  std::string message;    // "simulation became invalid ...", taken by the main thread
  std::uint64_t restarts = 0;
  // Written by the worker, summed over every run: the simulated time stepped while playing and
  // the wall time its steps took (a scripted run's last line: the pace and the worker's share).
  double simulatedSeconds = 0;
  double steppingSeconds = 0;
};

// The built-in presets with their descriptions (each a scenario file compiled in).
std::vector<ScenarioChoice> builtinScenarioChoices();

// The panel's cycle and blood controls from a scenario's settings, and the scenario with the
// panel's cycle, blood and beating-region settings applied: what a (re)start runs.
void setControls(const cardiac::Scenario& scenario, ViewerControls& controls);
cardiac::Scenario configuredScenario(const cardiac::Scenario& base, const ViewerControls& controls,
                                     const RegionEditor& region);

// The simulation's part of the panels' status: scenario, time, phase, cavity, valves, beats.
void readStatus(const SimulationState& state, ViewerStatus& status);
// Its circulation part: with the lumped circulation, the pressure-volume relations and the
// last complete beat's figures.
void readCirculationStatus(const SimulationState& state, CirculationStatus& status);

class SimulationRunner {
 public:
  // threads: the simulation's OpenMP threads. Starts the worker, which waits for start().
  explicit SimulationRunner(int threads);
  ~SimulationRunner();
  SimulationRunner(const SimulationRunner&) = delete;
  SimulationRunner& operator=(const SimulationRunner&) = delete;

  // A new simulation of `scenario` from t = 0 (also a restart). Built before the lock is
  // taken, so the one running keeps running meanwhile and stays when this throws
  // (std::invalid_argument: the model or cycle rejected the scenario). `prepare`, when given,
  // acts on the new simulation before anything watches it (a checkpoint's state loaded).
  void start(const cardiac::Scenario& scenario,
             const std::function<void(cardiac::HeartSimulation&)>& prepare = {});

  // Runs fn(SimulationState&) on the calling (main) thread with the worker held between steps.
  template <class Fn>
  decltype(auto) access(Fn&& fn) {
    Access guard(*this);
    return fn(m_state);
  }

 private:
  struct Access {
    explicit Access(SimulationRunner& runner);
    ~Access();
    Access(const Access&) = delete;
    Access& operator=(const Access&) = delete;
    SimulationRunner& runner;
    std::unique_lock<std::mutex> lock;
  };
  void run();
  void stepOnce();

  int m_threads;
  std::mutex m_mutex;
  std::condition_variable m_wake;
  std::atomic<bool> m_mainWaiting{false};
  bool m_stop = false;  // guarded by m_mutex
  SimulationState m_state;
  // The worker's own (no lock needed).
  Pacer m_pacer;
  PaceMeter m_meter;
  std::uint64_t m_seenRestarts = 0;
  std::thread m_worker;  // last: starts after everything it uses exists
};

}  // namespace hs::viewer
