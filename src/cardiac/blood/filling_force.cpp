#include "cardiac/blood/filling_force.h"

namespace hs::cardiac {

FillingForce::FillingForce(const FlowPath& path, const BloodSettings& blood, Real atrialPressureMmHg)
    : m_path(path),
      m_radius(blood.radius),
      m_spacing(blood.spacing),
      m_acceleration(Real(atrialPressureMmHg * kPascalPerMmHg) / (blood.restDensity * path.inflowLength)) {}

void FillingForce::apply(pbd::Particles& particles, pbd::Index first, const pbd::StepContext& context) const {
  if (m_acceleration == Real(0)) return;
  // Toward the ventricle, along the mitral disc's forward normal.
  const Vec3 dv = (m_acceleration * context.dt) * m_path.mitral.forward;
  for (std::size_t i = first; i < particles.size(); ++i) {
    if (!particles.active(i)) continue;
    if (m_path.classify(particles.position[i], m_radius, m_spacing) == FlowRegion::InflowVessel)
      particles.velocity[i] += dv;
  }
}

}  // namespace hs::cardiac
