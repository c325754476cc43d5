#pragma once
// The vessels' far ends as the lumped circulation's boundaries, where blood enters and leaves
// as its flows say: an inflow and an outflow buffer of the kind open-boundary SPH uses (Federico
// et al. 2012, Tafuni et al. 2018). The blood within one kernel support under each far end is a
// plug, kinematic along its vessel: the density solve and the wall still place it across the
// lumen, but it moves along the vessel as the lumped model says, so the column under it meets a
// full neighbourhood of blood that moves with the atrium or the aorta. Blood the outflow's plug
// carries past the far end leaves (BloodLoop parks it); blood enters behind the inflow's plug
// at free sites (BloodLoop re-entry).
//
// The ends' own figures: the vessels' ends are pinned while their roots descend with the base
// (rate w), so each vessel stretches and gains volume at w A_mean (A_mean its lumen's mean
// cross-section, VesselShape::meanAreaShare: the end's own area A for a straight vessel, more for
// an atrium or a root with sinuses). The inflow's end takes in Q_mitral + w A_mean and the
// outflow's lets out Q_aortic - w A_mean (A the far end's area, which holds one particle per
// spacing^2 at rest density).
#include <cstdint>
#include <span>
#include <vector>

#include "cardiac/anatomy/flow_path.h"
#include "cardiac/blood/blood_settings.h"
#include "pbd/core/particles.h"
#include "pbd/core/state_stream.h"

namespace hs::cardiac {

class VesselEnds {
 public:
  VesselEnds(const FlowPath& path, const BloodSettings& blood);

  // This step's lumped flows (m^3/s, mitral and aortic, forward positive) and the base's descent
  // rate w (m/s).
  void setFlows(double mitralFlow, double aorticFlow, double descentRate);
  // After the prediction: each plug is given its move along its vessel, p = x + u dt.
  void drive(pbd::Particles& particles, Index first, Real dt);
  // The plugs back at their heights along the vessels: on the solver's working positions (slot
  // k is particle ids[k]) after each density iteration, on the predictions after the contacts.
  void hold(std::vector<Vec3>& points, std::span<const Index> ids) const;
  void hold(pbd::Particles& particles) const;

  // Inside a plug (the boundary's own blood, not the vessel's lumen).
  [[nodiscard]] bool inBuffer(const Vec3& x) const;
  [[nodiscard]] Real inflowSpeed() const { return m_inflowSpeed; }    // m/s, into the heart
  [[nodiscard]] Real outflowSpeed() const { return m_outflowSpeed; }  // m/s, out of the heart
  // Volume (m^3) the lumped aortic flow has taken that the outflow's plug has not let out yet.
  [[nodiscard]] double outflowOwed() const { return m_owed; }
  // Checkpoints: the plugs' speeds and the volume owed (the plugs themselves are found anew
  // in every drive()).
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);

 private:
  [[nodiscard]] bool inInflowBuffer(const Vec3& x) const;
  [[nodiscard]] Real outflowPlugSpeed(const pbd::Particles& particles, Index first, Real dt);
  [[nodiscard]] Vec3 plugHeight(const Vec3& p, std::size_t k) const;

  FlowPath m_path;
  Orifice m_inflowEnd, m_outflowEnd;  // the vessels' far ends' discs (FlowPath::inflowEnd), found once
  Real m_depth, m_spacing;
  double m_particleVolume;
  Real m_inflowArea, m_outflowArea;
  double m_inflowStretch, m_outflowStretch;  // A_mean / A of each vessel (1 when straight)
  Real m_inflowSpeed = 0, m_outflowSpeed = 0, m_lumpedOutflowSpeed = 0;
  double m_owed = 0;
  double m_restUnderPlug = 1;  // particles under the outflow's plug at rest density
  std::vector<Index> m_plug;           // particles of either plug this step
  std::vector<Vec3> m_target;          // their predictions
  std::vector<std::uint8_t> m_inPlug;  // per particle: in a plug this step
  std::vector<Index> m_plugSlot;       // per particle: its index in m_plug
};

}  // namespace hs::cardiac
