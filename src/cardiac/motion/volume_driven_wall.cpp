#include "cardiac/motion/volume_driven_wall.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "cardiac/motion/base_taper.h"

namespace hs::cardiac {
namespace {

// Along a vessel the base's descent falls back to 0 at the pinned far end (the vessel is
// stretched, not moved as a whole).
Real vesselDescentShare(Real y, double plateTop, double vesselTop) {
  return Real(std::clamp(1 - (double(y) - plateTop) / std::max(vesselTop - plateTop, 1e-12), 0.0, 1.0));
}

// The wall thickness h' that keeps the wall's volume inside an epicardium of radii (A, C):
// A^2 C - (A - h)^2 (C - h) = W. The left side rises from 0 at h = 0 to A^2 C at h = min(A, C);
// bisection, as it needs no derivative and cannot leave the bracket. Returns min(A, C) when
// even a solid spheroid holds less than the wall (no cavity left).
double thicknessKeepingVolume(double A, double C, double W) {
  double low = 0, high = std::min(A, C);
  if (A * A * C <= W) return high;
  for (int i = 0; i < 60; ++i) {
    const double h = 0.5 * (low + high);
    (A * A * C - (A - h) * (A - h) * (C - h) < W ? low : high) = h;
  }
  return 0.5 * (low + high);
}

// An akinetic segment does not contract, but its border zone, tethered to the beating wall, moves
// in with it (hypokinesis fading over 1-2 cm; Lima et al. 1985, Circulation 71): a vertex that
// does not beat takes the beating wall's radial motion scaled by w = 1 - s^2 (3 - 2 s),
// s = d / (kBorderZone L), d its distance at rest from the nearest beating vertex, L the long
// axis (15 mm on `normal`). Left to the constraints instead, the seam between a driven and a
// carried wall folded (anterior-infarct, 79 degrees at one hinge).
constexpr double kBorderZone = 0.25;

// Per vertex of the myocardium that does not beat: w above; 1 where it beats.
std::vector<Real> borderZoneWeights(const LvModel& model, const std::vector<std::uint8_t>& beats) {
  const auto& x = model.mesh.vertices;
  std::vector<Index> beating;
  for (std::size_t v = 0; v < x.size(); ++v)
    if (beats[v] && model.region[v] == Region::Myocardium) beating.push_back(Index(v));
  const double zone = kBorderZone * double(model.longAxisLength);
  std::vector<Real> weight(x.size(), Real(1));
  for (std::size_t v = 0; v < x.size(); ++v) {
    if (beats[v] || model.region[v] != Region::Myocardium) continue;
    double nearest = HUGE_VAL;
    for (Index b : beating) nearest = std::min(nearest, double((x[v] - x[b]).norm()));
    const double s = std::clamp(nearest / zone, 0.0, 1.0);
    weight[v] = Real(1 - s * s * (3 - 2 * s));
  }
  return weight;
}

// The endocardium may shrink to this share of its rest radii; the tetrahedra at the apex
// invert a little beyond it.
constexpr double kSmallestEndocardium = 0.45;

}  // namespace

VolumeDrivenWall::VolumeDrivenWall(const LvModel& model, const std::vector<Index>& beating, Index firstParticle,
                                   const WallMotionSettings& settings)
    : m_model(&model), m_firstParticle(firstParticle), m_settings(settings) {
  const auto& x = model.mesh.vertices;
  const std::size_t n = x.size();
  const LvGeometryParams& g = model.params;
  m_rest = {0, double(g.endoRadius), double(g.endoLongAxis), double(g.endoRadius + g.wallThickness),
            double(model.longAxisLength)};
  m_wallVolume = m_rest.epiRadius * m_rest.epiRadius * m_rest.epiLong - m_rest.endoRadius * m_rest.endoRadius * m_rest.endoLong;
  std::vector<std::uint8_t> beats(n, 0), pinned(n, 0);
  for (Index v : beating) beats[v] = 1;
  for (Index v : model.pinned) pinned[v] = 1;
  // Each vessel is stretched between the plate's top and its own far end (the two may differ in
  // length).
  double plateTop = 0, inflowTop = 0, outflowTop = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (model.region[v] == Region::BasePlate) plateTop = std::max(plateTop, double(x[v].y()));
    if (model.region[v] == Region::InflowVessel) inflowTop = std::max(inflowTop, double(x[v].y()));
    if (model.region[v] == Region::OutflowVessel) outflowTop = std::max(outflowTop, double(x[v].y()));
  }
  m_beatingShare = myocardiumShare(model, beating);
  const std::vector<Real> border = borderZoneWeights(model, beats);
  m_longitudinalTravel = double(settings.longitudinal) * double(model.longAxisLength) * m_beatingShare;
  for (std::size_t v = 0; v < n; ++v) {
    if (pinned[v]) continue;
    Driven d{Index(v), Kind::Base, 1};
    switch (model.region[v]) {
      case Region::Myocardium:
        // An akinetic segment descends with the base; its radial motion is its border zone's.
        d.kind = v % 2 == 0 ? Kind::Endocardium : Kind::Epicardium;
        // The radial motion fades to none at the base plane (base_taper.h).
        d.share = baseTaper(x[v].y(), m_rest.endoLong) * border[v];
        break;
      case Region::BasePlate: break;
      case Region::InflowVessel:
      case Region::OutflowVessel:
        d = {Index(v), Kind::Vessel,
             vesselDescentShare(x[v].y(), plateTop, model.region[v] == Region::InflowVessel ? inflowTop : outflowTop)};
        if (d.share == 0) continue;
        break;
    }
    m_driven.push_back(Index(v));
    m_motion.push_back(d);
  }
  // The largest contraction: the endocardium no smaller than kSmallestEndocardium of rest.
  for (m_maxContraction = 0; m_maxContraction < 3; m_maxContraction += 0.01) {
    const Spheroids w = wallAt(m_maxContraction + 0.01);
    if (w.endoRadius < kSmallestEndocardium * m_rest.endoRadius || w.endoLong < kSmallestEndocardium * m_rest.endoLong) break;
  }
  m_scratch = x;
}

