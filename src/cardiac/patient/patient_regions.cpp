// Regions on a patient's ventricle (issue 16, item 3): the AHA 17 segments by the same rule as
// the procedural heart's (cardiac/anatomy/aha_segments.h), once the wall is in its frame: the long axis
// is y, the base plane y = 0, the apex at y = -cavityLength, the septum toward kSeptal (aha_segments.h).
#include "cardiac/anatomy/aha_segments.h"
#include "cardiac/patient/patient_wall_internal.h"

namespace hs::cardiac::detail {

std::vector<std::uint8_t> patientAhaSegments(const PatientWall& wall) {
  std::vector<std::uint8_t> segment(wall.mesh.vertices.size(), 0);
  for (std::size_t v = 0; v < segment.size(); ++v) {
    const std::size_t i = v % wall.endoVertices;  // the endocardial partner: layers are stacked copies
    if (!wall.basePlate[i]) segment[v] = ahaSegment(wall.mesh.vertices[i].cast<double>(), wall.cavityLength);
  }
  return segment;
}

}  // namespace hs::cardiac::detail

namespace hs::cardiac {

VentricleLandmarks landmarksInFile(const PatientWall& wall) {
  const HeartFrame& f = wall.frame;
  const auto toFile = [&](const Vec3d& heart) {
    Vec3d p = (f.rotation.transpose() * heart + f.origin) / f.metresPerUnit;
    return p;
  };
  std::size_t apex = 0;
  for (std::size_t i = 0; i < wall.endoVertices; ++i)
    if (wall.mesh.vertices[i].y() < wall.mesh.vertices[apex].y()) apex = i;
  return {toFile(wall.mesh.vertices[apex].cast<double>()), toFile(Vec3d::Zero()),
          f.rotation.row(1).transpose(), f.rotation.transpose() * kSeptal};
}

}  // namespace hs::cardiac
