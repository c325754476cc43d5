#pragma once
// The blood's path through the LV model: inflow vessel -> mitral orifice -> ventricle ->
// aortic orifice -> outflow vessel -> (the body) -> inflow vessel again.
//
// Valves. Each orifice (the lumen disc where a vessel meets the cavity, y = 0 in model
// coordinates) is a gate. A closed valve is a wall of zero thickness across the disc: a
// particle keeps its radius from it on the side it started the step on. An open valve lets
// particles through both ways, so a valve that closes late lets blood back (regurgitation).
// When valves open (ValveMode):
//   Timing    thesis: the mitral valve is open in diastole, the aortic in systole; both open
//             when the cycle is off.
//   Pressure  physiological: a valve is open while the pressure just before it exceeds the
//             pressure just after it (mean solver pressure of the blood within two spacings of
//             the disc on each side; the filling pressure is added on the inflow side).
//   Open      both always open.
//
// Filling pressure. The atrium is not modelled; its pressure P_a drives the inflow vessel:
// blood in it feels a body force along the vessel, rho a L = P_a over the vessel's length L,
// the same pressure difference an atrium at P_a would apply at the vessel's far end.
//
// Closed loop. A particle that passes the far end of either vessel has left the model (into
// the body or back into the atrium). It waits in a queue (parked: pinned, out of the way, not
// drawn) and re-enters, first in first out, at a free site of the inflow vessel's far end,
// moving with the blood there. The particle count never changes.
//
// Flow. Each step counts the particles that crossed each orifice disc forward and backward,
// between their start-of-step and end-of-step positions; one particle carries the volume
// m / rho0 = spacing^3.
#include <array>
#include <cstdint>
#include <deque>
#include <span>
#include <vector>

#include "cardiac/beat_clock.h"
#include "cardiac/beat_metrics.h"
#include "cardiac/lv_model.h"
#include "cardiac/scenario.h"
#include "pbd/particles.h"

namespace hs::cardiac {

enum class FlowRegion : std::uint8_t { InflowVessel = 0, Ventricle = 1, OutflowVessel = 2, Parked = 3, Outside = 4 };
inline constexpr std::size_t kFlowRegionCount = 5;

// One orifice disc: centre, unit normal pointing downstream (forward flow), lumen radius.
struct Orifice {
  Vec3 centre = Vec3::Zero();
  Vec3 forward = Vec3::UnitY();
  Real radius = 0;
  // Signed distance along `forward`: < 0 upstream, >= 0 downstream.
  [[nodiscard]] Real side(const Vec3& x) const { return forward.dot(x - centre); }
  // Distance from the disc's axis.
  [[nodiscard]] Real radial(const Vec3& x) const {
    const Vec3 d = x - centre;
    return (d - forward.dot(d) * forward).norm();
  }
};

// Moves p so it keeps `radius` from a closed orifice disc on the side x (its start-of-step
// position) lies on; points beyond the disc's rim are the wall's business. Returns true if p
// moved.
bool gateClosedOrifice(const Orifice& orifice, const Vec3& x, Vec3& p, Real radius);

// +1 forward, -1 backward, 0 no crossing of the disc between x and p.
int crossing(const Orifice& orifice, const Vec3& x, const Vec3& p);

struct ValveStates {
  bool mitralOpen = true;
  bool aorticOpen = true;
};

// Which valves are open in timing mode for the wall's phase.
ValveStates timedValves(bool cycleEnabled, Phase phase);

struct FlowStep {
  std::array<std::size_t, kFlowRegionCount> count{};  // particles per FlowRegion
  std::array<double, kFlowRegionCount> pressure{};     // Pa, mean per region (0 if empty)
  // Particles that crossed each orifice in the step, forward and backward.
  std::size_t mitralForward = 0, mitralBackward = 0, aorticForward = 0, aorticBackward = 0;
  std::size_t returned = 0;  // particles that left through a vessel end this step
  std::size_t reentered = 0;  // parked particles that re-entered the inflow vessel
  ValveStates valves;         // during the step
  // Pressures at the valves (Pa), as the pressure mode compares them.
  double mitralUpstream = 0, mitralDownstream = 0, aorticUpstream = 0, aorticDownstream = 0;
};

class Circulation {
 public:
  // The flow path of `model` (rest geometry) for blood of the given spacing and radius.
  Circulation(const LvModel& model, const CirculationSettings& settings, const BloodSettings& blood,
              const CycleSettings& cycle);

