#pragma once
// The filling pressure. The atrium is not modelled; its pressure P_a drives the inflow vessel:
// blood in it feels a body force along the vessel, rho0 a L = P_a over the vessel's length L,
// the same pressure difference an atrium at P_a would apply at the vessel's far end. An
// external force: applied with gravity, before the prediction.
#include "cardiac/anatomy/flow_path.h"
#include "cardiac/circulation/clinical_units.h"
#include "cardiac/blood/blood_settings.h"
#include "pbd/core/particles.h"
#include "pbd/core/step_context.h"

namespace hs::cardiac {

class FillingForce {
 public:
  FillingForce(const FlowPath& path, const BloodSettings& blood, Real atrialPressureMmHg);

  // v += a dt for the active blood [first, end) in the inflow vessel.
  void apply(pbd::Particles& particles, pbd::Index first, const pbd::StepContext& context) const;
  [[nodiscard]] Real acceleration() const { return m_acceleration; }  // m/s^2

 private:
  FlowPath m_path;
  Real m_radius, m_spacing;
  Real m_acceleration;  // a = P_a / (rho0 L)
};

}  // namespace hs::cardiac
