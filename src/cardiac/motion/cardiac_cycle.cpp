#include "cardiac/motion/cardiac_cycle.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "cardiac/motion/base_taper.h"

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
// its anchor to its end-systolic target, a fraction travel/contraction of the way. Unlike the
// incremental move, x stays: the step's velocity (p - x)/dt is then the path's own velocity,
// and the constraint corrections of one step do not pile up in the next (p is set, not moved).
void followPath(std::vector<Vec3>& predicted, const BeatingRegion& region, Real contraction) {
  const Real fraction = contraction > Real(0) ? std::min(Real(1), region.clock.travel() / contraction) : Real(0);
  for (std::size_t k = 0; k < region.particles.size(); ++k)
    predicted[region.particles[k]] = region.anchor[k] + fraction * (region.target[k] - region.anchor[k]);
}

// Physiological relaxation: back from the end-systolic positions to rest along the same smooth
// ramp, over `seconds`; `elapsed` is the time in diastole at the end of this step.
void relaxPath(std::vector<Vec3>& predicted, const BeatingRegion& region, double elapsed, double seconds) {
  const double s = std::clamp(elapsed / seconds, 0.0, 1.0);
  const Real g = Real(s - std::sin(2.0 * std::numbers::pi * s) / (2.0 * std::numbers::pi));
  for (std::size_t k = 0; k < region.particles.size(); ++k)
    predicted[region.particles[k]] = region.endSystole[k] + g * (region.rest[k] - region.endSystole[k]);
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
  s.irregularBothWays = cycle.irregularBothWays;
  return s;
}

std::vector<Vec3> restOf(const std::vector<Index>& vertices, const LvModel& model) {
  std::vector<Vec3> out;
  out.reserve(vertices.size());
  for (Index v : vertices) out.push_back(model.mesh.vertices[v]);
  return out;
}

// The beating shell at end-systole with the base held: volume_driven_wall.h's two half prolate
// spheroids without the base's descent. The endocardium's widest radius a_i moves in by the
// contraction; the epicardium keeps its apex and its base (c_o) and moves in only as the wall,
// incompressible, thickens uniformly from h to h':
//   (a_i' + h')^2 c_o - a_i'^2 (c_o - h') = a_o^2 c_o - a_i^2 c_i,   a_o = a_i + h, c_o = c_i + h,
// so the endocardial apex rises by h' - h (the apex thickens as the sides do). The left side
// grows with h' (bisection). Ratios of the new radii and long axes to the rest ones.
struct HeldShell {
  Real endoAcross = 1, endoAlong = 1, epiAcross = 1;
};

HeldShell heldShell(const LvGeometryParams& g, Real contraction) {
  const double ai = double(g.endoRadius), ci = double(g.endoLongAxis), h = double(g.wallThickness);
  const double ao = ai + h, co = ci + h;
  const double wall = ao * ao * co - ai * ai * ci;
  const double ai2 = std::max(ai - double(contraction), 0.0);
  double low = 0, high = co;
  for (int i = 0; i < 60; ++i) {
    const double t = 0.5 * (low + high);
    ((ai2 + t) * (ai2 + t) * co - ai2 * ai2 * (co - t) < wall ? low : high) = t;
  }
  const double h2 = 0.5 * (low + high);
  return {Real(ai2 / ai), Real((co - h2) / ci), Real((ai2 + h2) / ao)};
}

// Where a systole takes each beating vertex (physiological mode):
//  * the thesis's push: its rest position moved `contraction` toward the centre, never past it;
//  * with the base held (cycle.base_held): the held shell above. Each section shrinks about the
//    long axis (x = z = 0) by its layer's ratio, faded to none at the base plane (base_taper.h);
//    the endocardium (even ids) also shortens toward the base plane, y' = y c_i'/c_i; the
//    epicardium (odd ids) keeps its heights. Pushing toward one point, or moving both layers
//    alike, crushes the wall's tets or stretches its surface, and the constraints, resisting,
//    fold it (surface turns of 71-118 degrees).
std::vector<Vec3> endSystoleTargets(const std::vector<Index>& vertices, const LvModel& model, const Vec3& centre,
                                    const CycleSettings& cycle) {
  const std::vector<Vec3>& x = model.mesh.vertices;
  const HeldShell shell = cycle.baseHeld ? heldShell(model.params, cycle.contraction) : HeldShell{};
  std::vector<Vec3> out;
  out.reserve(vertices.size());
  for (Index v : vertices) {
    const Vec3& rest = x[v];
    if (cycle.baseHeld) {
      const bool endo = v % 2 == 0;
      const Real ratio = endo ? shell.endoAcross : shell.epiAcross;
      const Real across = 1 - baseTaper(rest.y(), double(model.longAxisLength)) * (1 - ratio);
      out.push_back(Vec3(across * rest.x(), endo ? rest.y() * shell.endoAlong : rest.y(), across * rest.z()));
      continue;
    }
    const Vec3 toCentre = centre - rest;
    const Real distance = toCentre.norm();
    out.push_back(distance > Real(0) ? rest + (std::min(cycle.contraction, distance) / distance) * toCentre : rest);
  }
  return out;
}

