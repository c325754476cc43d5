#include "cardiac/circulation/beat_metrics.h"

#include <algorithm>

namespace hs::cardiac {

void BeatTracker::record(double time, Phase phase, double volume, const ValveFlows& flows) {
  const bool systoleStarts = phase == Phase::Systole && m_previous != Phase::Systole;
  m_previous = phase;
  if (systoleStarts) {
    close(true);
    // The beat starts where the step started: the volume before it is end-diastolic.
    m_current = BeatSummary{};
    m_current.index = static_cast<int>(m_beats.size()) + 1;
    m_current.startTime = time;
    m_current.edv = m_current.esv = m_lastVolume;
    m_open = true;
  }
  m_lastVolume = volume;
  if (!m_open) return;
  m_current.flows += flows;
  if (phase == Phase::Systole) m_current.mitralNetInSystole += flows.mitralForward - flows.mitralBackward;
  else m_current.aorticNetInDiastole += flows.aorticForward - flows.aorticBackward;
  m_current.duration = time + m_stepLength - m_current.startTime;
  if (phase != Phase::Systole) m_systoleEnded = true;
  m_current.esv = std::min(m_current.esv, volume);
}

void BeatTracker::finish() { close(false); }

void BeatTracker::close(bool complete) {
  if (m_open && m_systoleEnded) {
    m_current.complete = complete;
    m_beats.push_back(m_current);
  }
  m_open = false;
  m_systoleEnded = false;
}

BeatMeans BeatTracker::means() const {
  BeatMeans m;
  for (const BeatSummary& b : m_beats) {
    if (b.index < 2 || !b.complete) continue;
    ++m.count;
    m.edv += b.edv, m.esv += b.esv, m.strokeVolume += b.strokeVolume();
    m.ejectionFraction += b.ejectionFraction(), m.cardiacOutput += b.cardiacOutput();
    m.regurgitantVolume += b.regurgitantVolume(), m.aorticNet += b.flows.aorticForward - b.flows.aorticBackward;
  }
  if (m.count == 0) return m;
  const double n = double(m.count);
  m.edv /= n, m.esv /= n, m.strokeVolume /= n, m.ejectionFraction /= n, m.cardiacOutput /= n;
  m.regurgitantVolume /= n, m.aorticNet /= n;
  return m;
}

double BeatTracker::meanEjectionFraction() const {
  if (m_beats.empty()) return 0;
  double sum = 0;
  for (const BeatSummary& b : m_beats) sum += b.ejectionFraction();
  return sum / double(m_beats.size());
}

VolumeScale volumeScaleFor(double cavityVolume) {
  if (cavityVolume < kThesisScaleVolume) return {};
  // Per minute as in the clinic, so that CO = SV x HR holds with HR in bpm.
  return {true, 1.0, "m^3", "m^3/s", 60.0, "m^3/min"};
}

void ValveFlows::save(pbd::StateWriter& w) const {
  w.fields(mitralForward, mitralBackward, aorticForward, aorticBackward);
}

void ValveFlows::load(pbd::StateReader& r) {
  r.fields(mitralForward, mitralBackward, aorticForward, aorticBackward);
}

void BeatSummary::save(pbd::StateWriter& w) const {
  w.fields(index, startTime, duration, complete, edv, esv, flows, mitralNetInSystole, aorticNetInDiastole);
}

void BeatSummary::load(pbd::StateReader& r) {
  r.fields(index, startTime, duration, complete, edv, esv, flows, mitralNetInSystole, aorticNetInDiastole);
}

void BeatTracker::save(pbd::StateWriter& w) const {
  w.section("beat tracker");
  w.fields(m_beats, m_current, m_open, m_systoleEnded, m_previous, m_lastVolume);
}

void BeatTracker::load(pbd::StateReader& r) {
  r.section("beat tracker");
  r.fields(m_beats, m_current, m_open, m_systoleEnded, m_previous, m_lastVolume);
}

}  // namespace hs::cardiac
