#include "viewer/app/resolution_probe.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>

#include "cardiac/heart_simulation.h"
#include "cardiac/run_monitor.h"

namespace hs::viewer {

using Clock = std::chrono::steady_clock;

ResolutionProbe::ResolutionProbe(std::vector<std::pair<BloodResolution, cardiac::Scenario>> levels, int threads)
    : m_levels(std::move(levels)), m_threads(threads), m_thread([this] { run(); }) {}

ResolutionProbe::~ResolutionProbe() {
  m_stop = true;
  m_thread.join();
}

int ResolutionProbe::measuredSteps(double dt) {
  return std::clamp(int(std::lround(kMeasuredSeconds / dt)), kMinSteps, kMaxSteps);
}

std::string ResolutionProbe::progress() const {
  const int i = std::min(m_current.load(), int(m_levels.size()) - 1);
  if (i < 0) return "";
  return std::string(resolutionName(m_levels[std::size_t(i)].first)) + " (" + std::to_string(i + 1) + " of " +
         std::to_string(m_levels.size()) + ")";
}

std::vector<LevelMeasurement> ResolutionProbe::measurements() const {
  const std::lock_guard lock(m_mutex);
  return m_measurements;
}

void ResolutionProbe::run() {
  std::vector<LevelMeasurement> results;
  for (std::size_t i = 0; i < m_levels.size() && !m_stop; ++i) {
    m_current = int(i);
    const auto& [level, scenario] = m_levels[i];
    LevelMeasurement m{level, false, 0};
    if (worthMeasuring(results)) m = measure(level, scenario);
    results.push_back(m);
  }
  for (std::size_t i = results.size(); i < m_levels.size(); ++i) results.push_back({m_levels[i].first, false, 0});
  {
    const std::lock_guard lock(m_mutex);
    m_measurements = std::move(results);
  }
  m_done = true;
}

// The level's simulation as the viewer's thread steps it (a step, then the health check), timed
// over measuredSteps after the warm-up. A level that cannot be built or goes invalid is left
// unmeasured: it is not offered by the pick.
LevelMeasurement ResolutionProbe::measure(BloodResolution level, const cardiac::Scenario& scenario) {
  LevelMeasurement m{level, false, 0};
  try {
    cardiac::HeartSimulation sim(scenario, m_threads);
    cardiac::MonitorSettings settings;
    settings.beatList = false;
    settings.lumpedSamples = 16;
    cardiac::RunMonitor monitor(sim, settings);
    const double dt = double(scenario.simulation.dt);
    for (int k = 0; k < kWarmupSteps && !m_stop; ++k) {
      sim.step();
      if (!monitor.observe().healthy()) return m;
    }
    const int steps = measuredSteps(dt);
    // Beyond this much wall time the level cannot hold real time: no need to go on.
    const double budget = double(steps) * dt / kHoldsRealTimePace;
    const auto start = Clock::now();
    double wall = 0;
    int done = 0;
    while (done < steps && !m_stop) {
      sim.step();
      if (!monitor.observe().healthy()) return m;
      ++done;
      wall = std::chrono::duration<double>(Clock::now() - start).count();
      if (wall > budget) break;
    }
    if (done == 0 || wall <= 0) return m;
    m.measured = true;
    m.pace = double(done) * dt / wall;
  } catch (const std::exception&) {
    m.measured = false;  // the scenario's geometry cannot hold this spacing
  }
  return m;
}

}  // namespace hs::viewer
