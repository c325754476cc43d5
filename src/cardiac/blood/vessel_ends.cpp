#include "cardiac/blood/vessel_ends.h"

#include <algorithm>
#include <numbers>

namespace hs::cardiac {
namespace {

// The outflow's plug (outflowPlugSpeed): the time over which it lets out blood it owes the aorta
// (s), the loosening of the blood under it at which it stops (a share of rest density), and how
// fast it follows a column that sinks away from it (spacings per step per unit of loosening).
constexpr double kRepayTime = 0.02;
constexpr double kLooseStop = 0.1;
constexpr double kFollow = 0.2;

}  // namespace

VesselEnds::VesselEnds(const FlowPath& path, const BloodSettings& blood)
    : m_path(path),
      m_inflowEnd(path.inflowEnd()),
      m_outflowEnd(path.outflowEnd()),
      m_depth(blood.supportRadius),
      m_spacing(blood.spacing),
      m_particleVolume(double(blood.spacing) * double(blood.spacing) * double(blood.spacing)),
      m_inflowArea(std::numbers::pi_v<Real> * path.mitral.radius * path.mitral.radius),
      m_outflowArea(std::numbers::pi_v<Real> * path.aortic.radius * path.aortic.radius),
      m_inflowStretch(path.inflowShape.meanAreaShare(double(path.mitral.radius))),
      m_outflowStretch(path.outflowShape.meanAreaShare(double(path.aortic.radius))) {
  // The layer under the outflow's plug at rest density: lumenDiscSites layers a spacing apart.
  const std::size_t perLayer = lumenDiscSites(path.aortic, 0, path.aortic.radius - blood.radius, blood.spacing, false).size();
  m_restUnderPlug = double(perLayer) * double(m_depth / m_spacing);
}

void VesselEnds::setFlows(double mitralFlow, double aorticFlow, double descentRate) {
  m_inflowSpeed = Real(mitralFlow / double(m_inflowArea) + descentRate * m_inflowStretch);
  m_lumpedOutflowSpeed = Real(aorticFlow / double(m_outflowArea) - descentRate * m_outflowStretch);
}

bool VesselEnds::inInflowBuffer(const Vec3& x) const {
  return x.y() > m_path.inflowTop - m_depth && m_inflowEnd.radial(x) < m_inflowEnd.radius + m_spacing;
}

bool VesselEnds::inBuffer(const Vec3& x) const {
  return inInflowBuffer(x) ||
         (x.y() > m_path.outflowTop - m_depth && m_outflowEnd.radial(x) < m_outflowEnd.radius + m_spacing);
}

// The outflow's plug moves at the lumped speed u_a = Q_aortic / A - w, plus what it owes the
// aorta (summed u_a - u over the steps, as a volume V) over kRepayTime. It must not run ahead of
// the column under it: as ejection starts the blood in the cavity gives a little before the
// column moves, and a plug that left it behind would leave the vessel's end empty. So it slows
// to a stop as the layer under it (a kernel support deep, n particles against the n0 it holds at
// rest density, its lumenDiscSites layers) loosens by kLooseStop, and follows a column that sinks away from it (gravity,
// with a shut valve below) down at kFollow (n/n0 - 1) d / dt:
//   u = max(0, u_a + V / (A tau)) clamp(1 - (1 - n/n0) / kLooseStop, 0, 1) + kFollow min(n/n0 - 1, 0) d / dt.
Real VesselEnds::outflowPlugSpeed(const pbd::Particles& particles, Index first, Real dt) {
  const Orifice& aortic = m_outflowEnd;
  std::size_t count = 0;
  for (std::size_t i = first; i < particles.size(); ++i) {
    const Vec3& x = particles.position[i];
    count += particles.active(i) && aortic.radial(x) < aortic.radius && x.y() > m_path.outflowTop - 2 * m_depth &&
             x.y() <= m_path.outflowTop - m_depth;
  }
  const double area = double(m_outflowArea);
  const double packing = double(count) / m_restUnderPlug;
  const double wanted = std::max(0.0, double(m_lumpedOutflowSpeed) + m_owed / (area * kRepayTime));
  const double brake = std::clamp(1 - (1 - packing) / kLooseStop, 0.0, 1.0);
  const double speed = wanted * brake + kFollow * std::min(packing - 1, 0.0) * double(m_spacing) / double(dt);
  m_owed += (double(m_lumpedOutflowSpeed) - speed) * area * double(dt);
  return Real(speed);
}

void VesselEnds::drive(pbd::Particles& particles, Index first, Real dt) {
  m_plug.clear();
  m_target.clear();
  m_inPlug.assign(particles.size(), 0);
  m_plugSlot.resize(particles.size());
  m_outflowSpeed = outflowPlugSpeed(particles, first, dt);
  // Downstream, each orifice's forward direction: into the heart, out of it.
  const Vec3 inflowMove = m_inflowSpeed * dt * m_path.mitral.forward;
  const Vec3 outflowMove = m_outflowSpeed * dt * m_path.aortic.forward;
  for (std::size_t i = first; i < particles.size(); ++i) {
    const Vec3& x = particles.position[i];
    if (!particles.active(i) || !inBuffer(x)) continue;
    const Vec3 target = x + (inInflowBuffer(x) ? inflowMove : outflowMove);
    particles.predicted[i] = target;
    m_inPlug[i] = 1;
    m_plugSlot[i] = Index(m_plug.size());
    m_plug.push_back(Index(i));
    m_target.push_back(target);
  }
}

// The plug's k-th particle at p, moved along its vessel (both are vertical) to its target's height.
Vec3 VesselEnds::plugHeight(const Vec3& p, std::size_t k) const {
  return Vec3(p.x(), m_target[k].y(), p.z());
}

void VesselEnds::hold(std::vector<Vec3>& points, std::span<const Index> ids) const {
  for (std::size_t k = 0; k < ids.size(); ++k)
    if (m_inPlug[ids[k]]) points[k] = plugHeight(points[k], m_plugSlot[ids[k]]);
}

void VesselEnds::hold(pbd::Particles& particles) const {
  for (std::size_t k = 0; k < m_plug.size(); ++k)
    particles.predicted[m_plug[k]] = plugHeight(particles.predicted[m_plug[k]], k);
}

void VesselEnds::save(pbd::StateWriter& w) const {
  w.section("vessel ends");
  w.fields(m_inflowSpeed, m_outflowSpeed, m_lumpedOutflowSpeed, m_owed);
}

void VesselEnds::load(pbd::StateReader& r) {
  r.section("vessel ends");
  r.fields(m_inflowSpeed, m_outflowSpeed, m_lumpedOutflowSpeed, m_owed);
}

}  // namespace hs::cardiac
