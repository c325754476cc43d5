#include "cardiac/blood/flow_components.h"

#include <cassert>

namespace hs::cardiac {

FlowComponentTracker::FlowComponentTracker(std::size_t particles)
    : m_inside(particles, 0), m_enteredDiastole(particles, kBeforeTracking), m_atEndDiastole(particles, Absent) {}

void FlowComponentTracker::observe(std::span<const std::uint8_t> inVentricle) {
  assert(inVentricle.size() == m_inside.size());
  // The first look finds blood already there: it entered before tracking began.
  for (std::size_t k = 0; k < m_inside.size(); ++k) {
    if (inVentricle[k] && !m_inside[k] && m_observed) m_enteredDiastole[k] = m_diastole;
    m_inside[k] = inVentricle[k];
  }
  m_observed = true;
}

void FlowComponentTracker::endDiastole() {
  std::size_t inside = 0, longStay = 0;
  for (std::size_t k = 0; k < m_inside.size(); ++k) {
    if (!m_inside[k]) {
      m_atEndDiastole[k] = Absent;
      continue;
    }
    ++inside;
    const std::int32_t entered = m_enteredDiastole[k];
    m_atEndDiastole[k] = entered == m_diastole ? New : Earlier;
    // Beats spent so far: this diastole is the first of them. From the start: at least m_diastole + 1.
    const std::int32_t beats = entered == kBeforeTracking ? m_diastole + 1 : m_diastole - entered + 1;
    longStay += beats > 3;
  }
  m_haveEndDiastole = true;
  m_stayedOverThreeBeats = inside > 0 ? double(longStay) / double(inside) : 0.0;
}

std::optional<FlowComponents> FlowComponentTracker::endSystole() {
  std::optional<FlowComponents> beat;
  if (m_haveEndDiastole) {
    std::size_t direct = 0, retained = 0, delayed = 0, residual = 0, residenceSum = 0, residenceCount = 0;
    for (std::size_t k = 0; k < m_inside.size(); ++k) {
      if (m_atEndDiastole[k] == Absent) continue;
      const bool left = !m_inside[k], fresh = m_atEndDiastole[k] == New;
      direct += fresh && left, retained += fresh && !left;
      delayed += !fresh && left, residual += !fresh && !left;
      if (left && m_enteredDiastole[k] != kBeforeTracking) {
        residenceSum += std::size_t(m_diastole - m_enteredDiastole[k] + 1);
        ++residenceCount;
      }
    }
    FlowComponents c;
    c.particles = direct + retained + delayed + residual;
    if (c.particles > 0) {
      const double n = double(c.particles);
      c.direct = double(direct) / n, c.retainedInflow = double(retained) / n;
      c.delayedEjection = double(delayed) / n, c.residual = double(residual) / n;
    }
    c.meanResidenceBeats = residenceCount > 0 ? double(residenceSum) / double(residenceCount) : 0.0;
    c.stayedOverThreeBeats = m_stayedOverThreeBeats;
    beat = c;
  }
  m_haveEndDiastole = false;
  ++m_diastole;
  return beat;
}

void FlowComponentTracker::save(pbd::StateWriter& w) const {
  w.fields(m_inside, m_enteredDiastole, m_atEndDiastole, m_diastole, m_observed, m_haveEndDiastole,
           m_stayedOverThreeBeats);
}

void FlowComponentTracker::load(pbd::StateReader& r) {
  r.fields(m_inside, m_enteredDiastole, m_atEndDiastole, m_diastole, m_observed, m_haveEndDiastole,
           m_stayedOverThreeBeats);
}

}  // namespace hs::cardiac
