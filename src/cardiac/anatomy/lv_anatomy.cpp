#include "cardiac/anatomy/lv_anatomy.h"

#include <algorithm>

namespace hs::cardiac {
namespace {

using Vec3d = Eigen::Vector3d;

// A closed ring's centroid and area vector 1/2 sum (p_k - c) x (p_k+1 - c): its norm is the
// area of the fan that closes the ring, its direction the fan's normal.
struct RingShape {
  Vec3d centroid = Vec3d::Zero();
  Vec3d area = Vec3d::Zero();
};

RingShape ringShape(const LvModel& model, const std::vector<Index>& ring) {
  RingShape s;
  if (ring.empty()) return s;
  for (Index v : ring) s.centroid += model.mesh.vertices[v].cast<double>();
  s.centroid /= double(ring.size());
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Vec3d a = model.mesh.vertices[ring[k]].cast<double>() - s.centroid;
    const Vec3d b = model.mesh.vertices[ring[(k + 1) % ring.size()]].cast<double>() - s.centroid;
    s.area += 0.5 * a.cross(b);
  }
  return s;
}

}  // namespace

AnatomyFigures measureAnatomy(const LvModel& model) {
  AnatomyFigures f;
  const RingShape mitral = ringShape(model, model.mitralRing);
  const RingShape aortic = ringShape(model, model.aorticRing);
  f.mitralArea = mitral.area.norm();
  f.aorticArea = aortic.area.norm();

  // The root: the outflow vessel's lumen side (even ids, lv_model.h) about the vessel's axis,
  // which rises along the flow path's aortic direction from the ring's centroid (a patient's
  // ring may be tilted against it, patient_vessels.h), shifted sideways where an anatomical root
  // leans (vessel_shape.h): the lumen is measured across, not along its lean.
  const FlowPath& path = model.flowPath;
  const Vec3d axis = path.aortic.forward.cast<double>().normalized();
  const VesselShape& shape = path.outflowShape;
  double rootRadius = -1;
  for (std::size_t v = 0; v < model.mesh.vertices.size(); v += 2) {
    if (model.region[v] != Region::OutflowVessel) continue;
    const Vec3& x = model.mesh.vertices[v];
    const double lean = shape.shift(FlowPath::heightShare(path.aortic, path.outflowTop, x.y()));
    const Vec3d d = x.cast<double>() - aortic.centroid - lean * Vec3d(shape.awayX, 0, shape.awayZ);
    rootRadius = std::max(rootRadius, (d - axis.dot(d) * axis).norm());
  }
  if (rootRadius >= 0) f.aorticRootDiameter = 2 * rootRadius;

  // The long axis: the cavity's extent below the mitral annulus's plane.
  const Vec3d down = mitral.area.norm() > 0 ? Vec3d(-mitral.area.normalized()) : -Vec3d::UnitY();
  for (const pbd::Triangle& t : model.cavitySurface)
    for (Index v : t) f.longAxis = std::max(f.longAxis, down.dot(model.mesh.vertices[v].cast<double>() - mitral.centroid));
  return f;
}

}  // namespace hs::cardiac
