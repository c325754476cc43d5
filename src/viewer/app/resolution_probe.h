#pragma once
// The viewer's start-up measurement of the blood's resolution levels (blood_resolution.h): in
// a thread of its own, while the window draws its first frames, each level of the scenario is
// built and stepped, coarsest first, for a fixed stretch of simulated time; it stops at the
// first level that cannot hold real time (a finer one is slower). The same steps each time:
// only the wall time they take depends on the machine. The simulation thread is held meanwhile,
// so the measurement has the cores the simulation will have, beside the drawing.
#include <atomic>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "cardiac/scenario.h"
#include "viewer/panels/blood_resolution.h"

namespace hs::viewer {

class ResolutionProbe {
 public:
  // Simulated time stepped per level after kWarmupSteps (the first steps build the grids); a
  // level already slower than kHoldsRealTimePace stops there.
  static constexpr double kMeasuredSeconds = 0.1;
  static constexpr int kWarmupSteps = 3;
  static constexpr int kMinSteps = 10, kMaxSteps = 200;

  // levels: the scenario at each level to measure, coarsest first; threads: the simulation's.
  ResolutionProbe(std::vector<std::pair<BloodResolution, cardiac::Scenario>> levels, int threads);
  ~ResolutionProbe();  // stops after the step in progress
  ResolutionProbe(const ResolutionProbe&) = delete;
  ResolutionProbe& operator=(const ResolutionProbe&) = delete;

  [[nodiscard]] bool done() const { return m_done; }
  // "medium (2 of 4)": the level being measured.
  [[nodiscard]] std::string progress() const;
  // One per level given, in that order (unmeasured after the first too slow); when done().
  [[nodiscard]] std::vector<LevelMeasurement> measurements() const;

  // The steps measured for a scenario stepping dt: kMeasuredSeconds of them, within the bounds.
  static int measuredSteps(double dt);

 private:
  void run();
  LevelMeasurement measure(BloodResolution level, const cardiac::Scenario& scenario);

  std::vector<std::pair<BloodResolution, cardiac::Scenario>> m_levels;
  int m_threads;
  mutable std::mutex m_mutex;
  std::vector<LevelMeasurement> m_measurements;  // guarded by m_mutex
  std::atomic<int> m_current{0};
  std::atomic<bool> m_stop{false}, m_done{false};
  std::thread m_thread;  // last: starts after everything it uses exists
};

}  // namespace hs::viewer
