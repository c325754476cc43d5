#include "cardiac/blood/ventricle_blood.h"

#include <algorithm>
#include <cassert>

#include "cardiac/blood/echo_velocities.h"

namespace hs::cardiac {

VentricleBlood::VentricleBlood(const pbd::Particles& particles, pbd::Index first)
    : m_first(first), m_tracker(particles.size() - first), m_inVentricle(particles.size() - first, 0) {}

double VentricleBlood::observe(const pbd::Particles& particles, std::span<const FlowRegion> regions,
                               std::span<const pbd::Vec3> velocities, HeartPhase before, HeartPhase after,
                               double time) {
  assert(regions.size() == particles.size() - m_first);
  assert(velocities.size() == particles.size());
  // In particle order, so that the energy's sum is the same for any thread count.
  double energy = 0;
  for (std::size_t i = m_first; i < particles.size(); ++i) {
    const bool inside = particles.active(i) && regions[i - m_first] == FlowRegion::Ventricle;
    m_inVentricle[particles.id[i] - m_first] = inside;
    if (inside && particles.inverseMass[i] > 0)
      energy += 0.5 * double(velocities[i].squaredNorm()) / double(particles.inverseMass[i]);  // m |v~|^2 / 2
  }
  m_tracker.observe(m_inVentricle);
  const bool filled = endDiastoleBetween(before, after);
  const bool ejected = before == HeartPhase::Ejection && after != HeartPhase::Ejection;
  if (filled) {
    m_tracker.endDiastole();
    if (m_endDiastole >= 0 && m_energySteps > 0)
      m_cycles.push_back({m_endDiastole, time, m_energySum / double(m_energySteps), m_fillingPeak});
    m_endDiastole = time;
    m_energySum = m_fillingPeak = 0;
    m_energySteps = 0;
  }
  m_energySum += energy;
  ++m_energySteps;
  if (after == HeartPhase::Filling) m_fillingPeak = std::max(m_fillingPeak, energy);
  if (ejected)
    if (const std::optional<FlowComponents> shares = m_tracker.endSystole()) m_beats.push_back({m_endDiastole, *shares});
  return energy;
}

std::optional<FlowComponents> meanFlowComponents(std::span<const BeatFlowComponents> beats, std::size_t skipped) {
  if (beats.size() <= skipped) return std::nullopt;
  FlowComponents mean;
  for (const BeatFlowComponents& b : beats.subspan(skipped)) {
    mean.direct += b.shares.direct, mean.retainedInflow += b.shares.retainedInflow;
    mean.delayedEjection += b.shares.delayedEjection, mean.residual += b.shares.residual;
    mean.meanResidenceBeats += b.shares.meanResidenceBeats, mean.stayedOverThreeBeats += b.shares.stayedOverThreeBeats;
  }
  const double n = double(beats.size() - skipped);
  mean.direct /= n, mean.retainedInflow /= n, mean.delayedEjection /= n, mean.residual /= n;
  mean.meanResidenceBeats /= n, mean.stayedOverThreeBeats /= n;
  return mean;
}

void VentricleBlood::save(pbd::StateWriter& w) const {
  m_tracker.save(w);
  w.fields(m_endDiastole, m_beats, m_energySum, m_fillingPeak, m_energySteps, m_cycles);
}

void VentricleBlood::load(pbd::StateReader& r) {
  m_tracker.load(r);
  r.fields(m_endDiastole, m_beats, m_energySum, m_fillingPeak, m_energySteps, m_cycles);
}

}  // namespace hs::cardiac
