#include "cardiac/blood/blood_loop.h"

#include <algorithm>
#include <cmath>

namespace hs::cardiac {

BloodLoop::BloodLoop(const FlowPath& path, const BloodSettings& blood, int inletLayers)
    : m_path(path), m_spacing(blood.spacing), m_radius(blood.radius), m_inletLayers(std::max(1, inletLayers)) {
  // The inflow's far end: where the lumen's axis ends (the mitral orifice's own for a straight
  // vessel).
  const Orifice mitral = path.inflowEnd();
  const Real reach = mitral.radius - blood.radius;
  if (m_inletLayers == 1) {
    // One square lattice of spacing d across the inflow lumen, half a spacing below its far
    // end, at least a radius inside the lumen wall (the thesis-era circulation).
    const Real y = path.inflowTop - Real(0.5) * m_spacing;
    const int n = int(std::floor(reach / m_spacing));
    for (int i = -n; i <= n; ++i)
      for (int k = -n; k <= n; ++k) {
        const Vec3 site(mitral.centre.x() + Real(i) * m_spacing, y, mitral.centre.z() + Real(k) * m_spacing);
        if (mitral.radial(site) <= reach) m_inletSites.push_back(site);
      }
  } else {
    // Layers a spacing apart below the far end, each at the blood's rest density
    // (lumenDiscSites), alternate layers turned by half a site.
    for (int layer = 0; layer < m_inletLayers; ++layer) {
      const Real y = path.inflowTop - (Real(0.5) + Real(layer)) * m_spacing;
      for (const Vec3& site : lumenDiscSites(mitral, y, reach, m_spacing, layer % 2 == 1)) m_inletSites.push_back(site);
    }
  }
  if (m_inletSites.empty())
    m_inletSites.push_back(Vec3(mitral.centre.x(), path.inflowTop - Real(0.5) * m_spacing, mitral.centre.z()));
  // Parked particles wait above the vessels, between them, more than a kernel support apart
  // (so they are nobody's neighbours).
  m_parkingOrigin = Vec3(Real(0.5) * (mitral.centre.x() + path.outflowEnd().centre.x()),
                         std::max(path.inflowTop, path.outflowTop) + 2 * blood.supportRadius, mitral.centre.z());
  m_parkingPitch = Real(1.01) * blood.supportRadius;
}

Vec3 BloodLoop::parkingSite(std::size_t slot) const {
  // Rows of 8 across x, then z, then layers upward.
  const Real i = Real(slot % 8), j = Real((slot / 8) % 8), layer = Real(slot / 64);
  return m_parkingOrigin + m_parkingPitch * Vec3(i - Real(3.5), layer, j - Real(3.5));
}

void BloodLoop::park(pbd::Particles& particles, Index particle) {
  std::size_t slot = 0;
  while (slot < m_lot.size() && m_lot[slot] != kFreeSlot) ++slot;
  if (slot == m_lot.size()) m_lot.push_back(kFreeSlot);
  m_lot[slot] = particles.id[particle];
  m_queue.push_back(particles.id[particle]);
  particles.position[particle] = particles.predicted[particle] = parkingSite(slot);
  particles.velocity[particle] = Vec3::Zero();
  particles.state[particle] = pbd::ParticleState::Parked;
}

void BloodLoop::startWaiting(pbd::Particles& particles, Index first, std::size_t count) {
  const std::size_t n = particles.size() - first;
  // A lot without a free slot fills at its end, where park's search from the first slot would
  // land after reading the whole lot: quadratic in `count`, hours for a million. The same slots,
  // taken in the same order, without the search.
  const bool full = std::find(m_lot.begin(), m_lot.end(), kFreeSlot) == m_lot.end();
  for (std::size_t k = n - count; k < n; ++k) {
    const Index particle = Index(first + k);
    if (!full) {
      park(particles, particle);
      continue;
    }
    m_lot.push_back(particles.id[particle]);
    m_queue.push_back(particles.id[particle]);
    particles.position[particle] = particles.predicted[particle] = parkingSite(m_lot.size() - 1);
    particles.velocity[particle] = Vec3::Zero();
    particles.state[particle] = pbd::ParticleState::Parked;
  }
}

BloodLoop::Turnover BloodLoop::circulate(pbd::Particles& particles, Index first) {
  Turnover turnover;
  for (std::size_t i = first; i < particles.size(); ++i) {
    if (!particles.active(i)) continue;
    const Vec3& x = particles.position[i];
    if (m_path.pastInflowEnd(x, m_spacing) || m_path.pastOutflowEnd(x, m_spacing)) {
      park(particles, Index(i));
      ++turnover.returned;
    }
  }
  turnover.reentered = m_inletMetered ? enterLayers(particles, first) : reenter(particles, first);
  return turnover;
}

void BloodLoop::meterInlet(Real travel, Real dt) {
  m_inletMetered = true;
  // Moving back out (a regurgitant mitral valve), the plug carries blood past the far end, where
  // it is parked: no debt of layers is kept for it.
  m_inletTravel = std::max(Real(0), m_inletTravel + travel);
  m_inletVelocity = (travel / dt) * m_path.mitral.forward;
}

std::size_t BloodLoop::enterLayers(pbd::Particles& particles, Index first) {
  const Orifice mitral = m_path.inflowEnd();
  std::size_t entered = 0;
  bool located = false;
  while (m_inletTravel >= m_spacing && !m_queue.empty()) {
    if (!located) locateParked(particles, first);
    located = true;
    m_inletTravel -= m_spacing;
    // A spacing behind the last layer, which entered half a spacing under the far end and has
    // since moved on by m_inletTravel more.
    const Real y = m_path.inflowTop - Real(0.5) * m_spacing - m_inletTravel;
    for (const Vec3& site : lumenDiscSites(mitral, y, mitral.radius - m_radius, m_spacing, m_inletLayer % 2 == 1)) {
      if (m_queue.empty()) break;
      enter(particles, first, site, m_inletVelocity);
      ++entered;
    }
    ++m_inletLayer;
  }
  return entered;
}

// Where each parked particle is now (the set may have been reordered since it was parked). Blood
// is created after the wall and only reordered among itself, so its ids are [first, end).
void BloodLoop::locateParked(const pbd::Particles& particles, Index first) {
  m_parkedAt.assign(particles.size() - first, kFreeSlot);
  for (std::size_t i = first; i < particles.size(); ++i)
    if (!particles.active(i)) m_parkedAt[particles.id[i] - first] = Index(i);
}

// The first in line enters at `site` (m_parkedAt must be current).
void BloodLoop::enter(pbd::Particles& particles, Index first, const Vec3& site, const Vec3& velocity) {
  const Index id = m_queue.front();
  m_queue.pop_front();
  std::replace(m_lot.begin(), m_lot.end(), id, kFreeSlot);
  const Index i = m_parkedAt[id - first];
  particles.position[i] = particles.predicted[i] = site;
  particles.velocity[i] = velocity;
  particles.state[i] = pbd::ParticleState::Active;
}

std::size_t BloodLoop::reenter(pbd::Particles& particles, Index first) {
  if (m_queue.empty()) return 0;
  // Blood near the inflow vessel's far end: the sites must be clear of it, and re-entering
  // particles take its mean velocity (they join the moving column).
  const Orifice mitral = m_path.inflowEnd();
  const Real near = m_path.inflowTop - Real(m_inletLayers + 1) * m_spacing;
  locateParked(particles, first);
  m_occupied.clear();
  Vec3 velocity = Vec3::Zero();
  for (std::size_t i = first; i < particles.size(); ++i) {
    const Vec3& x = particles.position[i];
    if (!particles.active(i) || x.y() < near || mitral.radial(x) > mitral.radius + m_spacing) continue;
    m_occupied.push_back(x);
    velocity += particles.velocity[i];
  }
  if (!m_occupied.empty()) velocity /= Real(m_occupied.size());
  velocity = mitral.forward * std::max(Real(0), velocity.dot(mitral.forward));  // never back out
  const Real clear2 = Real(0.9 * 0.9) * m_spacing * m_spacing;
  std::size_t reentered = 0;
  for (const Vec3& site : m_inletSites) {
    if (m_queue.empty()) break;
    bool free = true;
    for (const Vec3& x : m_occupied) free = free && (x - site).squaredNorm() >= clear2;
    if (!free) continue;
    enter(particles, first, site, velocity);
    m_occupied.push_back(site);
    ++reentered;
  }
  return reentered;
}

void BloodLoop::save(pbd::StateWriter& w) const {
  w.section("blood loop");
  w.fields(m_inletMetered, m_inletTravel, m_inletVelocity, m_inletLayer, m_lot, m_queue);
}

void BloodLoop::load(pbd::StateReader& r) {
  r.section("blood loop");
  r.fields(m_inletMetered, m_inletTravel, m_inletVelocity, m_inletLayer, m_lot, m_queue);
}

}  // namespace hs::cardiac
