// A patient's wall from a surface (cardiac/patient/patient_wall.h), on synthetic ventricles placed in a
// scanner frame: the frame found again, the annuli, the flat base opened, quality, volume.
#include <gtest/gtest.h>

#include "cardiac/anatomy/aha_segments.h"

#include "patient_test_hearts.h"
#include "thrown_message.h"

namespace hs::cardiac {
namespace {

using namespace testing;

PatientWallSettings mmSettings() {
  PatientWallSettings s;
  s.file = "lv.obj";
  s.units = LengthUnit::Millimetre;
  return s;
}

Vec3d ringCentre(const PatientWall& w, const std::vector<Index>& ring) {
  Vec3d c = Vec3d::Zero();
  for (Index i : ring) c += w.mesh.vertices[i].cast<double>() / double(ring.size());
  return c;
}

TEST(PatientWall, TruncatedCupInAScannerFrameIsPlacedBaseUpWithItsOrificesOpened) {
  PatientWallSettings settings = mmSettings();
  settings.septum = scannerRotation() * Vec3d::UnitZ();  // the cup's +z side is the septum
  const PatientWall w = buildPatientWall(inScannerFrame(spheroidCup()), nullptr, settings);
  EXPECT_TRUE(w.baseOpened);
  // The frame: the long axis is the cup's y (base-ward), the septum the frame's kSeptal.
  EXPECT_NEAR(w.frame.rotation.row(1).dot(scannerRotation() * Vec3d::UnitY()), 1.0, 1e-3);
  EXPECT_NEAR((w.frame.rotation.transpose() * kSeptal).dot(scannerRotation() * Vec3d::UnitZ()), 1.0, 1e-3);
  EXPECT_NEAR(w.frame.rotation.determinant(), 1.0, 1e-9);
  EXPECT_NEAR(w.cavityLength, kLengthMm * 1e-3, 0.5e-3);
  // Base up, apex down: the rim at y = 0, every endocardial point below the plate.
  for (std::size_t i = 0; i < w.endoVertices; ++i) EXPECT_LT(w.mesh.vertices[i].y(), 1e-4);
  // The orifices as in the procedural heart: mitral larger, toward -x; aortic toward +x.
  EXPECT_GT(w.mitralRing.size(), w.aorticRing.size());
  EXPECT_NEAR(ringCentre(w, w.mitralRing).x(),
              detail::proceduralOrificeLayout().mitralCentreX * kRadiusMm * 1e-3, 1e-3);
  EXPECT_NEAR(ringCentre(w, w.aorticRing).x(),
              detail::proceduralOrificeLayout().aorticCentreX * kRadiusMm * 1e-3, 1e-3);
  EXPECT_NEAR(ringCentre(w, w.mitralRing).y(), 0.0, 1e-6);
  // The cavity (the orifices closed flat) is the half spheroid's, remeshed at 5 mm.
  EXPECT_NEAR(w.cavityVolume * 1e6, halfSpheroidMl(), 0.02 * halfSpheroidMl());
  EXPECT_EQ(w.quality.invertedTets, 0u);
  EXPECT_GT(w.quality.minDihedralDeg, 10);
  EXPECT_LT(w.quality.maxAspectRatio, 5);
  EXPECT_EQ(w.mesh.tets.size(), 3 * 2 * w.endocardium.size());
}

TEST(PatientWall, TwoAnnuliAreFoundBySizeAndTheSeptumIsOnTheAorticSide) {
  const PatientWall w = buildPatientWall(inScannerFrame(twoAnnuliVentricle()), nullptr, mmSettings());
  EXPECT_FALSE(w.baseOpened);
  EXPECT_GT(w.mitralRing.size(), w.aorticRing.size());
  // The aortic orifice was at the cup's +x: the septum lies 45 degrees on from it, turning
  // about the long axis (the cup's +y) the way that takes anterior to septal (about -y).
  const Vec3d septum =
      scannerRotation() * (Eigen::AngleAxisd(-std::numbers::pi / 4, Vec3d::UnitY()) * Vec3d::UnitX());
  EXPECT_NEAR((w.frame.rotation.transpose() * kSeptal).dot(septum), 1.0, 1e-3);
  EXPECT_EQ(w.septumFrom, "aortic annulus");
  // As in the procedural heart: the aortic annulus toward +x (the outflow on the septal side),
  // the mitral toward -x (blood enters on the front view's left).
  EXPECT_GT(ringCentre(w, w.aorticRing).x(), 0);
  EXPECT_LT(ringCentre(w, w.mitralRing).x(), 0);
  EXPECT_NEAR(w.frame.rotation.row(1).dot(scannerRotation() * Vec3d::UnitY()), 1.0, 1e-2);
  // Remeshing rounds the right-angled crease between the cup and the plate (no feature edges
  // are kept): 2.3% of this small (6.5 cm) ventricle's volume at 5 mm.
  EXPECT_NEAR(w.cavityVolume * 1e6, halfSpheroidMl(), 0.03 * halfSpheroidMl());
  EXPECT_EQ(w.quality.invertedTets, 0u);
}

TEST(PatientWall, AnnulusOverrideSwapsTheValves) {
  const Surface heart = inScannerFrame(twoAnnuliVentricle());
  const auto loops = pbd::boundaryLoopVertices(heart.triangles);
  ASSERT_EQ(loops.size(), 2u);
  PatientWallSettings settings = mmSettings();
  settings.mitralLoop = loops[0].size() < loops[1].size() ? 1 : 2;  // the smaller one
  const PatientWall w = buildPatientWall(heart, nullptr, settings);
  EXPECT_LT(w.mitralRing.size(), w.aorticRing.size());
  settings.mitralLoop = 3;
  EXPECT_EQ(
      hs::testing::thrownMessage<std::invalid_argument>([&] { buildPatientWall(heart, nullptr, settings); }),
      "lv.obj: mitral loop 3: expected a loop number in [1, 2]");
}

TEST(PatientWall, ClosedVentricleWithAFlatBaseHasItsBaseCutAndOpened) {
  Surface cup = spheroidCup();
  const auto loop = pbd::boundaryLoopVertices(cup.triangles).at(0);
  cup.vertices.emplace_back(0, 0, 0);
  const auto centre = static_cast<Index>(cup.vertices.size() - 1);
  for (std::size_t k = 0; k < loop.size(); ++k)
    cup.triangles.push_back({centre, loop[(k + 1) % loop.size()], loop[k]});
  ASSERT_TRUE(pbd::checkSurface(cup.triangles).closed);
  const PatientWall w = buildPatientWall(inScannerFrame(cup), nullptr, mmSettings());
  EXPECT_TRUE(w.baseOpened);
  EXPECT_NEAR(w.cavityVolume * 1e6, halfSpheroidMl(), 0.02 * halfSpheroidMl());
}

TEST(PatientWall, EpicardiumSetsTheThickness) {
  // An epicardium 8 mm outside the cup: a spheroid of radii a + 8, c + 8, cut higher.
  const auto sphere = pbd::testing::makeSphere(5, 1.0);
  Surface epi;
  for (const Vec3& p : sphere.vertices)
    epi.vertices.emplace_back(pbd::Real((kRadiusMm + 8) * p.x()), pbd::Real((kLengthMm + 8) * p.z()),
                              pbd::Real((kRadiusMm + 8) * p.y()));
  epi.triangles = sphere.triangles;
  const PatientWall w = buildPatientWall(inScannerFrame(spheroidCup()), nullptr, mmSettings());
  PatientWallSettings settings = mmSettings();
  Surface epiScanner = inScannerFrame(epi);
  const PatientWall thick = buildPatientWall(inScannerFrame(spheroidCup()), &epiScanner, settings);
  EXPECT_EQ(thick.quality.invertedTets, 0u);
  // The apex: 8 mm thick (the outermost layer starts at 2 n).
  const std::size_t n = thick.endoVertices;
  std::size_t apex = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (thick.mesh.vertices[i].y() < thick.mesh.vertices[apex].y()) apex = i;
  EXPECT_NEAR((thick.mesh.vertices[2 * n + apex] - thick.mesh.vertices[apex]).norm(), 0.008, 0.001);
  EXPECT_NEAR((w.mesh.vertices[2 * w.endoVertices] - w.mesh.vertices[0]).norm(), 0.010, 1e-4);
}

TEST(PatientWall, UnitsThatMakeNoHeartAreRefusedSuggestingTheOtherUnit) {
  const Surface mm = inScannerFrame(spheroidCup());
  PatientWallSettings settings = mmSettings();
  settings.units = LengthUnit::Metre;
  EXPECT_EQ(
      hs::testing::thrownMessage<std::invalid_argument>([&] { buildPatientWall(mm, nullptr, settings); }),
      "lv.obj: a heart 56.1 m across (5.61e+03 cm) is implausible; expected 3-30 cm; is the file in mm? "
      "(units = \"mm\" makes it 5.61 cm)");
  Surface metres = mm;
  for (Vec3& p : metres.vertices) p *= pbd::Real(1e-3);
  EXPECT_EQ(
      hs::testing::thrownMessage<std::invalid_argument>(
          [&] { buildPatientWall(metres, nullptr, mmSettings()); }),
      "lv.obj: a heart 0.0561 mm across (0.00561 cm) is implausible; expected 3-30 cm; is the file in m? "
      "(units = \"m\" makes it 5.61 cm)");
  EXPECT_NO_THROW(buildPatientWall(metres, nullptr, settings));
  EXPECT_NE(hs::testing::thrownMessage<std::invalid_argument>(
                [] { checkHeartSize(5000, LengthUnit::Millimetre, "x.stl"); })
                .find("x.stl: a heart 5e+03 mm across (500 cm) is implausible; expected 3-30 cm; check the "
                      "file's units"),
            std::string::npos);
}

TEST(PatientWall, SurfacesThatMakeNoVentricleAreRefused) {
  const auto sphere = pbd::testing::makeSphere(3, 40.0);
  EXPECT_EQ(hs::testing::thrownMessage<std::invalid_argument>([&] {
              buildPatientWall({sphere.vertices, sphere.triangles}, nullptr, mmSettings());
            }),
            "lv.obj: a closed surface without a flat base; expected boundary loops at the mitral and aortic "
            "annuli or a "
            "flat truncated base");
  Surface holed = twoAnnuliVentricle();
  holed.triangles.erase(holed.triangles.begin());  // a third loop near the apex
  EXPECT_EQ(
      hs::testing::thrownMessage<std::invalid_argument>(
          [&] { buildPatientWall(holed, nullptr, mmSettings()); }),
      "lv.obj: 3 boundary loops; expected 2 (the mitral and aortic annuli) or 1 (a flat truncated base)");
  EXPECT_THROW(wallResolution("medium"), std::invalid_argument);
  // A cup with a hole at its apex: two loops, but not two annuli.
  const Surface cup = spheroidCup();
  std::vector<Index> kept;
  for (Index f = 0; f < cup.triangles.size(); ++f) {
    double y = 0;
    for (Index v : cup.triangles[f]) y += cup.vertices[v].y() / 3.0;
    if (y > -0.97 * kLengthMm) kept.push_back(f);
  }
  const pbd::SubSurface apexHole = pbd::extractSubSurface(cup.vertices, cup.triangles, kept);
  ASSERT_EQ(pbd::boundaryLoopVertices(apexHole.triangles).size(), 2u);
  EXPECT_EQ(hs::testing::thrownMessage<std::invalid_argument>([&] {
              buildPatientWall({apexHole.vertices, apexHole.triangles}, nullptr, mmSettings());
            }),
            "lv.obj: the 2 boundary loops lie 99.4% of the ventricle's length apart; expected both annuli at "
            "the base "
            "(within 30%)");
  const auto message = [](const Surface& surface) {
    return hs::testing::thrownMessage<std::invalid_argument>(
        [&] { buildPatientWall(surface, nullptr, mmSettings()); });
  };
  // A flat sheet 6 cm across: one flat loop, but no cavity.
  Surface sheet;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) sheet.vertices.emplace_back(pbd::Real(20 * i), pbd::Real(20 * j), 0);
  for (Index j = 0; j < 3; ++j)
    for (Index i = 0; i < 3; ++i) {
      const Index a = 4 * j + i;
      sheet.triangles.push_back({a, a + 1, a + 5});
      sheet.triangles.push_back({a, a + 5, a + 4});
    }
  EXPECT_EQ(message(sheet),
            "lv.obj: the surface holds 0 mL with its loops closed flat, too little for a heart 6 cm across; "
            "expected a "
            "cup-shaped endocardium");
  // A fin on the sheet: an edge of three triangles.
  Surface fin = sheet;
  fin.vertices.emplace_back(20, 20, 30);
  fin.triangles.push_back({5, 6, static_cast<Index>(fin.vertices.size() - 1)});
  EXPECT_EQ(message(fin),
            "lv.obj: 1 edges are shared by more than two triangles; expected a manifold surface");
  Surface flipped = twoAnnuliVentricle();
  std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
  EXPECT_EQ(message(flipped),
            "lv.obj: neighbouring triangles are wound in opposite directions; expected a consistently "
            "oriented surface");
  Surface twice = twoAnnuliVentricle();
  const Surface copy = twoAnnuliVentricle();
  const auto offset = static_cast<Index>(twice.vertices.size());
  for (const Vec3& p : copy.vertices) twice.vertices.push_back(p + Vec3(0, 0, 1));
  for (const pbd::Triangle& t : copy.triangles)
    twice.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  EXPECT_EQ(message(twice), "lv.obj: 2 separate pieces; expected one connected endocardium");
}

}  // namespace
}  // namespace hs::cardiac
