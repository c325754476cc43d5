// The shipped patient meshes made into walls (io/mesh/patient_surfaces.h, cardiac/patient/patient_wall.h):
// biv-me's patient 1 at frame 0 (an endocardium open at two annuli, mm) and the idealized LV of
// Arostica et al. 2025 (a truncated ventricle with endo- and epicardium markers, m).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>

#include "cardiac/patient/patient_wall.h"
#include "io/mesh/mesh_import.h"
#include "io/mesh/patient_surfaces.h"
#include "thrown_message.h"

namespace hs::io {
namespace {

using cardiac::LengthUnit;
using cardiac::PatientWall;
using cardiac::PatientWallSettings;
using Vec3d = Eigen::Vector3d;

const std::string kBivme = std::string(HS_TEST_DATA_DIR) + "/meshes/bivme_patient1/";
const std::string kIdealized =
    std::string(HS_TEST_DATA_DIR) + "/meshes/arostica2025_idealized_lv/ellipsoid_0.005.node";

PatientSurfaces surfacesOf(const std::string& file) { return patientSurfaces(readMesh(file), file); }

PatientWall bivmeWall(const cardiac::Surface* epicardium = nullptr) {
  const PatientSurfaces s = surfacesOf(kBivme + "patient1_LV_ENDOCARDIAL_000.obj");
  PatientWallSettings settings;
  settings.file = "patient1_LV_ENDOCARDIAL_000.obj";
  return cardiac::buildPatientWall(s.endocardium, epicardium, settings);
}

PatientWall idealizedWall() {
  const PatientSurfaces s = surfacesOf(kIdealized);
  PatientWallSettings settings;
  settings.file = "ellipsoid_0.005.node";
  settings.units = LengthUnit::Metre;
  return cardiac::buildPatientWall(s.endocardium, s.epicardium ? &*s.epicardium : nullptr, settings);
}

// The unit direction across the long axis, in the file's frame, of a segment's endocardial
// vertices' centroid.
Vec3d segmentDirection(const PatientWall& w, int segment) {
  Vec3d sum = Vec3d::Zero();
  for (std::size_t i = 0; i < w.endoVertices; ++i)
    if (w.segment[i] == segment) sum += w.mesh.vertices[i].cast<double>();
  const Vec3d heart(sum.x(), 0, sum.z());
  return w.frame.rotation.transpose() * heart.normalized();
}

void expectAhaSegmentsOn(const PatientWall& w, const Vec3d& septumInFile) {
  std::array<int, 18> count{};
  for (std::uint8_t s : w.segment) ++count[s];
  for (int s = 1; s <= 17; ++s) EXPECT_GT(count[s], 0) << "segment " << s;
  std::size_t apex = 0;
  for (std::size_t i = 0; i < w.endoVertices; ++i)
    if (w.mesh.vertices[i].y() < w.mesh.vertices[apex].y()) apex = i;
  EXPECT_EQ(w.segment[apex], 17);
  for (int s : {2, 3, 8, 9}) EXPECT_GT(segmentDirection(w, s).dot(septumInFile), 0.5) << "segment " << s;
  for (int s : {5, 6, 11, 12}) EXPECT_LT(segmentDirection(w, s).dot(septumInFile), -0.5) << "segment " << s;
}

TEST(PatientMeshes, BivmeFrame0MakesAGoodWallAroundItsOwnCavity) {
  const PatientWall w = bivmeWall();
  EXPECT_FALSE(w.baseOpened);
  EXPECT_EQ(w.quality.invertedTets, 0u);
  EXPECT_GT(w.quality.minDihedralDeg, 8);
  EXPECT_LT(w.quality.maxAspectRatio, 6);
  EXPECT_GT(w.mesh.tets.size(), 5000u);
  EXPECT_LT(w.mesh.tets.size(), 12000u);
  // Frame 0 encloses 174.49 mL with its annuli closed flat (heartsim mesh); remeshed at 5 mm.
  EXPECT_NEAR(w.cavityVolume * 1e6, 174.49, 0.02 * 174.49);
  EXPECT_NEAR(w.cavityLength, 0.095, 0.003);
  // The mitral annulus is the larger loop: loop 1, 48 vertices, 107.5 mm around. Its remeshed
  // ring keeps the perimeter.
  double perimeter = 0;
  for (std::size_t k = 0; k < w.mitralRing.size(); ++k)
    perimeter +=
        (w.mesh.vertices[w.mitralRing[k]] - w.mesh.vertices[w.mitralRing[(k + 1) % w.mitralRing.size()]])
            .norm();
  EXPECT_NEAR(perimeter, 0.1075, 0.003);
  EXPECT_GT(w.mitralRing.size(), w.aorticRing.size());
}

TEST(PatientMeshes, BivmeSeptumFromTheAnnuliAgreesWithItsRightVentricle) {
  const std::string epiFile = kBivme + "patient1_EPICARDIAL_000.obj";
  const ImportedMesh epiMesh = readMesh(epiFile);
  const cardiac::Surface epi{epiMesh.vertices, epiMesh.triangles};
  const PatientWall fromAnnuli = bivmeWall();
  const PatientWall fromRv = bivmeWall(&epi);
  EXPECT_EQ(fromAnnuli.septumFrom, "aortic annulus");
  EXPECT_EQ(fromRv.septumFrom, "right ventricle");
  EXPECT_FALSE(fromRv.thicknessFromEpicardium);  // a biventricular epicardium: rays would cross the RV
  const Vec3d a = cardiac::landmarksInFile(fromAnnuli).septum, b = cardiac::landmarksInFile(fromRv).septum;
  EXPECT_GT(a.dot(b), std::cos(15.0 * 3.14159265358979 / 180.0));
  // The AHA segments, classified with the annuli's septum, put 2-3 and 8-9 on the right
  // ventricle's side.
  expectAhaSegmentsOn(fromAnnuli, b);
}

TEST(PatientMeshes, BivmeIsPlacedTheSameWhateverTheScannerFrame) {
  PatientSurfaces s = surfacesOf(kBivme + "patient1_LV_ENDOCARDIAL_000.obj");
  PatientWallSettings settings;
  settings.file = "turned.obj";
  const PatientWall w = bivmeWall();
  const Eigen::Matrix3d q = Eigen::AngleAxisd(2.1, Vec3d(0.3, -1, 0.4).normalized()).toRotationMatrix();
  for (pbd::Vec3& p : s.endocardium.vertices)
    p = (q * p.cast<double>() + Vec3d(500, -20, 7)).cast<pbd::Real>();
  const PatientWall turned = cardiac::buildPatientWall(s.endocardium, nullptr, settings);
  EXPECT_NEAR(turned.cavityLength, w.cavityLength, 1e-4);
  EXPECT_NEAR(turned.cavityVolume, w.cavityVolume, 0.005 * w.cavityVolume);
  // The same frame: the turned file's axes are q times the original's.
  for (int r = 0; r < 3; ++r)
    EXPECT_NEAR(turned.frame.rotation.row(r).dot(q * w.frame.rotation.row(r).transpose()), 1.0, 1e-4);
}

TEST(PatientMeshes, BivmeInTheWrongUnitsIsRefused) {
  const PatientSurfaces s = surfacesOf(kBivme + "patient1_LV_ENDOCARDIAL_000.obj");
  PatientWallSettings settings;
  settings.file = "patient1_LV_ENDOCARDIAL_000.obj";
  settings.units = LengthUnit::Metre;
  EXPECT_EQ(testing::thrownMessage<std::invalid_argument>(
                [&] { cardiac::buildPatientWall(s.endocardium, nullptr, settings); }),
            "patient1_LV_ENDOCARDIAL_000.obj: a heart 91.6 m across (9.16e+03 cm) is implausible; expected "
            "3-30 cm; is the "
            "file in mm? (units = \"mm\" makes it 9.16 cm)");
}

TEST(PatientMeshes, IdealizedLvGetsItsBaseOpenedAndItsWallFromTheEpicardium) {
  const PatientWall w = idealizedWall();
  EXPECT_TRUE(w.baseOpened);
  EXPECT_TRUE(w.thicknessFromEpicardium);
  EXPECT_EQ(w.quality.invertedTets, 0u);
  EXPECT_GT(w.quality.minDihedralDeg, 12);
  EXPECT_LT(w.quality.maxAspectRatio, 4);
  // Issue 16: the idealized LV's cavity is 167.5 mL at rest.
  EXPECT_NEAR(w.cavityVolume * 1e6, 167.5, 0.01 * 167.5);
  // Endocardial apex x = -0.090, epicardial x = -0.097 (the .face file's header): 7 mm thick.
  const std::size_t n = w.endoVertices;
  std::size_t apex = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (w.mesh.vertices[i].y() < w.mesh.vertices[apex].y()) apex = i;
  EXPECT_NEAR((w.mesh.vertices[2 * n + apex] - w.mesh.vertices[apex]).norm(), 0.007, 0.0005);
  EXPECT_NEAR(w.cavityLength, 0.09 + 0.02647, 0.001);
  // Long axis: the file's +x (base at x = 0.026).
  EXPECT_NEAR(cardiac::landmarksInFile(w).longAxis.x(), 1.0, 1e-6);
  EXPECT_GT(w.mitralRing.size(), w.aorticRing.size());
  expectAhaSegmentsOn(w, cardiac::landmarksInFile(w).septum);
}

TEST(PatientMeshes, IdealizedLvTakesItsSeptumFromTheSetting) {
  const PatientSurfaces s = surfacesOf(kIdealized);
  PatientWallSettings settings;
  settings.file = "ellipsoid_0.005.node";
  settings.units = LengthUnit::Metre;
  settings.septum = Vec3d(0, 0, 1);
  const PatientWall w = cardiac::buildPatientWall(s.endocardium, &*s.epicardium, settings);
  EXPECT_EQ(w.septumFrom, "setting");
  expectAhaSegmentsOn(w, Vec3d(0, 0, 1));
}

}  // namespace
}  // namespace hs::io
