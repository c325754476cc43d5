#include "cardiac/flow_path.h"

#include <algorithm>

namespace hs::cardiac {

FlowRegion FlowPath::classify(const Vec3& x, Real lumenSlack, Real endSlack) const {
  if (!x.allFinite()) return FlowRegion::Outside;
  // The valve planes are the regions' borders, as for the flows (flow_meter.h).
  if (x.y() >= mitral.centre.y()) {
    if (mitral.radial(x) < mitral.radius + lumenSlack && x.y() <= inflowTop + endSlack) return FlowRegion::InflowVessel;
    if (aortic.radial(x) < aortic.radius + lumenSlack && x.y() <= outflowTop + endSlack)
      return FlowRegion::OutflowVessel;
  }
  if (x.y() >= mitral.centre.y() + plateMid) return FlowRegion::Outside;
  // (x^2 + z^2) / a^2 + y^2 / c^2 <= 1 for the mid-wall spheroid, y clamped at the base plane.
  Vec3 q = x - apexAxisOrigin;
  q.y() = std::min(q.y(), Real(0));
  const Real e = (q.x() * q.x() + q.z() * q.z()) / (midWallRadius * midWallRadius) +
                 (q.y() * q.y()) / (midWallLongAxis * midWallLongAxis);
  return e <= Real(1) ? FlowRegion::Ventricle : FlowRegion::Outside;
}

}  // namespace hs::cardiac
