#include "cardiac/blood/flow_meter.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace hs::cardiac {

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

FlowMeter::FlowMeter(const FlowPath& path, const BloodSettings& blood, double atrialPressurePa)
    : m_path(path),
      m_radius(blood.radius),
      m_spacing(blood.spacing),
      m_particleVolume(blood.spacing * blood.spacing * blood.spacing),
      m_atrialPressurePa(atrialPressurePa) {}

void FlowMeter::begin(const pbd::Particles& particles, Index first) {
  m_start.assign(particles.position.begin() + first, particles.position.end());
}

namespace {

// Mean pressure just before (slot 0) and after (slot 1) an orifice: blood within `slab` of its
// disc, inside its rim.
struct ValveSample {
  double sum[2] = {0, 0};
  std::size_t count[2] = {0, 0};
  void add(const Orifice& o, const Vec3& x, Real p, Real slab) {
    const Real side = o.side(x);
    if (std::abs(side) > slab || o.radial(x) >= o.radius) return;
    const int k = side >= Real(0) ? 1 : 0;
    sum[k] += double(p);
    ++count[k];
  }
  [[nodiscard]] double mean(int k) const { return count[k] > 0 ? sum[k] / double(count[k]) : 0.0; }
};

// A Doppler sample volume in an orifice (echo_velocities.h): the smoothed velocity along the
// disc's forward normal, summed over the blood within `slab` of the disc, inside its rim or the
// valve's narrower opening.
struct DopplerSample {
  double sum = 0;
  std::size_t count = 0;
  void add(const Orifice& o, const Vec3& x, const Vec3& smoothed, Real slab, Real opening) {
    if (std::abs(o.side(x)) > slab || o.radial(x) >= std::min(o.radius, opening)) return;
    sum += double(o.forward.dot(smoothed));
    ++count;
  }
  [[nodiscard]] double mean() const { return count > 0 ? sum / double(count) : 0.0; }
};

// Below this many blood particles the regions are found on one thread.
constexpr std::ptrdiff_t kParallelRegions = 1024;

}  // namespace

void FlowMeter::measure(const pbd::Particles& particles, Index first, const std::vector<Real>& pressures,
                        const ValveStates& valves, int threads, std::span<const Vec3> smoothed) {
  assert(m_start.size() == particles.size() - first);
  // Each particle's region first, in parallel (a pure function of its position), so that the
  // sums below keep one order for any thread count.
  const auto blood = std::ptrdiff_t(particles.size() - first);
  m_regions.resize(std::size_t(blood));
#pragma omp parallel for schedule(dynamic, 256) num_threads(threads) if (blood >= kParallelRegions)
  for (std::ptrdiff_t b = 0; b < blood; ++b) {
    const std::size_t i = first + std::size_t(b);
    if (particles.active(i)) m_regions[std::size_t(b)] = m_path.classify(particles.position[i], m_radius, m_spacing);
  }
  FlowStep s;
  s.valves = valves;
  std::array<double, kFlowRegionCount> pressureSum{};
  ValveSample mitral, aortic;
  DopplerSample mitralDoppler, aorticDoppler;
  const Real slab = 2 * m_spacing;
  const bool doppler = smoothed.size() == particles.size();
  for (std::size_t i = first; i < particles.size(); ++i) {
    if (!particles.active(i)) continue;
    const Vec3& x0 = m_start[i - first];
    const Vec3& x1 = particles.position[i];
    const int m = crossing(m_path.mitralValve(), x0, x1);
    const int a = crossing(m_path.aorticValve(), x0, x1);
    s.mitralForward += m > 0, s.mitralBackward += m < 0;
    s.aorticForward += a > 0, s.aorticBackward += a < 0;
    if (a > 0) s.aorticJet = std::max(s.aorticJet, double(particles.velocity[i].norm()));
    const Real p = i < pressures.size() ? pressures[i] : Real(0);
    const FlowRegion r = m_regions[i - first];
    ++s.count[std::size_t(r)];
    pressureSum[std::size_t(r)] += double(p);
    mitral.add(m_path.mitralValve(), x1, p, slab);
    aortic.add(m_path.aorticValve(), x1, p, slab);
    if (doppler) {
      mitralDoppler.add(m_path.mitralValve(), x1, smoothed[i], m_spacing, m_path.mitralValve().radius);
      aorticDoppler.add(m_path.aorticValve(), x1, smoothed[i], m_spacing, m_aorticOpening);
    }
  }
  s.mitralEcho = mitralDoppler.mean();
  s.aorticEcho = aorticDoppler.mean();
  for (std::size_t r = 0; r < kFlowRegionCount; ++r)
    s.pressure[r] = s.count[r] > 0 ? pressureSum[r] / double(s.count[r]) : 0.0;
  s.valvePressures = {mitral.mean(0) + m_atrialPressurePa, mitral.mean(1), aortic.mean(0), aortic.mean(1)};
  m_last = s;
}

void FlowMeter::recordLoop(std::size_t returned, std::size_t reentered, std::size_t waiting) {
  m_last.returned = returned;
  m_last.reentered = reentered;
  m_last.count[std::size_t(FlowRegion::Parked)] = waiting;
}

ValveFlows FlowMeter::lastStepFlows() const {
  const double v = double(m_particleVolume);
  return {double(m_last.mitralForward) * v, double(m_last.mitralBackward) * v, double(m_last.aorticForward) * v,
          double(m_last.aorticBackward) * v};
}

void FlowStep::save(pbd::StateWriter& w) const {
  w.fields(count, pressure, mitralForward, mitralBackward, aorticForward, aorticBackward, aorticJet, aorticEcho, mitralEcho, returned, reentered, valves, valvePressures);
}

void FlowStep::load(pbd::StateReader& r) {
  r.fields(count, pressure, mitralForward, mitralBackward, aorticForward, aorticBackward, aorticJet, aorticEcho, mitralEcho, returned, reentered, valves, valvePressures);
}

void FlowMeter::save(pbd::StateWriter& w) const {
  w.section("flow meter");
  w.fields(m_last);
}

void FlowMeter::load(pbd::StateReader& r) {
  r.section("flow meter");
  r.fields(m_last);
}

}  // namespace hs::cardiac