VolumeDrivenWall::Spheroids VolumeDrivenWall::wallAt(double a) const {
  Spheroids w;
  w.descent = a * m_longitudinalTravel;
  w.epiRadius = m_rest.epiRadius * (1 - a * double(m_settings.radial) * m_beatingShare);
  w.epiLong = m_rest.epiLong - w.descent;
  const double h = thicknessKeepingVolume(w.epiRadius, w.epiLong, m_wallVolume);
  w.endoRadius = w.epiRadius - h;
  w.endoLong = w.epiLong - h;
  return w;
}

// A beating vertex keeps its place on its spheroid: x and z scale with the radius (less toward
// the base), y with the long axis below the descended base plane.
Vec3 VolumeDrivenWall::place(const Driven& d, const Spheroids& wall) const {
  const Vec3& x = m_model->mesh.vertices[d.vertex];
  const Real descent = Real(wall.descent);
  switch (d.kind) {
    case Kind::Base: return {x.x(), x.y() - descent, x.z()};
    case Kind::Vessel: return {x.x(), x.y() - d.share * descent, x.z()};
    case Kind::Endocardium:
    case Kind::Epicardium: {
      const bool endo = d.kind == Kind::Endocardium;
      const double radius = endo ? wall.endoRadius / m_rest.endoRadius : wall.epiRadius / m_rest.epiRadius;
      const double length = endo ? wall.endoLong / m_rest.endoLong : wall.epiLong / m_rest.epiLong;
      const Real across = Real(1 - double(d.share) * (1 - radius));
      return {x.x() * across, Real(-wall.descent + double(x.y()) * length), x.z() * across};
    }
  }
  return x;
}

void VolumeDrivenWall::placeAll(double a, std::vector<Vec3>& out, Index offset) const {
  const Spheroids wall = wallAt(a);
  for (const Driven& d : m_motion) out[offset + d.vertex] = place(d, wall);
}

double VolumeDrivenWall::predictedVolume(double a) const {
  placeAll(a, m_scratch, 0);
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
  for (int iteration = 0; iteration < 6; ++iteration) {
    const double h = 1e-4;
    const double v = predictedVolume(a);
    const double slope = (predictedVolume(a + h) - v) / h;
    if (!(slope < 0)) break;
    const double next = std::clamp(a - (v - wanted) / slope, -m_maxContraction, m_maxContraction);
    const bool converged = std::abs(next - a) < 1e-7;
    a = next;
    if (converged) break;
  }
  m_contraction = a;
  m_lastPredicted = predictedVolume(a);
  m_started = true;
  placeAll(a, predicted, m_firstParticle);
}

void VolumeDrivenWall::save(pbd::StateWriter& w) const {
  w.section("driven wall");
  w.fields(m_contraction, m_lastPredicted, m_started);
}

void VolumeDrivenWall::load(pbd::StateReader& r) {
  r.section("driven wall");
  r.fields(m_contraction, m_lastPredicted, m_started);
}

}  // namespace hs::cardiac
