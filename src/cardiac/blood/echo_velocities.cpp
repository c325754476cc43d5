#include "cardiac/blood/echo_velocities.h"

#include <algorithm>

namespace hs::cardiac {

bool endDiastoleBetween(HeartPhase before, HeartPhase after) {
  return before == HeartPhase::Filling && (after == HeartPhase::IsovolumicContraction || after == HeartPhase::Ejection);
}

void EchoVelocities::observe(double aortic, double mitral, HeartPhase before, HeartPhase after, bool atrialKick,
                             double time) {
  if (endDiastoleBetween(before, after)) {
    if (m_started) {
      m_current.end = time;
      m_cycles.push_back(m_current);
    }
    m_current = {};
    m_current.start = time;
    m_started = true;
    m_kickSeen = false;
  }
  // Forward flow only: a leak's backward reading is not the jet's peak.
  if (after == HeartPhase::Ejection) m_current.aorticPeak = std::max(m_current.aorticPeak, aortic);
  if (after != HeartPhase::Filling) return;
  if (atrialKick) {
    m_kickSeen = true;
    m_current.mitralA = std::max(m_current.mitralA.value_or(0.0), mitral);
  } else if (!m_kickSeen) {
    m_current.mitralE = std::max(m_current.mitralE, mitral);
  }
}

void EchoVelocities::save(pbd::StateWriter& w) const { w.fields(m_current, m_started, m_kickSeen, m_cycles); }

void EchoVelocities::load(pbd::StateReader& r) { r.fields(m_current, m_started, m_kickSeen, m_cycles); }

}  // namespace hs::cardiac
