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
    m_atEndDiastole[k] = m_enteredDiastole[k] == m_diastole ? New : Earlier;
    longStay += beatsInside(k) > 3;
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
      const bool left = !m_inside[k];
      switch (componentOf(m_atEndDiastole[k] == New, left)) {
        case FlowComponent::Direct: ++direct; break;
        case FlowComponent::RetainedInflow: ++retained; break;
        case FlowComponent::DelayedEjection: ++delayed; break;
        case FlowComponent::Residual: ++residual; break;
        case FlowComponent::None: break;
      }
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

std::int32_t FlowComponentTracker::beatsInside(std::size_t k) const {
  // From the start: at least m_diastole + 1.
  const std::int32_t entered = m_enteredDiastole[k];
  return entered == kBeforeTracking ? m_diastole + 1 : m_diastole - entered + 1;
}

FlowComponent componentOf(bool enteredThisDiastole, bool left) {
  if (enteredThisDiastole) return left ? FlowComponent::Direct : FlowComponent::RetainedInflow;
  return left ? FlowComponent::DelayedEjection : FlowComponent::Residual;
}

std::vector<FlowComponent> FlowComponentTracker::components() const {
  std::vector<FlowComponent> out(m_inside.size(), FlowComponent::None);
  // The diastole the last end-diastole closed: endSystole() has begun the next one since.
  const std::int32_t sorted = m_haveEndDiastole ? m_diastole : m_diastole - 1;
  for (std::size_t k = 0; k < m_inside.size(); ++k) {
    if (m_atEndDiastole[k] == Absent) continue;
    // Ejected blood that comes round through the loop and enters again in a later diastole has
    // still left in the beat being shown.
    const bool left = !m_inside[k] || m_enteredDiastole[k] > sorted;
    out[k] = componentOf(m_atEndDiastole[k] == New, left);
  }
  return out;
}

std::vector<Stay> FlowComponentTracker::stays() const {
  std::vector<Stay> out(m_inside.size(), Stay::Outside);
  for (std::size_t k = 0; k < m_inside.size(); ++k)
    if (m_inside[k]) out[k] = beatsInside(k) > 3 ? Stay::OverThreeBeats : Stay::UpToThreeBeats;
  return out;
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
