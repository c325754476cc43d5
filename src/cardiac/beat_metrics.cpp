#include "cardiac/beat_metrics.h"

#include <algorithm>

namespace hs::cardiac {

void BeatTracker::record(double time, Phase phase, double volume) {
  const bool systoleStarts = phase == Phase::Systole && m_previous != Phase::Systole;
  m_previous = phase;
  if (systoleStarts) {
    finish();
    // The beat starts where the step started: the volume before it is end-diastolic.
    m_current = BeatSummary{static_cast<int>(m_beats.size()) + 1, time, m_lastVolume, m_lastVolume};
    m_open = true;
  }
  m_lastVolume = volume;
  if (!m_open) return;
  if (phase != Phase::Systole) m_systoleEnded = true;
  m_current.esv = std::min(m_current.esv, volume);
}

void BeatTracker::finish() {
  if (m_open && m_systoleEnded) m_beats.push_back(m_current);
  m_open = false;
  m_systoleEnded = false;
}

double BeatTracker::meanEjectionFraction() const {
  if (m_beats.empty()) return 0;
  double sum = 0;
  for (const BeatSummary& b : m_beats) sum += b.ejectionFraction();
  return sum / double(m_beats.size());
}

}  // namespace hs::cardiac
