#pragma once
// The blood's path through the LV model, as geometry: inflow vessel -> mitral orifice ->
// ventricle -> aortic orifice -> outflow vessel. Part of the LV model (LvModel::flowPath),
// found once on its rest shape; the one place that says which region a point is in.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "cardiac/anatomy/vessel_shape.h"
#include "pbd/core/types.h"

namespace hs::pbd {
class SurfaceInside;
}

namespace hs::cardiac {

using pbd::Real;
using pbd::Vec3;

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

struct FlowPath {
  // The lumen discs where the vessels meet the cavity (the base plate's cavity side, y = 0 in
  // model coordinates). Mitral: forward is down (-y), into the cavity; aortic: up, out of it.
  Orifice mitral, aortic;
  Real inflowTop = 0, outflowTop = 0;  // y of the vessels' far ends
  Real inflowLength = 0;               // from the mitral disc to the inflow vessel's far end
  Vec3 apexAxisOrigin = Vec3::Zero();  // the endocardial spheroid's centre on the base plane
  Real midWallRadius = 0, midWallLongAxis = 0;
  Real plateMid = 0;                   // half the base plate's thickness
  // A patient's ventricle (patient_vessels.h): inside its mid-wall surface closed over the
  // annuli, instead of the spheroid; each vessel begins at its own orifice's plane. Null for the
  // procedural heart.
  std::shared_ptr<const pbd::SurfaceInside> cavity;
  // The valves' discs where they differ from the orifices: a patient's ring is tilted against
  // the vertical vessel above it, and its valve lies in the ring's own plane, reaching its
  // farthest vertex (patient_vessels.h). The valves close these discs and the flow meter counts
  // through them.
  std::optional<Orifice> mitralValveDisc, aorticValveDisc;
  // The open mitral valve's leaflets hang this far (m) into the cavity below its disc, as a tube
  // of the disc's radius (valves.h); 0: none.
  Real mitralLeafletLength = 0;
  // The vessels' shapes above their orifices (vessel_shape.h): straight but for an anatomical
  // procedural heart's atrium, sinuses and lean.
  VesselShape inflowShape, outflowShape;
  [[nodiscard]] const Orifice& mitralValve() const { return mitralValveDisc ? *mitralValveDisc : mitral; }
  [[nodiscard]] const Orifice& aorticValve() const { return aorticValveDisc ? *aorticValveDisc : aortic; }

  // Which part of the path x is in, however the wall has moved. A vessel: past its valve's
  // plane inside its lumen, within `lumenSlack` of the lumen wall and `endSlack` beyond its far
  // end (the blood's radius and spacing: particles touching the wall count as inside). The
  // ventricle: inside the mid-wall spheroid, continued as a cylinder up to the base plate's
  // middle (or inside a patient's `cavity`). Anything else (a particle that went through the
  // wall) is Outside; never Parked.
  [[nodiscard]] FlowRegion classify(const Vec3& x, Real lumenSlack, Real endSlack) const;
  // The path with the base plate (and both orifices in it) moved `descent` toward the apex,
  // as the lumped circulation's wall moves it (volume_driven_wall.h); the vessels' far ends
  // are pinned and stay.
  [[nodiscard]] FlowPath descended(Real descent) const {
    FlowPath moved = *this;
    moved.mitral.centre.y() -= descent;
    moved.aortic.centre.y() -= descent;
    for (std::optional<Orifice>* disc : {&moved.mitralValveDisc, &moved.aorticValveDisc})
      if (*disc) (*disc)->centre.y() -= descent;
    return moved;
  }
  // The inflow (or outflow) vessel's lumen at height y (clamped to the vessel): the disc whose
  // vertical axis is the lumen's there and whose radius is the lumen's largest there. The
  // orifice itself for a straight vessel.
  [[nodiscard]] Orifice inflowSection(Real y) const { return section(mitral, inflowTop, inflowShape, y); }
  [[nodiscard]] Orifice outflowSection(Real y) const { return section(aortic, outflowTop, outflowShape, y); }
  // The share u of a vessel's height at y, from its orifice `o` (0) to its far end `top` (1),
  // clamped: where its shape is read (vessel_shape.h).
  [[nodiscard]] static double heightShare(const Orifice& o, Real top, Real y) {
    return std::clamp(double(y - o.centre.y()) / double(top - o.centre.y()), 0.0, 1.0);
  }
  // The vessels' far ends: where blood leaves and the closed loop puts it back.
  [[nodiscard]] Orifice inflowEnd() const { return inflowSection(inflowTop); }
  [[nodiscard]] Orifice outflowEnd() const { return outflowSection(outflowTop); }
  // Past the far end of the inflow (or outflow) vessel, within `slack` of its lumen's axis
  // cylinder: blood that has left the model there.
  [[nodiscard]] bool pastInflowEnd(const Vec3& x, Real slack) const {
    const Orifice end = inflowEnd();
    return x.y() > inflowTop && end.radial(x) < end.radius + slack;
  }
  [[nodiscard]] bool pastOutflowEnd(const Vec3& x, Real slack) const {
    const Orifice end = outflowEnd();
    return x.y() > outflowTop && end.radial(x) < end.radius + slack;
  }

 private:
  // The lumen's section at height y of a vessel rising from orifice `o` to `top` (u = the share
  // of its height, which a descended base keeps: vessel_shape.h).
  static Orifice section(const Orifice& o, Real top, const VesselShape& shape, Real y) {
    if (shape.straight()) return o;
    const double u = heightShare(o, top, y);
    const double shift = shape.shift(u);
    Orifice s = o;
    s.centre.x() += Real(shift * shape.awayX);
    s.centre.z() += Real(shift * shape.awayZ);
    s.radius = Real(shape.maxRadius(u, double(o.radius)));
    return s;
  }
};

// Sites across a vertical vessel's lumen at height y, about a spacing d apart: the axis, then
// rings evenly out to `reach` (the lumen radius less a particle radius), as many as fit about a
// spacing apart, each with sites a spacing apart; `turned` turns every ring by half a site (alternate layers). One site
// per d^2 of the lumen: the blood's rest density, which a square lattice inside the wall
// reaches only to about 55%.
std::vector<Vec3> lumenDiscSites(const Orifice& lumen, Real y, Real reach, Real spacing, bool turned);

}  // namespace hs::cardiac
