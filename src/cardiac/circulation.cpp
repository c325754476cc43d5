#include "cardiac/circulation.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace hs::cardiac {
namespace {

Orifice orificeOf(const LvModel& model, const std::vector<Index>& ring, Real radius, const Vec3& forward) {
  Orifice o;
  Vec3 centroid = Vec3::Zero();
  for (Index v : ring) centroid += model.mesh.vertices[v];
  o.centre = centroid / Real(ring.size());
  o.forward = forward;
  o.radius = radius;
  return o;
}

}  // namespace

bool gateClosedOrifice(const Orifice& orifice, const Vec3& x, Vec3& p, Real radius) {
  if (orifice.radial(p) >= orifice.radius) return false;
  // C = side(x) * side(p) - r >= 0 with side(x) = +-1 (the half-space the particle came from).
  const Real from = orifice.side(x) >= Real(0) ? Real(1) : Real(-1);
  const Real c = from * orifice.side(p) - radius;
  if (c >= Real(0)) return false;
  p -= c * from * orifice.forward;
  return true;
}

int crossing(const Orifice& orifice, const Vec3& x, const Vec3& p) {
  const Real a = orifice.side(x);
  const Real b = orifice.side(p);
  const bool forward = a < Real(0) && b >= Real(0);
  const bool backward = a >= Real(0) && b < Real(0);
  if (!forward && !backward) return 0;
  // Where the segment meets the plane: inside the disc?
  const Real t = a / (a - b);
  if (orifice.radial(x + t * (p - x)) >= orifice.radius) return 0;
  return forward ? 1 : -1;
}

ValveStates timedValves(bool cycleEnabled, Phase phase) {
  if (!cycleEnabled) return {true, true};
  const bool systole = phase == Phase::Systole;
  return {!systole, systole};
}

Circulation::Circulation(const LvModel& model, const CirculationSettings& settings, const BloodSettings& blood,
                         const CycleSettings& cycle)
    : m_settings(settings), m_cycleEnabled(cycle.enabled) {
  const LvGeometryParams& g = model.params;
  // Inflow: forward is down (-y) into the cavity; outflow: up (+y) out of it.
  m_mitral = orificeOf(model, model.mitralRing, g.mitralRadius, -Vec3::UnitY());
  m_aortic = orificeOf(model, model.aorticRing, g.aorticRadius, Vec3::UnitY());
  m_inflowTop = m_mitral.centre.y() + g.baseThickness + g.inflowVesselLength;
  m_outflowTop = m_aortic.centre.y() + g.baseThickness + g.outflowVesselLength;
  m_inflowLength = m_inflowTop - m_mitral.centre.y();
  m_apexAxisOrigin = Vec3(0, m_mitral.centre.y(), 0);  // the spheroid's centre on the base plane
  m_midWallRadius = g.endoRadius + Real(0.5) * g.wallThickness;
  m_midWallLongAxis = g.endoLongAxis + Real(0.5) * g.wallThickness;
  m_plateMid = Real(0.5) * g.baseThickness;
  m_spacing = blood.spacing;
  m_radius = blood.radius;
  m_restDensity = blood.restDensity;
  m_particleVolume = blood.spacing * blood.spacing * blood.spacing;
  // Re-entry sites: a square lattice of spacing d across the inflow lumen, half a spacing
  // below its far end, at least a radius inside the lumen wall.
  const Real y = m_inflowTop - Real(0.5) * m_spacing;
  const Real reach = m_mitral.radius - m_radius;
  const int n = int(std::floor(reach / m_spacing));
  for (int i = -n; i <= n; ++i)
    for (int k = -n; k <= n; ++k) {
      const Vec3 site(m_mitral.centre.x() + Real(i) * m_spacing, y, m_mitral.centre.z() + Real(k) * m_spacing);
      if (m_mitral.radial(site) <= reach) m_inletSites.push_back(site);
    }
  if (m_inletSites.empty()) m_inletSites.push_back(Vec3(m_mitral.centre.x(), y, m_mitral.centre.z()));
  // Parked particles wait above the vessels, between them, more than a kernel support apart
  // (so they are nobody's neighbours).
  m_parkingOrigin = Vec3(Real(0.5) * (m_mitral.centre.x() + m_aortic.centre.x()),
                         std::max(m_inflowTop, m_outflowTop) + 2 * blood.supportRadius, m_mitral.centre.z());
  m_parkingPitch = Real(1.01) * blood.supportRadius;
}

