#pragma once
// Real-time pacing of the viewer's simulation thread: simulated time follows wall-clock time x
// speed. Pure arithmetic on the times it is given, so it is unit-tested without a clock. Also
// the frame-time summary of a scripted run.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace hs::viewer {

// The simulated time owed to wall-clock time. The simulation thread adds the wall time that
// passed, steps while a step is due, and sleeps until the next one is due.
class Pacer {
 public:
  // Owed time beyond this much wall time is dropped, not made up: a simulation that cannot
  // keep up runs steadily slower than real time instead of in bursts, and after a pause (a
  // restart, a slow frame) it does not race to catch up.
  static constexpr double kMaxLagSeconds = 0.1;

  // wallSeconds have passed at `speed` (simulated seconds per wall second), with steps of dt.
  // Returns true when owed time had to be dropped: the simulation is behind real time.
  bool elapse(double wallSeconds, double speed, double dt);
  // A step of dt is owed.
  [[nodiscard]] bool due(double dt) const { return m_debt >= dt * (1 - 1e-9); }
  void stepped(double dt) { m_debt -= dt; }
  // Wall seconds until the next step of dt is due at `speed`.
  [[nodiscard]] double secondsUntilDue(double dt, double speed) const;
  void reset() { m_debt = 0; }
  [[nodiscard]] double debt() const { return m_debt; }

 private:
  double m_debt = 0;  // simulated seconds owed
};

// The pace achieved, simulated seconds per wall second, measured over windows of half a second
// of wall time, so the number in the status corner is steady enough to read.
class PaceMeter {
 public:
  static constexpr double kWindowSeconds = 0.5;

  // wallSeconds passed, simSeconds were simulated in them; dropped: owed time was dropped.
  void add(double wallSeconds, double simSeconds, bool dropped);
  // The last complete window's pace (1 before the first).
  [[nodiscard]] double factor() const { return m_factor; }
  // The last window dropped owed time and ran below 95% of the speed asked for.
  [[nodiscard]] bool behind(double speed) const { return m_lastDropped && m_factor < 0.95 * speed; }
  void reset() { *this = PaceMeter(); }

 private:
  double m_wall = 0, m_sim = 0;
  bool m_dropped = false;
  double m_factor = 1;
  bool m_lastDropped = false;
};

}  // namespace hs::viewer

namespace hs::viewer {

// What a scripted viewer run (--frames N) reports of its frame times: the mean, the frame rate
// it gives, and the 95th percentile (a steady rate has it close to the mean).
struct FrameTimeSummary {
  int frames = 0;         // frames summarised
  double meanMs = 0;      // mean frame time
  double fps = 0;         // 1000 / meanMs
  double p95Ms = 0;       // 95% of the frames took at most this long
};

// Frame times in seconds, in order; the first `skip` (start-up: the first frames compile
// shaders and fill caches) are left out when there are more than that.
FrameTimeSummary summariseFrameTimes(const std::vector<double>& seconds, std::size_t skip);

// The simulation over a scripted run, from when it was let go after start-up (the blood's
// levels measured) to the last frame.
struct SimulationPace {
  double simulatedSeconds = 0;  // simulated time stepped
  double wallSeconds = 0;       // wall time it took
  double steppingSeconds = 0;   // of which the simulation thread spent stepping
  int particles = 0;            // blood particles (0: none)
};

// The run's last line: "heartsim: 590 frames: 26.0 ms mean, 38.5 fps, 95% within 33.7 ms;
// simulation 1.02x real time (stepping 64% of the time), 2,100 particles". Without a pace (the
// run ended during start-up): "simulation not started".
std::string scriptedRunLine(const FrameTimeSummary& frames, const std::optional<SimulationPace>& simulation);

}  // namespace hs::viewer