  [[nodiscard]] const Orifice& mitral() const { return m_mitral; }
  [[nodiscard]] const Orifice& aortic() const { return m_aortic; }
  [[nodiscard]] FlowRegion classify(const Vec3& x) const;

  // Start of a step: decides the valves for this step (from the wall's phase and the last
  // step's pressures), remembers where the blood starts, and applies the filling pressure's
  // body force to the inflow vessel's blood (v += a dt).
  void beginStep(pbd::Particles& particles, Index first, Phase phase, Real dt);
  // Closed valves as walls, for the solver's working copy (points[k] is particle ids[k]) and
  // for the particle set's predictions.
  void gatePoints(const pbd::Particles& particles, std::vector<Vec3>& points, std::span<const Index> ids) const;
  void gateParticles(pbd::Particles& particles, Index first) const;
  // End of a step: counts orifice crossings and regions, parks particles that left through a
  // vessel end and lets waiting ones re-enter. `pressures` is indexed by particle (the fluid
  // solver's pressures()).
  void endStep(pbd::Particles& particles, Index first, const std::vector<Real>& pressures);

  // The last `count` blood particles start outside the model, queued to enter.
  void startWaiting(pbd::Particles& particles, Index first, std::size_t count);

  [[nodiscard]] const FlowStep& lastStep() const { return m_last; }
  // Volumes through the two orifices in the step just taken (m^3): the crossing particles,
  // each carrying m / rho0.
  [[nodiscard]] ValveFlows lastStepFlows() const;
  [[nodiscard]] const ValveStates& valves() const { return m_valves; }
  // Particle i (a particle id) is parked outside the model, waiting to re-enter.
  [[nodiscard]] bool parked(Index particle) const;
  // Blood particles are reordered (HeartSimulation::reorderBlood): order[k] is the old blood
  // index now at blood index k.
  void permute(std::span<const Index> order);
  [[nodiscard]] Real particleVolume() const { return m_particleVolume; }
  [[nodiscard]] const CirculationSettings& settings() const { return m_settings; }

 private:
  // The closed valves' gates for a particle that started the step at x and is predicted at p.
  void gate(const Vec3& x, Vec3& p) const;
  Vec3 parkingSite(std::size_t k) const;
  void park(pbd::Particles& particles, Index particle);
  void reenter(pbd::Particles& particles, Index first);
  void decideValves(Phase phase);

  CirculationSettings m_settings;
  bool m_cycleEnabled = true;
  Orifice m_mitral, m_aortic;
  Real m_inflowTop = 0, m_outflowTop = 0;  // y of the vessels' far ends
  Real m_inflowLength = 0;
  Vec3 m_apexAxisOrigin = Vec3::Zero();  // the endocardial spheroid's centre (lv_model.h)
  Real m_midWallRadius = 0, m_midWallLongAxis = 0;
  Real m_plateMid = 0;  // half the base plate's thickness
  Real m_spacing = 0, m_radius = 0, m_restDensity = 0, m_particleVolume = 0;
  std::vector<Vec3> m_inletSites;  // lattice sites across the inflow vessel's far end
  Vec3 m_parkingOrigin = Vec3::Zero();
  Real m_parkingPitch = 0;
  static constexpr Index kFreeSlot = ~Index(0);
  std::vector<Index> m_lot;            // parking site k holds this blood index (or kFreeSlot)
  Real m_inverseMass = 0;              // of a blood particle, restored when it re-enters
  Index m_first = 0;                   // first blood particle
  std::vector<Vec3> m_scratch;
  ValveStates m_valves;
  FlowStep m_last;
  std::vector<Vec3> m_start;           // blood start-of-step positions (blood index)
  std::vector<std::uint8_t> m_parked;  // per blood index
  std::deque<Index> m_queue;           // parked blood indices, first in first out
};

}  // namespace hs::cardiac
