#pragma once
// The recent past of the pump's values for the viewer's live plots: one PumpSample per step
// over the last `window` seconds of simulated time, oldest first, in a ring buffer that grows
// to hold the window. It also smooths the valve flows: one blood particle carries
// spacing^3 (0.047 mL in `normal`), so a step's flow is a whole number of particles per step
// (steps of 46.66 mL/s at dt = 1 ms), and a particle that jitters back across an open valve's
// disc reads as a step of backward flow while the ventricle fills. The centred mean over
// about 25 ms (an odd number of steps) keeps the beat's shape (filling and ejection last
// hundreds of ms) and removes that counting noise. No GL or ImGui: unit-tested.
#include <cstddef>
#include <vector>

#include "viewer/plots/pump_readout.h"

namespace hs::viewer {

class PlotHistory {
 public:
  // More than a plot can show (a few hundred pixels): beyond it the oldest samples go even
  // inside the window, so a tiny dt cannot make the buffer grow without bound.
  static constexpr std::size_t kMaxSamples = std::size_t(1) << 17;

  static constexpr double kSmoothingSeconds = 0.025;

  explicit PlotHistory(double windowSeconds = 5, double smoothingSeconds = kSmoothingSeconds)
      : m_window(windowSeconds), m_smoothing(smoothingSeconds) {}

  // Simulated seconds kept. A longer window fills as time goes on (what was dropped is gone).
  void setWindow(double seconds);
  [[nodiscard]] double window() const { return m_window; }

  // Appends a sample. A time at or before the newest one means the simulation started again
  // (Reset, a new scenario, a setting that restarts): the history starts over with it. The
  // sample `smoothingHalfSteps()` back gets its smoothed flows (its window is now whole).
  void push(const PumpSample& sample);
  void clear() { m_head = m_size = 0, m_halfSteps = -1; }

  // The smoothing window in steps either side of a sample (from the step length the first two
  // samples show; -1 before), and its length in seconds: (2 half + 1) steps, the nearest odd
  // number of steps to the asked window.
  [[nodiscard]] int smoothingHalfSteps() const { return m_halfSteps; }
  [[nodiscard]] double smoothingSeconds() const;

  [[nodiscard]] std::size_t size() const { return m_size; }
  [[nodiscard]] bool empty() const { return m_size == 0; }
  // i = 0 is the oldest sample.
  [[nodiscard]] const PumpSample& operator[](std::size_t i) const {
    return m_ring[(m_head + i) % m_ring.size()];
  }
  [[nodiscard]] const PumpSample& newest() const { return (*this)[m_size - 1]; }
  // The first sample at or after `time` (size() when there is none).
  [[nodiscard]] std::size_t lowerBound(double time) const;

 private:
  void dropOld();
  void grow();
  void smoothNewest();
  PumpSample& at(std::size_t i) { return m_ring[(m_head + i) % m_ring.size()]; }

  double m_window;
  double m_smoothing;
  int m_halfSteps = -1;
  double m_step = 0;  // s, the step length the window was counted in
  std::vector<PumpSample> m_ring;
  std::size_t m_head = 0;  // index of the oldest sample in m_ring
  std::size_t m_size = 0;
};

// Axis ticks at 1, 2 or 5 times a power of ten: the first tick at or above lo, the step, and
// how many fit up to hi. At most maxTicks (>= 2) ticks.
struct AxisTicks {
  double first = 0, step = 1;
  int count = 0;
};
AxisTicks niceTicks(double lo, double hi, int maxTicks);

// A plot's value range: the data's, widened to include zero when asked, padded, and rounded
// out to whole tick steps; a flat line gets a range around it.
struct AxisRange {
  double lo = 0, hi = 1;
};
AxisRange niceRange(double dataMin, double dataMax, bool includeZero, int maxTicks);

}  // namespace hs::viewer