std::vector<Index> toParticles(const std::vector<Index>& vertices, Index first) {
  std::vector<Index> out(vertices);
  for (Index& v : out) v += first;
  return out;
}

}  // namespace

CardiacCycle::CardiacCycle(const CycleSettings& cycle, const LvModel& model, Index firstParticle)
    : m_centre(model.centre), m_contraction(cycle.contraction) {
  if (!cycle.enabled) return;
  m_kinematic = cycle.baseHeld && cycle.mode == TimingMode::Physiological;
  // A kinematic wall returns to rest only along the relaxation's path: without one it would jump.
  if (m_kinematic && !(cycle.relaxationFraction > 0))
    throw std::invalid_argument("cycle.relaxation_fraction: got 0; expected more than 0 with cycle.base_held = true "
                                "(the held wall returns to rest only along the relaxation)");
  {
    // Relaxation lasts a share of the regular diastole (the irregular pattern cuts diastoles).
    const double period = 60.0 / double(cycle.heartRateBpm);
    m_relaxationSeconds = double(cycle.relaxationFraction) * period * (1.0 - double(cycle.systolicFraction));
  }
  std::vector<Index> beating = selectBeatingVertices(cycle, model);
  // A heart told to beat with nothing to move would beat nothing without a word.
  if (beating.empty())
    throw std::invalid_argument("cycle.sphere: the beating region (cycle.segments, cycle.vertices and [cycle.sphere]) "
                                "selects no wall vertex that can move; expected a sphere that reaches the wall, "
                                "segments 1-17 or myocardium vertex ids");
  const BeatClockSettings main = clockSettings(cycle);
  if (cycle.pattern != BeatPattern::Inconsistent) {
    m_regions.push_back({toParticles(beating, firstParticle), BeatClock(main), {}, restOf(beating, model), {},
                         endSystoleTargets(beating, model, m_centre, cycle)});
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
  other.startDelay = cycle.inconsistentPhaseOffset;
  const BeatClock offClock(other);
  m_regions.push_back({toParticles(mainPart, firstParticle), BeatClock(main), {}, restOf(mainPart, model), {},
                       endSystoleTargets(mainPart, model, m_centre, cycle)});
  m_regions.push_back({toParticles(offPart, firstParticle), offClock, {}, restOf(offPart, model), {},
                       endSystoleTargets(offPart, model, m_centre, cycle)});
}

void CardiacCycle::apply(std::vector<Vec3>& positions, std::vector<Vec3>& predicted, const pbd::StepContext& context) {
  const Real dt = context.dt;
  for (BeatingRegion& region : m_regions) {
    if (!region.clock.physiological()) {
      moveTowardCentre(positions, predicted, region.particles, m_centre, region.clock.advance(dt));
      continue;
    }
    const Phase phase = region.clock.phase();
    const int step = region.clock.stepsInPhase();
    if (phase == Phase::Systole && step == 0) {
      region.anchor.resize(region.particles.size());
      for (std::size_t k = 0; k < region.particles.size(); ++k) region.anchor[k] = predicted[region.particles[k]];
    }
    if (phase == Phase::Diastole && step == 0) {
      region.endSystole.resize(region.particles.size());
      for (std::size_t k = 0; k < region.particles.size(); ++k) region.endSystole[k] = positions[region.particles[k]];
    }
    region.clock.advance(dt);
    if (phase == Phase::Systole) {
      followPath(predicted, region, m_contraction);
    } else if (phase == Phase::Diastole && m_relaxationSeconds > 0 && !region.endSystole.empty()) {
      const double elapsed = double(step + 1) * double(dt);
      if (m_kinematic || elapsed <= m_relaxationSeconds + 0.5 * double(dt))
        relaxPath(predicted, region, elapsed, m_relaxationSeconds);  // at rest once relaxed
    } else if (m_kinematic) {  // before the first systole or after the last beat: at rest
      for (std::size_t k = 0; k < region.particles.size(); ++k) predicted[region.particles[k]] = region.rest[k];
    }
  }
}

void CardiacCycle::advanceClocks(Real dt) {
  for (BeatingRegion& region : m_regions) region.clock.advance(dt);
}

Phase CardiacCycle::phase() const {
  return m_regions.empty() ? Phase::Rest : m_regions.front().clock.phase();
}

int CardiacCycle::beatsCompleted() const {
  return m_regions.empty() ? 0 : m_regions.front().clock.systolesCompleted();
}

void CardiacCycle::save(pbd::StateWriter& w) const {
  w.section("cardiac cycle");
  w.put(std::uint64_t(m_regions.size()));
  for (const BeatingRegion& region : m_regions) w.fields(region.clock, region.anchor, region.endSystole);
}

void CardiacCycle::load(pbd::StateReader& r) {
  r.section("cardiac cycle");
  const std::size_t at = r.offset();
  std::uint64_t count = 0;
  r.get(count);
  if (count != m_regions.size())
    throw pbd::StateError("cardiac cycle: " + std::to_string(count) + " beating regions where the scenario has " +
                              std::to_string(m_regions.size()),
                          at);
  for (BeatingRegion& region : m_regions) r.fields(region.clock, region.anchor, region.endSystole);
}

}  // namespace hs::cardiac