FlowRegion Circulation::classify(const Vec3& x) const {
  if (!x.allFinite()) return FlowRegion::Outside;
  // Past a valve's plane inside its lumen (with a radius of slack for particles touching the
  // lumen wall): that vessel. The valve planes are the regions' borders, as for the flows.
  if (x.y() >= m_mitral.centre.y()) {
    if (m_mitral.radial(x) < m_mitral.radius + m_radius && x.y() <= m_inflowTop + m_spacing)
      return FlowRegion::InflowVessel;
    if (m_aortic.radial(x) < m_aortic.radius + m_radius && x.y() <= m_outflowTop + m_spacing)
      return FlowRegion::OutflowVessel;
  }
  // Inside the mid-wall spheroid, continued as a cylinder up to the base plate's middle: the
  // cavity, however the wall has moved. A particle beyond it went through the wall.
  if (x.y() >= m_mitral.centre.y() + m_plateMid) return FlowRegion::Outside;
  Vec3 q = x - m_apexAxisOrigin;
  q.y() = std::min(q.y(), Real(0));
  const Real e = (q.x() * q.x() + q.z() * q.z()) / (m_midWallRadius * m_midWallRadius) +
                 (q.y() * q.y()) / (m_midWallLongAxis * m_midWallLongAxis);
  return e <= Real(1) ? FlowRegion::Ventricle : FlowRegion::Outside;
}

bool Circulation::parked(Index particle) const {
  if (particle < m_first) return false;
  const std::size_t b = particle - m_first;
  return b < m_parked.size() && m_parked[b] != 0;
}

void Circulation::decideValves(Phase phase) {
  switch (m_settings.valveMode) {
    case ValveMode::Open:
      m_valves = {true, true};
      break;
    case ValveMode::Timing:
      m_valves = timedValves(m_cycleEnabled, phase);
      break;
    case ValveMode::Pressure: {
      const FlowStep& s = m_last;
      m_valves.mitralOpen = s.mitralUpstream > s.mitralDownstream;
      m_valves.aorticOpen = s.aorticUpstream > s.aorticDownstream;
      break;
    }
  }
}

void Circulation::beginStep(pbd::Particles& particles, Index first, Phase phase, Real dt) {
  m_first = first;
  const std::size_t n = particles.size() - first;
  if (m_parked.size() != n) m_parked.assign(n, 0);
  decideValves(phase);
  m_start.assign(particles.position.begin() + first, particles.position.end());
  // Filling pressure: a = P_a / (rho0 L) along the inflow vessel, toward the ventricle.
  const Real a = Real(m_settings.atrialPressureMmHg * kPascalPerMmHg) / (m_restDensity * m_inflowLength);
  if (a == Real(0)) return;
  const Vec3 dv = (a * dt) * m_mitral.forward;
  for (std::size_t b = 0; b < n; ++b) {
    if (m_parked[b]) continue;
    if (classify(particles.position[first + b]) == FlowRegion::InflowVessel) particles.velocity[first + b] += dv;
  }
}

void Circulation::gate(const Vec3& x, Vec3& p) const {
  if (!m_valves.mitralOpen) gateClosedOrifice(m_mitral, x, p, m_radius);
  if (!m_valves.aorticOpen) gateClosedOrifice(m_aortic, x, p, m_radius);
}

void Circulation::gatePoints(const pbd::Particles& particles, std::vector<Vec3>& points,
                             std::span<const Index> ids) const {
  if (m_valves.mitralOpen && m_valves.aorticOpen) return;
  for (std::size_t k = 0; k < ids.size(); ++k) gate(particles.position[ids[k]], points[k]);
}

void Circulation::gateParticles(pbd::Particles& particles, Index first) const {
  if (m_valves.mitralOpen && m_valves.aorticOpen) return;
  for (std::size_t i = first; i < particles.size(); ++i) gate(particles.position[i], particles.predicted[i]);
}

Vec3 Circulation::parkingSite(std::size_t k) const {
  // Rows of 8 across x, then z, then layers upward.
  const Real i = Real(k % 8), j = Real((k / 8) % 8), layer = Real(k / 64);
  return m_parkingOrigin + m_parkingPitch * Vec3(i - Real(3.5), layer, j - Real(3.5));
}

void Circulation::park(pbd::Particles& particles, Index particle) {
  const std::size_t b = particle - m_first;
  std::size_t slot = 0;
  while (slot < m_lot.size() && m_lot[slot] != kFreeSlot) ++slot;
  if (slot == m_lot.size()) m_lot.push_back(kFreeSlot);
  m_lot[slot] = Index(b);
  m_parked[b] = 1;
  m_queue.push_back(Index(b));
  if (particles.inverseMass[particle] > Real(0)) m_inverseMass = particles.inverseMass[particle];
  particles.position[particle] = particles.predicted[particle] = parkingSite(slot);
  particles.velocity[particle] = Vec3::Zero();
  particles.inverseMass[particle] = 0;  // pinned: the solvers leave it where it is
}

void Circulation::startWaiting(pbd::Particles& particles, Index first, std::size_t count) {
  m_first = first;
  const std::size_t n = particles.size() - first;
  m_parked.assign(n, 0);
  for (std::size_t k = n - count; k < n; ++k) park(particles, Index(first + k));
  m_last.count[std::size_t(FlowRegion::Parked)] = m_queue.size();
}

