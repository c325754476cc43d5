#pragma once
// What flows where in one step: the particles that crossed each orifice disc forward and
// backward (between their start-of-step and end-of-step positions; one particle carries the
// volume m / rho0 = spacing^3), the blood in each region of the path and its mean pressure,
// and the pressures just before and after each valve (blood within two spacings of the disc),
// which the valves' pressure mode compares; and what pulsed-wave Doppler reads in each orifice
// (echo_velocities.h).
#include <array>
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "cardiac/anatomy/flow_path.h"
#include "cardiac/blood/blood_settings.h"
#include "cardiac/circulation/beat_metrics.h"
#include "cardiac/circulation/valves.h"
#include "pbd/core/particles.h"

namespace hs::cardiac {

// +1 forward, -1 backward, 0 no crossing of the disc between x and p.
int crossing(const Orifice& orifice, const Vec3& x, const Vec3& p);

struct FlowStep {
  std::array<std::size_t, kFlowRegionCount> count{};  // particles per FlowRegion
  std::array<double, kFlowRegionCount> pressure{};     // Pa, mean per region (0 if empty)
  // Particles that crossed each orifice in the step, forward and backward.
  std::size_t mitralForward = 0, mitralBackward = 0, aorticForward = 0, aorticBackward = 0;
  // m/s, the fastest single particle that crossed the aortic disc forward: PBF's particle noise
  // rides on it (~0.5 m/s), so it is not the jet's velocity; aorticEcho is.
  double aorticJet = 0;
  // m/s, the Doppler readings (echo_velocities.h): the mean over the blood within one spacing of
  // each valve's disc, inside its rim (a stenotic valve's opening), of the smoothed velocity along
  // the disc's forward normal; 0 with no blood there or no smoothed field given.
  double aorticEcho = 0, mitralEcho = 0;
  std::size_t returned = 0;   // particles that left through a vessel end this step
  std::size_t reentered = 0;  // parked particles that re-entered the inflow vessel
  ValveStates valves;         // during the step
  ValvePressures valvePressures;
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);
};

class FlowMeter {
 public:
  // `atrialPressurePa`: the filling pressure, added on the mitral valve's upstream side (the
  // atrium is not modelled, filling_force.h).
  FlowMeter(const FlowPath& path, const BloodSettings& blood, double atrialPressurePa);

  // Start of a step: remembers where the blood [first, end) starts.
  void begin(const pbd::Particles& particles, Index first);
  // End of a step: crossings, regions and pressures of the active blood. `pressures` is
  // indexed by particle (pbd::FluidSolver::pressures()). The regions are found on `threads`
  // threads (a patient's cavity test is the costly part); the sums run in particle order.
  // `smoothed`: the smoothed velocity by particle (pbd::FluidSolver::smoothedVelocities), read
  // for the Doppler readings; empty: none taken.
  void measure(const pbd::Particles& particles, Index first, const std::vector<Real>& pressures,
               const ValveStates& valves, int threads = 1, std::span<const Vec3> smoothed = {});
  // The closed loop's share of the step (blood_loop.h): left, re-entered, waiting.
  void recordLoop(std::size_t returned, std::size_t reentered, std::size_t waiting);

  [[nodiscard]] const FlowStep& lastStep() const { return m_last; }
  // The region of each blood particle at the last step's end, by storage order from `first`
  // (stale for a parked particle: read it with the particle's active flag).
  [[nodiscard]] const std::vector<FlowRegion>& regions() const { return m_regions; }
  // Volumes through the two orifices in the step just measured (m^3).
  [[nodiscard]] ValveFlows lastStepFlows() const;
  [[nodiscard]] Real particleVolume() const { return m_particleVolume; }
  // Measure at the orifices where they are now (a descending base carries them); call before
  // begin(): a step's crossings are counted against one plane.
  void follow(const FlowPath& path) { m_path = path; }
  // A stenotic aortic valve opens to a central disc of this radius (Valves::narrowAorticOpening):
  // the Doppler reading samples the opening, not the closed cusps around it.
  void narrowAorticOpening(Real radius) { m_aorticOpening = radius; }
  // Checkpoints: the last step (the valves' pressure mode reads it); the start positions and
  // the orifices are set anew at every step's start.
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);

 private:
  FlowPath m_path;
  Real m_radius, m_spacing, m_particleVolume;
  Real m_aorticOpening = std::numeric_limits<Real>::infinity();  // m, see narrowAorticOpening
  double m_atrialPressurePa;
  std::vector<Vec3> m_start;          // blood start-of-step positions (blood index)
  std::vector<FlowRegion> m_regions;  // scratch: each blood particle's region this step
  FlowStep m_last;
};

}  // namespace hs::cardiac
