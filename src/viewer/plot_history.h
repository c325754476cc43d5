#pragma once
// The recent past of the pump's values for the viewer's live plots: one PumpSample per step
// over the last `window` seconds of simulated time, oldest first, in a ring buffer that grows
// to hold the window. No GL or ImGui: unit-tested.
#include <cstddef>
#include <vector>

#include "viewer/pump_readout.h"

namespace hs::viewer {

class PlotHistory {
 public:
  // More than a plot can show (a few hundred pixels): beyond it the oldest samples go even
  // inside the window, so a tiny dt cannot make the buffer grow without bound.
  static constexpr std::size_t kMaxSamples = std::size_t(1) << 17;

  explicit PlotHistory(double windowSeconds = 5) : m_window(windowSeconds) {}

  // Simulated seconds kept. A longer window fills as time goes on (what was dropped is gone).
  void setWindow(double seconds);
  [[nodiscard]] double window() const { return m_window; }

  // Appends a sample. A time at or before the newest one means the simulation started again
  // (Reset, a new scenario, a setting that restarts): the history starts over with it.
  void push(const PumpSample& sample);
  void clear() { m_head = m_size = 0; }

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

  double m_window;
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
