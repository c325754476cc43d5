#include "pbd/core/thread_governor.h"

#include <algorithm>

namespace hs::pbd {

ThreadGovernor::ThreadGovernor(int maxThreads, ThreadGovernorSettings settings)
    : m_max(std::max(1, maxThreads)), m_settings(settings) {
  m_settings.probeSteps = std::max(2, m_settings.probeSteps);
  startProbe();
}

void ThreadGovernor::startProbe() {
  m_stage = Stage::ProbeMany;
  m_current = m_max;
  m_stageSteps = 0;
  m_manySeconds = m_oneSeconds = 0;
}

void ThreadGovernor::record(double seconds) {
  ++m_steps;
  if (m_current < m_max) ++m_reduced;
  if (m_max == 1 || !m_settings.adaptive) return;
  // The first step after a change is not timed: it pays for waking the other threads.
  const bool timed = m_stageSteps > 0;
  ++m_stageSteps;
  switch (m_stage) {
    case Stage::ProbeMany:
      if (timed) m_manySeconds += seconds;
      if (m_stageSteps == m_settings.probeSteps) {
        m_stage = Stage::ProbeOne;
        m_current = 1;
        m_stageSteps = 0;
      }
      return;
    case Stage::ProbeOne:
      if (timed) m_oneSeconds += seconds;
      if (m_stageSteps == m_settings.probeSteps) {
        // Equal times keep the threads: an idle machine's ties go to the parallel step.
        const int chosen = m_oneSeconds < m_manySeconds ? 1 : m_max;
        m_holdScale = chosen == m_held ? std::min(2 * m_holdScale, m_settings.maxHoldScale) : 1;
        m_held = m_current = chosen;
        m_stage = Stage::Hold;
        m_stageSteps = 0;
        m_heldSeconds = 0;
      }
      return;
    case Stage::Hold:
      m_heldSeconds += seconds;
      if (m_stageSteps >= m_settings.holdSteps * m_holdScale &&
          m_heldSeconds >= m_settings.holdSeconds * m_holdScale)
        startProbe();
      return;
  }
}

}  // namespace hs::pbd
