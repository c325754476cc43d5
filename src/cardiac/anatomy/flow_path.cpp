#include "cardiac/anatomy/flow_path.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesh/surface_inside.h"

namespace hs::cardiac {

FlowRegion FlowPath::classify(const Vec3& x, Real lumenSlack, Real endSlack) const {
  if (!x.allFinite()) return FlowRegion::Outside;
  // Within a vessel's lumen (and a slack of its wall) and below its far end (and a slack).
  auto inLumen = [&](const Orifice& section, Real top) {
    return section.radial(x) < section.radius + lumenSlack && x.y() <= top + endSlack;
  };
  if (cavity) {
    if (x.y() >= mitral.centre.y() && inLumen(inflowSection(x.y()), inflowTop)) return FlowRegion::InflowVessel;
    if (x.y() >= aortic.centre.y() && inLumen(outflowSection(x.y()), outflowTop)) return FlowRegion::OutflowVessel;
    return cavity->contains(x) ? FlowRegion::Ventricle : FlowRegion::Outside;
  }
  // The valve planes are the regions' borders, as for the flows (flow_meter.h).
  if (x.y() >= mitral.centre.y()) {
    if (inLumen(inflowSection(x.y()), inflowTop)) return FlowRegion::InflowVessel;
    if (inLumen(outflowSection(x.y()), outflowTop)) return FlowRegion::OutflowVessel;
  }
  if (x.y() >= mitral.centre.y() + plateMid) return FlowRegion::Outside;
  // (x^2 + z^2) / a^2 + y^2 / c^2 <= 1 for the mid-wall spheroid, y clamped at the base plane.
  Vec3 q = x - apexAxisOrigin;
  q.y() = std::min(q.y(), Real(0));
  const Real e = (q.x() * q.x() + q.z() * q.z()) / (midWallRadius * midWallRadius) +
                 (q.y() * q.y()) / (midWallLongAxis * midWallLongAxis);
  return e <= Real(1) ? FlowRegion::Ventricle : FlowRegion::Outside;
}

std::vector<Vec3> lumenDiscSites(const Orifice& lumen, Real y, Real reach, Real spacing, bool turned) {
  const Vec3 centre(lumen.centre.x(), y, lumen.centre.z());
  std::vector<Vec3> sites{centre};
  // Rings evenly out to `reach`, as many as fit about a spacing apart.
  const int rings = reach > 0 ? std::max(1, int(std::lround(reach / spacing))) : 0;
  for (int k = 1; k <= rings; ++k) {
    const Real radius = reach * Real(k) / Real(rings);
    const int count = std::max(1, int(std::lround(2 * std::numbers::pi_v<Real> * radius / spacing)));
    for (int j = 0; j < count; ++j) {
      const Real angle = 2 * std::numbers::pi_v<Real> * (Real(j) + (turned ? Real(0.5) : Real(0))) / Real(count);
      sites.push_back(centre + radius * Vec3(std::cos(angle), 0, std::sin(angle)));
    }
  }
  return sites;
}

}  // namespace hs::cardiac
