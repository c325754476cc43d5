#include "cardiac/volume_driven_wall.h"

#include <algorithm>
#include <cmath>

namespace hs::cardiac {
namespace {

// Share of the base's descent a vertex takes: from 0 at the epicardial apex to 1 at the base
// plane (y = 0) along the myocardium; the base plate takes all of it; along a vessel it falls
// back to 0 at the pinned far end (the vessel is stretched, not moved as a whole).
double descentShare(const LvModel& model, Index v, double apexY, double plateTop, double vesselTop) {
  const double y = model.mesh.vertices[v].y();
  switch (model.region[v]) {
    case Region::Myocardium: return std::clamp((y - apexY) / (0 - apexY), 0.0, 1.0);
    case Region::BasePlate: return 1;
    case Region::InflowVessel:
    case Region::OutflowVessel:
      return std::clamp(1 - (y - plateTop) / std::max(vesselTop - plateTop, 1e-12), 0.0, 1.0);
  }
  return 0;
}

// Toward the long axis (x = z = 0). A cavity-side vertex (even id) travels `radial` of its
// distance r_i from the axis; its outer partner (id + 1) travels r_i / r_o as far, which keeps
// the wall's cross-section r_o^2 - r_i^2 to first order: the wall thickens as it contracts.
Vec3 radialDisplacement(const std::vector<Vec3>& x, Index v, Real radial) {
  const Vec3 own(x[v].x(), 0, x[v].z());
  if (v % 2 == 0) return -radial * own;
  const Real inner = Vec3(x[v - 1].x(), 0, x[v - 1].z()).norm();
  const Real outer = own.norm();
  if (!(outer > Real(0))) return Vec3::Zero();
  return Vec3(-radial * (inner * inner / (outer * outer)) * own);
}

// The base ring is held by the fibrous base plate, which does not shorten: the radial motion
// fades from the mid-ventricle (a third of the long axis below the base) to none at the base
// plane, smoothly (s^2 (3 - 2 s)), so the plate's rim is not crushed.
double radialTaper(double y, double endoLongAxis) {
  const double s = std::clamp(-y / (endoLongAxis / 3), 0.0, 1.0);
  return s * s * (3 - 2 * s);
}

// The shell is one tetrahedron thick: beyond this contraction (about half its radius inward at
// 0.4 radial shortening) its tetrahedra invert. The cavity then stops short of the lumped
// volume, which the run reports (cavity_volume_error_max), rather than breaking the wall.
constexpr double kMaxContraction = 1.2;

}  // namespace

VolumeDrivenWall::VolumeDrivenWall(const LvModel& model, const std::vector<Index>& beating, Index firstParticle,
                                   const WallMotionSettings& settings)
    : m_model(&model), m_firstParticle(firstParticle) {
  const auto& x = model.mesh.vertices;
  const std::size_t n = x.size();
  std::vector<std::uint8_t> beats(n, 0);
  for (Index v : beating) beats[v] = 1;
  double apexY = 0, plateTop = 0, vesselTop = 0;
  for (std::size_t v = 0; v < n; ++v) {
    apexY = std::min(apexY, double(x[v].y()));
    vesselTop = std::max(vesselTop, double(x[v].y()));
    if (model.region[v] == Region::BasePlate) plateTop = std::max(plateTop, double(x[v].y()));
  }
  m_beatingShare = myocardiumShare(model, beating);
  m_longitudinalTravel = double(settings.longitudinal) * double(model.longAxisLength) * m_beatingShare;
  std::vector<std::uint8_t> pinned(n, 0);
  for (Index v : model.pinned) pinned[v] = 1;
  for (std::size_t v = 0; v < n; ++v) {
    if (pinned[v]) continue;
    const bool myocardium = model.region[v] == Region::Myocardium;
    if (myocardium && !beats[v]) continue;  // an akinetic segment is carried, not driven
    Vec3 d(0, Real(-m_longitudinalTravel * descentShare(model, Index(v), apexY, plateTop, vesselTop)), 0);
    if (myocardium) d += Real(radialTaper(x[v].y(), double(model.params.endoLongAxis))) * radialDisplacement(x, Index(v), settings.radial);
    if (d.squaredNorm() == 0) continue;
    m_driven.push_back(Index(v));
    m_displacement.push_back(d);
  }
  m_scratch = x;
}

double VolumeDrivenWall::predictedVolume(double a) const {
  const auto& rest = m_model->mesh.vertices;
  for (std::size_t k = 0; k < m_driven.size(); ++k) m_scratch[m_driven[k]] = rest[m_driven[k]] + Real(a) * m_displacement[k];
  return double(cavityVolume(*m_model, m_scratch));
}

double VolumeDrivenWall::baseDescent(double a) const { return a * m_longitudinalTravel; }

void VolumeDrivenWall::drive(const std::vector<Vec3>& positions, std::vector<Vec3>& predicted, double targetVolume) {
  // What the constraints (and the vertices not driven) added to the last step's volume.
  const double measured = double(cavityVolume(*m_model, positions));
  const double correction = m_started ? measured - m_lastPredicted : measured - predictedVolume(0);
  const double wanted = targetVolume - correction;
  // Newton on V_p(a) = wanted from the last contraction; V_p is smooth and falls with a.
  double a = m_contraction;
  for (int iteration = 0; iteration < 4; ++iteration) {
    const double h = 1e-4;
    const double v = predictedVolume(a);
    const double slope = (predictedVolume(a + h) - v) / h;
    if (!(slope < 0)) break;
    const double next = std::clamp(a - (v - wanted) / slope, -kMaxContraction, kMaxContraction);
    const bool converged = std::abs(next - a) < 1e-7;
    a = next;
    if (converged) break;
  }
  m_contraction = a;
  m_lastPredicted = predictedVolume(a);
  m_started = true;
  const auto& rest = m_model->mesh.vertices;
  for (std::size_t k = 0; k < m_driven.size(); ++k)
    predicted[m_firstParticle + m_driven[k]] = rest[m_driven[k]] + Real(a) * m_displacement[k];
}

}  // namespace hs::cardiac
