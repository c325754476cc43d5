#include "cardiac/circulation/valves.h"

namespace hs::cardiac {

ValveStates timedValves(bool cycleEnabled, Phase phase) {
  if (!cycleEnabled) return {true, true};
  const bool systole = phase == Phase::Systole;
  return {!systole, systole};
}

bool gateClosedOrifice(const Orifice& orifice, const Vec3& x, Vec3& p, Real radius) {
  if (orifice.radial(p) >= orifice.radius) return false;
  // C = side(x) * side(p) - r >= 0 with side(x) = +-1 (the half-space the particle came from).
  const Real from = orifice.side(x) >= Real(0) ? Real(1) : Real(-1);
  const Real c = from * orifice.side(p) - radius;
  if (c >= Real(0)) return false;
  p -= c * from * orifice.forward;
  return true;
}

bool gateOpenLeaflets(const Orifice& orifice, Real length, const Vec3& x, Vec3& p, Real radius) {
  const Real along = orifice.side(p);
  if (along < Real(0) || along > length) return false;
  // C = side(x) * (R - rho(p)) - r >= 0 with side(x) = +1 inside the tube, -1 outside, and rho
  // the distance from the axis; its gradient is radial.
  const Vec3 offAxis = (p - orifice.centre) - along * orifice.forward;
  const Real rho = offAxis.norm();
  const Real from = orifice.radial(x) < orifice.radius ? Real(1) : Real(-1);
  const Real c = from * (orifice.radius - rho) - radius;
  if (c >= Real(0) || !(rho > Real(0))) return false;
  p += c * from * (offAxis / rho);
  return true;
}

Valves::Valves(const FlowPath& path, ValveMode mode, bool cycleEnabled, Real bloodRadius)
    : m_mitral(path.mitralValve()),
      m_aortic(path.aorticValve()),
      m_mitralLeaflets(path.mitralLeafletLength),
      m_mode(mode),
      m_cycleEnabled(cycleEnabled),
      m_radius(bloodRadius) {}

void Valves::decide(Phase phase, const ValvePressures& lastStep) {
  switch (m_mode) {
    case ValveMode::Open:
      m_states = {true, true};
      break;
    case ValveMode::Timing:
      m_states = timedValves(m_cycleEnabled, phase);
      break;
    case ValveMode::Pressure:
      m_states.mitralOpen = lastStep.mitralUpstream > lastStep.mitralDownstream;
      m_states.aorticOpen = lastStep.aorticUpstream > lastStep.aorticDownstream;
      break;
  }
}

void Valves::gate(const Vec3& x, Vec3& p) const {
  if (!m_states.mitralOpen) {
    gateClosedOrifice(m_mitral, x, p, m_radius);
  } else if (m_mitralLeaflets > 0) {
    gateOpenLeaflets(m_mitral, m_mitralLeaflets, x, p, m_radius);
  }
  if (!m_states.aorticOpen) {
    gateClosedOrifice(m_aortic, x, p, m_radius);
  } else if (m_aorticOpening && m_aortic.radial(p) >= *m_aorticOpening) {
    gateClosedOrifice(m_aortic, x, p, m_radius);  // the stenotic valve's ring
  }
}

bool Valves::gates() const {
  return !m_states.mitralOpen || !m_states.aorticOpen || m_aorticOpening || m_mitralLeaflets > 0;
}

void Valves::gatePoints(const pbd::Particles& particles, std::vector<Vec3>& points,
                        std::span<const Index> ids) const {
  if (!gates()) return;
  for (std::size_t k = 0; k < ids.size(); ++k) gate(particles.position[ids[k]], points[k]);
}

void Valves::gateParticles(pbd::Particles& particles, Index first) const {
  if (!gates()) return;
  for (std::size_t i = first; i < particles.size(); ++i) gate(particles.position[i], particles.predicted[i]);
}

void ValveStates::save(pbd::StateWriter& w) const {
  w.fields(mitralOpen, aorticOpen);
}

void ValveStates::load(pbd::StateReader& r) {
  r.fields(mitralOpen, aorticOpen);
}

void ValvePressures::save(pbd::StateWriter& w) const {
  w.fields(mitralUpstream, mitralDownstream, aorticUpstream, aorticDownstream);
}

void ValvePressures::load(pbd::StateReader& r) {
  r.fields(mitralUpstream, mitralDownstream, aorticUpstream, aorticDownstream);
}

void Valves::save(pbd::StateWriter& w) const {
  w.section("valves");
  w.fields(m_states);
}

void Valves::load(pbd::StateReader& r) {
  r.section("valves");
  r.fields(m_states);
}

}  // namespace hs::cardiac
