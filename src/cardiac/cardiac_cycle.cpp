#include "cardiac/cardiac_cycle.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hs::cardiac {

std::vector<Index> selectBeatingVertices(const CycleSettings& cycle, const LvModel& model) {
  const std::size_t n = model.mesh.vertices.size();
  std::vector<bool> chosen(n, false);
  const bool anySelection = !cycle.segments.empty() || !cycle.vertices.empty() || cycle.sphereEnabled;
  for (std::size_t v = 0; v < n; ++v) {
    const int segment = model.segment[v];
    if (!anySelection) {
      chosen[v] = model.region[v] == Region::Myocardium;
      continue;
    }
    if (std::find(cycle.segments.begin(), cycle.segments.end(), segment) != cycle.segments.end())
      chosen[v] = true;
    if (cycle.sphereEnabled &&
        (model.mesh.vertices[v] - cycle.sphereCentre).norm() <= cycle.sphereRadius)
      chosen[v] = true;
  }
  for (Index id : cycle.vertices) {
    if (id >= n) {
      throw std::invalid_argument("cycle.vertices: vertex id " + std::to_string(id) +
                                  " is out of range (the model has " + std::to_string(n) +
                                  " vertices, ids 0.." + std::to_string(n - 1) + ")");
    }
    if (std::binary_search(model.pinned.begin(), model.pinned.end(), id)) {
      throw std::invalid_argument("cycle.vertices: vertex " + std::to_string(id) +
                                  " is pinned (a vessel's far end) and cannot beat");
    }
    chosen[id] = true;
  }
  // Pinned vertices hold the heart in place; a sphere reaching them leaves them out.
  for (Index id : model.pinned) chosen[id] = false;
  std::vector<Index> out;
  for (std::size_t v = 0; v < n; ++v)
    if (chosen[v]) out.push_back(static_cast<Index>(v));
  return out;
}

void moveTowardCentre(std::vector<Vec3>& positions, std::vector<Vec3>& predicted,
                      const std::vector<Index>& particles, const Vec3& centre, Real displacement) {
  if (displacement == Real(0)) return;
  for (Index i : particles) {
    const Vec3 toCentre = centre - predicted[i];
    const Real distance = toCentre.norm();
    if (distance <= Real(0)) continue;
    const Vec3 move = (std::min(displacement, distance) / distance) * toCentre;
    predicted[i] += move;
    positions[i] += move;
  }
}

namespace {

// Physiological systole: each beating particle's prediction is set on its straight path from
// its anchor toward the centre, `travel` along it (never past the centre). Unlike the
// incremental move, x stays: the step's velocity (p - x)/dt is then the path's own velocity,
// and the constraint corrections of one step do not pile up in the next (p is set, not moved).
void followPath(std::vector<Vec3>& predicted, const BeatingRegion& region, const Vec3& centre) {
  const Real travel = region.clock.travel();
  for (std::size_t k = 0; k < region.particles.size(); ++k) {
    const Index i = region.particles[k];
    const Vec3 toCentre = centre - region.anchor[k];
    const Real distance = toCentre.norm();
    if (distance <= Real(0)) continue;
    predicted[i] = region.anchor[k] + (std::min(travel, distance) / distance) * toCentre;
  }
}

BeatClockSettings clockSettings(const CycleSettings& cycle) {
  BeatClockSettings s;
  s.physiological = cycle.mode == TimingMode::Physiological;
  s.systoleSteps = cycle.beatingDuration;
  s.diastoleSteps = cycle.beatingDuration;
  s.displacePerStep = cycle.beatingDisplace;
  s.period = Real(60) / cycle.heartRateBpm;
  s.systolicFraction = cycle.systolicFraction;
  s.contraction = cycle.contraction;
  s.beats = cycle.beats;
  s.seed = cycle.seed;
  s.irregularity = cycle.pattern == BeatPattern::Irregular ? cycle.irregularity : Real(0);
  return s;
}

std::vector<Index> toParticles(const std::vector<Index>& vertices, Index first) {
  std::vector<Index> out(vertices);
  for (Index& v : out) v += first;
  return out;
}

}  // namespace

CardiacCycle::CardiacCycle(const CycleSettings& cycle, const LvModel& model, Index firstParticle,
                           Real dt)
    : m_centre(model.centre) {
  if (!cycle.enabled) return;
  std::vector<Index> beating = selectBeatingVertices(cycle, model);
  const BeatClockSettings main = clockSettings(cycle);
  if (cycle.pattern != BeatPattern::Inconsistent) {
    m_regions.push_back({toParticles(beating, firstParticle), BeatClock(main, dt), {}});
    return;
  }
  // Inconsistent: the listed segments leave the main region and get their own clock, with
  // rate scaled by rateFactor (same contraction per beat) and started phaseOffset later.
  std::vector<Index> mainPart;
  std::vector<Index> offPart;
  for (Index v : beating) {
    const int segment = model.segment[v];
    const bool off = std::find(cycle.inconsistentSegments.begin(), cycle.inconsistentSegments.end(),
                               segment) != cycle.inconsistentSegments.end();
    (off ? offPart : mainPart).push_back(v);
  }
  BeatClockSettings other = main;
  const Real rate = cycle.inconsistentRateFactor;
  other.period = main.period / rate;
  other.systoleSteps = std::max(1, int(std::lround(double(main.systoleSteps) / double(rate))));
  other.diastoleSteps = other.systoleSteps;
  other.displacePerStep =
      main.displacePerStep * Real(main.systoleSteps) / Real(other.systoleSteps);
  other.beats = main.beats > 0 ? std::max(1, int(std::lround(main.beats * double(rate)))) : 0;
  BeatClock offClock(other, dt);
  const double cycleSteps = main.physiological ? double(other.period) / double(dt)
                                               : double(other.systoleSteps + other.diastoleSteps);
  offClock.delayStart(int(std::lround(cycleSteps * double(cycle.inconsistentPhaseOffset))));
  m_regions.push_back({toParticles(mainPart, firstParticle), BeatClock(main, dt), {}});
  m_regions.push_back({toParticles(offPart, firstParticle), offClock, {}});
}

void CardiacCycle::apply(std::vector<Vec3>& positions, std::vector<Vec3>& predicted) {
  for (BeatingRegion& region : m_regions) {
    if (!region.clock.physiological()) {
      moveTowardCentre(positions, predicted, region.particles, m_centre, region.clock.advance());
      continue;
    }
    const bool systole = region.clock.phase() == Phase::Systole;
    if (systole && region.clock.stepsInPhase() == 0) {
      region.anchor.resize(region.particles.size());
      for (std::size_t k = 0; k < region.particles.size(); ++k) region.anchor[k] = predicted[region.particles[k]];
    }
    region.clock.advance();
    if (systole) followPath(predicted, region, m_centre);
  }
}

Phase CardiacCycle::phase() const {
  return m_regions.empty() ? Phase::Rest : m_regions.front().clock.phase();
}

int CardiacCycle::beatsCompleted() const {
  return m_regions.empty() ? 0 : m_regions.front().clock.systolesCompleted();
}

}  // namespace hs::cardiac
