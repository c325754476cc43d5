#pragma once
// How many threads the next step uses, chosen from the measured wall time of recent steps.
//
// Every stage gives bitwise the same result on any number of threads (block colouring, fixed
// reduction orders), so the count is free to change from one step to the next without changing
// the state. That makes a governor possible: with another process keeping a core busy, two
// threads that meet at a barrier dozens of times a step wait for each other's time slices and
// run slower than one (docs/performance.md: 32 steps/s on 2 threads against 120 on 1 for
// `normal`); on an idle machine two are faster. Rather than guess, the governor measures:
//   probe   a few steps on all the threads allowed, then as many on one;
//   hold    the faster of the two for a while (a number of steps and of seconds), then probe
//           again, so that a machine that becomes busy or idle is followed within seconds.
//           A probe that confirms the count held doubles the next hold (up to maxHoldScale
//           times): a probe on the slower count costs steps, and a steady machine needs few.
// With one thread allowed, or `adaptive` off, there is nothing to choose and nothing is measured.
#include <cstdint>

namespace hs::pbd {

struct ThreadGovernorSettings {
  bool adaptive = true;     // false: every step on all the threads allowed (nothing measured)
  int probeSteps = 8;       // steps timed on each count per probe (the first of each is not timed)
  int holdSteps = 200;      // steps on the chosen count before the next probe, at least ...
  double holdSeconds = 1;   // ... and this much wall time (times the hold's scale)
  int maxHoldScale = 8;     // the most a confirmed count's hold grows to
};

class ThreadGovernor {
 public:
  explicit ThreadGovernor(int maxThreads, ThreadGovernorSettings settings = {});

  // The threads for the next step.
  [[nodiscard]] int threads() const { return m_current; }
  // The wall time (s) the step just taken needed, on threads() threads.
  void record(double seconds);

  [[nodiscard]] int maxThreads() const { return m_max; }
  // Steps taken on fewer threads than allowed, and all steps recorded (for reports).
  [[nodiscard]] std::int64_t reducedSteps() const { return m_reduced; }
  [[nodiscard]] std::int64_t steps() const { return m_steps; }

 private:
  enum class Stage { ProbeMany, ProbeOne, Hold };
  void startProbe();

  int m_max = 1;
  ThreadGovernorSettings m_settings;
  Stage m_stage = Stage::ProbeMany;
  int m_current = 1;
  int m_stageSteps = 0;       // steps recorded in this stage
  double m_manySeconds = 0;   // timed seconds of the many-thread probe
  double m_oneSeconds = 0;    // ... of the one-thread probe
  double m_heldSeconds = 0;   // wall time spent holding
  int m_holdScale = 1;        // doubles when a probe confirms the count held
  int m_held = 0;             // the count the last probe chose (0: none yet)
  std::int64_t m_reduced = 0;
  std::int64_t m_steps = 0;
};

}  // namespace hs::pbd
