#pragma once
// The mitral and aortic valves as gates. Each orifice disc (flow_path.h) is a gate. A closed
// valve is a wall of zero thickness across the disc: a particle keeps its radius from it on
// the side it started the step on. An open valve lets particles through both ways, so a valve
// that closes late lets blood back (regurgitation). An open mitral valve with leaflets
// (FlowPath::mitralLeafletLength) hangs them into the cavity as a tube of the annulus's radius,
// again a wall of zero thickness: the inflow leaves it at the leaflets' tips, where its vortex
// ring forms (Elbaz et al. 2014), not at the annulus. When valves open (ValveMode):
//   Timing    thesis: the mitral valve is open in diastole, the aortic in systole; both open
//             when the cycle is off.
//   Pressure  physiological: a valve is open while the pressure just before it exceeded the
//             pressure just after it in the last step (flow_meter.h measures them).
//   Open      both always open.
#include <optional>
#include <span>
#include <vector>

#include "cardiac/anatomy/flow_path.h"
#include "cardiac/circulation/beat_clock.h"
#include "pbd/core/particles.h"

namespace hs::cardiac {

// How the valves open and close ([circulation] valve_mode): by the cycle's timing, by the
// pressures across them, or never closed.
enum class ValveMode { Timing, Pressure, Open };

using pbd::Index;

struct ValveStates {
  bool mitralOpen = true;
  bool aorticOpen = true;
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);
};

// The pressures (Pa) just before and after each valve, as the pressure mode compares them.
struct ValvePressures {
  double mitralUpstream = 0, mitralDownstream = 0, aorticUpstream = 0, aorticDownstream = 0;
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);
};

// Which valves are open in timing mode for the wall's phase.
ValveStates timedValves(bool cycleEnabled, Phase phase);

// Moves p so it keeps `radius` from a closed orifice disc on the side x (its start-of-step
// position) lies on; points beyond the disc's rim are the wall's business. Returns true if p
// moved.
bool gateClosedOrifice(const Orifice& orifice, const Vec3& x, Vec3& p, Real radius);

// Moves p so it keeps `radius` from open leaflets hanging `length` downstream of the orifice
// as a tube of its radius, on the side (inside or outside the tube) x lies on; points upstream
// of the orifice or beyond the tips are the wall's and the other gates' business. Returns true
// if p moved.
bool gateOpenLeaflets(const Orifice& orifice, Real length, const Vec3& x, Vec3& p, Real radius);

class Valves {
 public:
  Valves(const FlowPath& path, ValveMode mode, bool cycleEnabled, Real bloodRadius);

  // Start of a step: the valves for this step, from the wall's phase and the last step's
  // pressures.
  void decide(Phase phase, const ValvePressures& lastStep);
  // The lumped circulation's valves (lumped_circulation.h) instead: open while blood flows forward.
  void follow(const ValveStates& states) { m_states = states; }
  // The valves sit in the orifices where they are now (a descending base carries them).
  void follow(const FlowPath& path) {
    m_mitral = path.mitralValve();
    m_aortic = path.aorticValve();
  }
  // A stenotic aortic valve: open, it lets blood through a central opening of this radius only
  // (m, smaller than the orifice); the ring around it stays shut.
  void narrowAorticOpening(Real radius) { m_aorticOpening = radius; }
  [[nodiscard]] const ValveStates& states() const { return m_states; }
  // Checkpoints: the valves' states (their orifices follow the wall at every step's start).
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);

  // Closed valves as walls: for the fluid solver's working positions (points[k] is particle
  // ids[k]), and for the particle set's predictions of [first, end).
  void gatePoints(const pbd::Particles& particles, std::vector<Vec3>& points, std::span<const Index> ids) const;
  void gateParticles(pbd::Particles& particles, Index first) const;

 private:
  // The closed valves' gates, and the open mitral valve's leaflets, for a particle that started
  // the step at x and is predicted at p.
  void gate(const Vec3& x, Vec3& p) const;
  // Whether this step has anything to gate (a closed valve, a stenotic ring, open leaflets).
  [[nodiscard]] bool gates() const;

  Orifice m_mitral, m_aortic;
  std::optional<Real> m_aorticOpening;
  Real m_mitralLeaflets;  // FlowPath::mitralLeafletLength
  ValveMode m_mode;
  bool m_cycleEnabled;
  Real m_radius;
  ValveStates m_states;
};

}  // namespace hs::cardiac
