// The copied third-party meshes (tests/data/meshes, see its README.md for sources and licences)
// read with the counts their sources state, and the summary's volumes, loops and quality.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "io/mesh/mesh_import.h"
#include "io/mesh/mesh_summary.h"
#include "mesh_writers.h"

namespace hs::testing {
namespace {

const std::string kMeshes = std::string(HS_TEST_DATA_DIR) + "/meshes/";

TEST(MeshExamples, BivmeEndocardiumHasTwoAnnuliAndEncloses174Millilitres) {
  const io::ImportedMesh mesh = io::readMesh(kMeshes + "bivme_patient1/patient1_LV_ENDOCARDIAL_000.obj");
  // 1,572 vertices and 3,072 triangles: the data's README (the biv-me template's endocardium).
  EXPECT_EQ(mesh.vertices.size(), 1572u);
  EXPECT_EQ(mesh.triangles.size(), 3072u);
  EXPECT_TRUE(mesh.markers.empty());  // no "o" or "g" in the file
  const io::MeshSummary s = io::summarizeMesh(mesh);
  EXPECT_EQ(s.unitGuess, "mm");
  EXPECT_FALSE(s.closed);
  EXPECT_EQ(s.nonManifoldEdges, 0u);
  ASSERT_EQ(s.loops.size(), 2u);
  // The mitral annulus of 48 vertices and the aortic of 24 (the data's README); the mitral
  // the larger: a flat cap of about 9 cm^2 against 3.
  std::map<std::size_t, double> capOf;
  for (const io::BoundaryLoop& loop : s.loops) capOf[loop.vertices] = loop.capArea;
  ASSERT_EQ(capOf.count(48), 1u);
  ASSERT_EQ(capOf.count(24), 1u);
  EXPECT_GT(capOf[48], 2 * capOf[24]);
  // Issue 16: frame 0 encloses 174.5 mL when its two annuli are closed by flat caps.
  EXPECT_NEAR(s.cappedVolume * s.millilitresPerCubicUnit, 174.5, 0.1);
}

TEST(MeshExamples, ArosticaIdealizedLvHasItsTetsAndThreeMarkers) {
  const io::ImportedMesh mesh = io::readMesh(kMeshes + "arostica2025_idealized_lv/ellipsoid_0.005.ele");
  // The counts in the files' header lines and the data's README: 4,577 nodes, 17,625 tets,
  // 6,230 boundary faces marked 1 (endocardium), 2 (epicardium), 3 (base).
  EXPECT_EQ(mesh.vertices.size(), 4577u);
  EXPECT_EQ(mesh.tets.size(), 17625u);
  EXPECT_EQ(mesh.triangles.size(), 6230u);
  ASSERT_EQ(mesh.markers.size(), 3u);
  std::size_t marked = 0;
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(mesh.markers[std::size_t(i)].number, i + 1);
    marked += mesh.markers[std::size_t(i)].triangles.size();
  }
  EXPECT_EQ(marked, 6230u);
  const io::MeshSummary s = io::summarizeMesh(mesh);
  EXPECT_EQ(s.unitGuess, "m");
  // The wall of an ellipsoidal shell truncated at the base: apex at x = -0.097 (epicardium).
  EXPECT_NEAR(s.min[0], -0.097, 1e-6);
  ASSERT_TRUE(s.quality.has_value());
  EXPECT_EQ(s.quality->invertedTets, 0u);
  EXPECT_GT(s.quality->minDihedralDeg, 5.0);
  EXPECT_GT(s.tetVolume, 0.0);
  // The tets' boundary is the marked faces: as many as the .face file lists.
  EXPECT_EQ(pbd::boundaryFaces(mesh.tets).size(), 6230u);
}

TEST(MeshSummary, LoopAndCappedVolumeOfAnOpenBoxAgainstHandComputedValues) {
  // The 3 x 2 x 1 cm box without its top (marker 2): one loop of 4 vertices, perimeter
  // 2 (0.03 + 0.02) m, cap area 0.03 x 0.02 m^2; capped, the box's volume, 6 mL.
  const MarkedTetMesh box = boxMesh();
  io::ImportedMesh open;
  open.vertices = box.vertices;
  for (std::size_t t = 0; t < box.triangles.size(); ++t)
    if (box.triangleMarker[t] != 2) open.triangles.push_back(box.triangles[t]);
  const io::MeshSummary s = io::summarizeMesh(open);
  EXPECT_FALSE(s.closed);
  ASSERT_EQ(s.loops.size(), 1u);
  EXPECT_EQ(s.loops[0].vertices, 4u);
  EXPECT_NEAR(s.loops[0].perimeter, 0.1, 1e-7);
  EXPECT_NEAR(s.loops[0].capArea, 0.0006, 1e-9);
  EXPECT_NEAR(s.cappedVolume * s.millilitresPerCubicUnit, 6.0, 1e-3);
  // Closed, the enclosed volume is the sum of the tets' volumes.
  io::ImportedMesh closed = open;
  closed.triangles = box.triangles;
  const io::MeshSummary c = io::summarizeMesh(closed);
  EXPECT_TRUE(c.closed);
  EXPECT_TRUE(c.loops.empty());
  EXPECT_NEAR(c.enclosedVolume, 6e-6, 1e-11);
}

}  // namespace
}  // namespace hs::testing
