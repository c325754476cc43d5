// Regions on a patient's ventricle: the AHA segments (cardiac/anatomy/aha_segments.h's rule, reused)
// and the landmarks, on a synthetic ventricle in a scanner frame whose septum is given.
#include <gtest/gtest.h>

#include <array>

#include "cardiac/anatomy/aha_segments.h"
#include "patient_test_hearts.h"

namespace hs::cardiac {
namespace {

using namespace testing;

struct Placed {
  PatientWall wall;
  Vec3d septumInFile;
};

Placed placedCup() {
  PatientWallSettings settings;
  settings.file = "cup.obj";
  const Vec3d septum = scannerRotation() * Vec3d(1, 0, 1).normalized();  // in the cup's frame: +x +z
  settings.septum = septum;
  return {buildPatientWall(inScannerFrame(spheroidCup()), nullptr, settings), septum};
}

TEST(PatientRegions, EverySegmentHoldsVerticesAndTheApexCapIsAtTheApex) {
  const Placed p = placedCup();
  std::array<int, 18> count{};
  for (std::uint8_t s : p.wall.segment) ++count[s];
  for (int s = 1; s <= 17; ++s) EXPECT_GT(count[s], 0) << "segment " << s;
  EXPECT_GT(count[0], 0);  // the base plate made over the truncated base
  std::size_t apex = 0;
  for (std::size_t i = 0; i < p.wall.endoVertices; ++i)
    if (p.wall.mesh.vertices[i].y() < p.wall.mesh.vertices[apex].y()) apex = i;
  EXPECT_EQ(p.wall.segment[apex], 17);
  // Every layer of a vertex carries its endocardial partner's segment.
  for (std::size_t v = 0; v < p.wall.mesh.vertices.size(); ++v)
    EXPECT_EQ(p.wall.segment[v], p.wall.segment[v % p.wall.endoVertices]);
}

TEST(PatientRegions, SeptalSegmentsLieTowardTheGivenSeptumInTheFile) {
  const Placed p = placedCup();
  const VentricleLandmarks l = landmarksInFile(p.wall);
  // Back in the scanner frame: the apex c = 50 mm below the base centre along the cup's axis.
  const Vec3d axis = scannerRotation() * Vec3d::UnitY();
  EXPECT_NEAR(l.longAxis.dot(axis), 1.0, 1e-6);
  EXPECT_NEAR((l.baseCentre - scannerOffset()).norm(), 0.0, 0.5);
  EXPECT_NEAR((l.apex - (scannerOffset() - kLengthMm * axis)).norm(), 0.0, 1.0);
  EXPECT_NEAR(l.septum.dot(p.septumInFile), 1.0, 1e-6);
  // Each segment's endocardial centroid, across the axis, in the file frame.
  std::array<Vec3d, 18> sum;
  sum.fill(Vec3d::Zero());
  std::array<int, 18> count{};
  for (std::size_t i = 0; i < p.wall.endoVertices; ++i) {
    const Vec3d heart = p.wall.mesh.vertices[i].cast<double>();
    sum[p.wall.segment[i]] += p.wall.frame.rotation.transpose() * heart / p.wall.frame.metresPerUnit;
    ++count[p.wall.segment[i]];
  }
  const auto direction = [&](int s) {
    const Vec3d c = sum[s] / count[s];
    return Vec3d((c - axis * axis.dot(c)).normalized());
  };
  // Anteroseptal and inferoseptal (2, 3, 8, 9) sit 30 degrees either side of the septum;
  // the lateral ones (5, 6, 11, 12) opposite; the apical septal (14) on it.
  for (int s : {2, 3, 8, 9}) EXPECT_GT(direction(s).dot(p.septumInFile), 0.8) << "segment " << s;
  for (int s : {5, 6, 11, 12}) EXPECT_LT(direction(s).dot(p.septumInFile), -0.8) << "segment " << s;
  EXPECT_GT(direction(14).dot(p.septumInFile), 0.9);
  // Anterior (1) and inferior (4) are 90 degrees off, on opposite sides.
  EXPECT_NEAR(direction(1).dot(p.septumInFile), 0.0, 0.2);
  EXPECT_LT(direction(1).dot(direction(4)), -0.9);
}

}  // namespace
}  // namespace hs::cardiac
