#pragma once
// The steps of buildPatientWall (cardiac/patient/patient_wall.h) that tests reach on their own.
#include "cardiac/patient/patient_wall.h"

namespace hs::cardiac::detail {

// A loop's centroid and its vector area (1/2) sum p_i x p_(i+1) (length: the flat cap's area).
struct LoopShape {
  Vec3d centroid = Vec3d::Zero();
  Vec3d vectorArea = Vec3d::Zero();
};
LoopShape loopShape(const std::vector<Vec3>& vertices, const std::vector<Index>& loop);

// The base of a truncated ventricle (one boundary loop, the rim, in the heart frame) closed
// flat with the mitral and aortic orifices cut in it.
struct OpenedBase {
  Surface surface;  // the cup's vertices first, then the plate's
  std::vector<Index> mitralRing, aorticRing;
  std::vector<bool> basePlate;  // per vertex
};
OpenedBase openFlatBase(const Surface& cup, const std::vector<Index>& rim, double spacing,
                        const std::string& file);

// Where the procedural heart puts its orifices in its base plate, as shares of the cavity's
// radius at the base (LvGeometryParams' defaults): centres on the x axis, radii.
struct OrificeLayout {
  double mitralCentreX = 0, mitralRadius = 0, aorticCentreX = 0, aorticRadius = 0;
};
OrificeLayout proceduralOrificeLayout();

// AHA segment per wall vertex, from its endocardial partner (vertex v -> v mod n) by
// ahaSegment; 0 on the base plate.
std::vector<std::uint8_t> patientAhaSegments(const PatientWall& wall);

}  // namespace hs::cardiac::detail