void Circulation::reenter(pbd::Particles& particles, Index first) {
  if (m_queue.empty()) return;
  // Blood near the inflow vessel's far end: the sites must be clear of it, and re-entering
  // particles take its mean velocity (they join the moving column).
  const Real near = m_inflowTop - 2 * m_spacing;
  std::vector<Vec3>& occupied = m_scratch;
  occupied.clear();
  Vec3 velocity = Vec3::Zero();
  for (std::size_t i = first; i < particles.size(); ++i) {
    if (m_parked[i - first]) continue;
    const Vec3& x = particles.position[i];
    if (x.y() < near || m_mitral.radial(x) > m_mitral.radius + m_spacing) continue;
    occupied.push_back(x);
    velocity += particles.velocity[i];
  }
  if (!occupied.empty()) velocity /= Real(occupied.size());
  velocity = m_mitral.forward * std::max(Real(0), velocity.dot(m_mitral.forward));  // never back out
  const Real clear2 = Real(0.9 * 0.9) * m_spacing * m_spacing;
  for (const Vec3& site : m_inletSites) {
    if (m_queue.empty()) break;
    bool free = true;
    for (const Vec3& x : occupied) free = free && (x - site).squaredNorm() >= clear2;
    if (!free) continue;
    const Index b = m_queue.front();
    m_queue.pop_front();
    std::replace(m_lot.begin(), m_lot.end(), b, kFreeSlot);
    m_parked[b] = 0;
    const Index i = first + b;
    particles.position[i] = particles.predicted[i] = site;
    particles.velocity[i] = velocity;
    particles.inverseMass[i] = m_inverseMass;
    occupied.push_back(site);
    ++m_last.reentered;
  }
}

void Circulation::endStep(pbd::Particles& particles, Index first, const std::vector<Real>& pressures) {
  assert(m_start.size() == particles.size() - first);
  FlowStep s;
  s.valves = m_valves;
  std::array<double, kFlowRegionCount> pressureSum{};
  // Pressure just before / after each valve: blood within two spacings of the disc.
  double sum[4] = {0, 0, 0, 0};
  std::size_t count[4] = {0, 0, 0, 0};
  const Real slab = 2 * m_spacing;
  auto sample = [&](const Orifice& o, const Vec3& x, Real p, int index) {
    const Real side = o.side(x);
    if (std::abs(side) > slab || o.radial(x) >= o.radius) return;
    const int k = index + (side >= Real(0) ? 1 : 0);
    sum[k] += double(p);
    ++count[k];
  };
  for (std::size_t i = first; i < particles.size(); ++i) {
    const std::size_t b = i - first;
    if (m_parked[b]) continue;
    const Vec3& x0 = m_start[b];
    const Vec3& x1 = particles.position[i];
    const int m = crossing(m_mitral, x0, x1);
    const int a = crossing(m_aortic, x0, x1);
    s.mitralForward += m > 0, s.mitralBackward += m < 0;
    s.aorticForward += a > 0, s.aorticBackward += a < 0;
    const Real p = i < pressures.size() ? pressures[i] : Real(0);
    const FlowRegion r = classify(x1);
    ++s.count[std::size_t(r)];
    pressureSum[std::size_t(r)] += double(p);
    sample(m_mitral, x1, p, 0);
    sample(m_aortic, x1, p, 2);
  }
  for (std::size_t r = 0; r < kFlowRegionCount; ++r)
    s.pressure[r] = s.count[r] > 0 ? pressureSum[r] / double(s.count[r]) : 0.0;
  auto mean = [&](int k) { return count[k] > 0 ? sum[k] / double(count[k]) : 0.0; };
  s.mitralUpstream = mean(0) + m_settings.atrialPressureMmHg * kPascalPerMmHg;
  s.mitralDownstream = mean(1);
  s.aorticUpstream = mean(2);
  s.aorticDownstream = mean(3);
  m_last = s;
  if (m_settings.loop) {
    // Blood past a vessel's far end has left the model: it waits to re-enter.
    for (std::size_t i = first; i < particles.size(); ++i) {
      if (m_parked[i - first]) continue;
      const Vec3& x = particles.position[i];
      const bool outInflow = x.y() > m_inflowTop && m_mitral.radial(x) < m_mitral.radius + m_spacing;
      const bool outOutflow = x.y() > m_outflowTop && m_aortic.radial(x) < m_aortic.radius + m_spacing;
      if (outInflow || outOutflow) {
        park(particles, Index(i));
        ++m_last.returned;
      }
    }
    reenter(particles, first);
  }
  m_last.count[std::size_t(FlowRegion::Parked)] = m_queue.size();
}

ValveFlows Circulation::lastStepFlows() const {
  const double v = double(m_particleVolume);
  return {double(m_last.mitralForward) * v, double(m_last.mitralBackward) * v, double(m_last.aorticForward) * v,
          double(m_last.aorticBackward) * v};
}

void Circulation::permute(std::span<const Index> order) {
  if (m_parked.size() != order.size()) return;
  std::vector<Index> newIndex(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) newIndex[order[k]] = Index(k);
  std::vector<std::uint8_t> parked(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) parked[k] = m_parked[order[k]];
  m_parked.swap(parked);
  for (Index& b : m_queue) b = newIndex[b];
  for (Index& b : m_lot)
    if (b != kFreeSlot) b = newIndex[b];
}

}  // namespace hs::cardiac
