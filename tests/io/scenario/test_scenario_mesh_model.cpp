// [model] kind = "mesh" (issue 16, items 6-7): the keys checked as the scenario is read, the
// paths found from the scenario file, and the two built-in patient hearts built and beating.
#include <gtest/gtest.h>

#include "thrown_message.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "cardiac/heart_simulation.h"
#include "io/scenario/scenario_file.h"

namespace hs::io {
namespace {

using cardiac::ModelKind;
using cardiac::Scenario;

const std::string kData = HS_TEST_DATA_DIR;
const std::string kBivmeEndo = kData + "/meshes/bivme_patient1/patient1_LV_ENDOCARDIAL_000.obj";

// The ScenarioError message of f(), or fails the test.
std::string errorOf(const std::function<void()>& f) { return hs::testing::thrownMessage<ScenarioError>(f); }

// parseScenario(text) fails with one line holding every piece.
void expectError(const std::string& text, const std::vector<std::string>& pieces) {
  const std::string msg = errorOf([&] { parseScenario(text, "lesson.toml"); });
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  for (const std::string& p : pieces) EXPECT_NE(msg.find(p), std::string::npos) << "missing '" << p << "' in: " << msg;
}

std::string meshModel(const std::string& extra) {
  return "[model]\nkind = \"mesh\"\nendocardium = \"" + kBivmeEndo + "\"\n" + extra;
}

TEST(ScenarioMeshModel, ProceduralIsTheDefaultAndReadsNoFile) {
  const Scenario s = parseScenario("[model]\nendocardium = \"no/such.obj\"\n", "lesson.toml");
  EXPECT_EQ(s.patient.kind, ModelKind::Procedural);
  EXPECT_TRUE(s.patient.endocardiumSurface.vertices.empty());
  EXPECT_EQ(s.patient.endocardium, "no/such.obj");
}

TEST(ScenarioMeshModel, BadValuesNameTheFileLineKeyAndWhatWasExpected) {
  expectError("[model]\nkind = \"patient\"\n", {"lesson.toml:2", "model.kind", "\"procedural\", \"mesh\""});
  expectError(meshModel("units = \"cm\"\n"), {"lesson.toml:4", "model.units", "\"mm\", \"m\""});
  expectError(meshModel("mesh_resolution = 3\n"), {"lesson.toml:4", "model.mesh_resolution", "\"coarse\""});
  expectError(meshModel("mitral_loop = -1\n"), {"lesson.toml:4", "model.mitral_loop", ">= 0"});
  expectError(meshModel("[model.markers]\nendocardium = 1.5\n"),
              {"lesson.toml:5", "model.markers.endocardium", "name (a string) or number"});
  expectError(meshModel("septum = [1, 0]\n"), {"lesson.toml:4", "model.septum", "3 finite numbers"});
}

TEST(ScenarioMeshModel, AMeshHeartNeedsExactlyOneMeshThatReads) {
  expectError("[model]\nkind = \"mesh\"\n", {"lesson.toml:2", "model.endocardium", "exactly one", "neither"});
  expectError(meshModel("volume_mesh = \"lv.msh\"\n"), {"model.endocardium", "exactly one", "both"});
  expectError("[model]\nkind = \"mesh\"\nendocardium = \"missing.obj\"\n",
              {"lesson.toml:3", "model.endocardium", "missing.obj: no such mesh file"});
  expectError("[model]\nkind = \"mesh\"\nvolume_mesh = \"lv.xyz\"\n",
              {"lesson.toml:3", "model.volume_mesh", "lv.xyz", "expected .obj"});
  expectError(meshModel("wall_thickness = 0.5\n"), {"lesson.toml:4", "model.wall_thickness", "[0.002, 0.03]"});
  // Blood starts in a patient's cavity and vessels (tests/io/scenario/test_patient_blood.cpp), nowhere else.
  expectError(meshModel("[blood]\nenabled = true\nstart = \"vessel\"\n"),
              {"lesson.toml:6", "blood.start", "expected \"heart\"", "got \"vessel\""});
  const std::string node = kData + "/meshes/arostica2025_idealized_lv/ellipsoid_0.005.node";
  expectError("[model]\nkind = \"mesh\"\nvolume_mesh = \"" + node + "\"\n[model.markers]\nendocardium = 9\n",
              {"model.volume_mesh", "no surface group '9' for the endocardium; expected one of 1, 2, 3"});
}

TEST(ScenarioMeshModel, PathsStartAtTheScenarioFilesFolderAndTheWallIsACentimetre) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / "heartsim_mesh_model";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "lesson" / "hearts");
  std::filesystem::copy_file(kBivmeEndo, dir / "lesson" / "hearts" / "endo.obj");
  std::ofstream(dir / "lesson" / "patient.toml") << "[model]\nkind = \"mesh\"\nendocardium = \"hearts/endo.obj\"\n";
  const Scenario s = loadScenario((dir / "lesson" / "patient.toml").string());
  EXPECT_EQ(s.patient.endocardium, (dir / "lesson" / "hearts" / "endo.obj").lexically_normal().string());
  EXPECT_EQ(s.patient.endocardiumSurface.vertices.size(), 1572u);
  EXPECT_FALSE(s.patient.epicardiumSurface.has_value());
  EXPECT_EQ(s.geometry.wallThickness, pbd::Real(0.010));  // unset: a real heart's, not the thesis's 0.5 m
  // Written out and read back (checkpoints do): the absolute path finds the same file.
  const Scenario back = parseScenario(scenarioToToml(s), "elsewhere/dump.toml");
  EXPECT_EQ(back.patient.endocardium, s.patient.endocardium);
  EXPECT_EQ(back.patient.endocardiumSurface.vertices.size(), 1572u);
}

TEST(ScenarioMeshModel, InlineMarkersChooseTheVolumeMeshsSurfaces) {
  const std::string node = kData + "/meshes/arostica2025_idealized_lv/ellipsoid_0.005.node";
  const Scenario s = parseScenario("[model]\nkind = \"mesh\"\nunits = \"m\"\nvolume_mesh = \"" + node +
                                       "\"\nmarkers = { endocardium = 2, epicardium = \"1\" }\n",
                                   "lesson.toml");
  EXPECT_EQ(s.patient.markerEndocardium, "2");
  // Swapped on purpose: the endocardium is now the benchmark's epicardium (3474 triangles).
  EXPECT_EQ(s.patient.endocardiumSurface.triangles.size(), 3474u);
  ASSERT_TRUE(s.patient.epicardiumSurface.has_value());
  EXPECT_EQ(s.patient.epicardiumSurface->triangles.size(), 2500u);
}

// The built-in heart at rest and after a short beat: the cavity volume, the wall's pairs
// (endocardial 2i, epicardial 2i + 1), no tet inverted.
struct Beat {
  double restMl = 0, minMl = 0;
  std::size_t inverted = 0;
};

Beat beatOf(const std::string& name, double seconds) {
  cardiac::HeartSimulation sim(loadScenario(name), 1);
  const cardiac::LvModel& m = sim.model();
  EXPECT_EQ(m.mesh.vertices.size() % 2, 0u);
  for (const pbd::Triangle& t : m.cavitySurface) EXPECT_TRUE(t[0] % 2 == 0 && t[1] % 2 == 0 && t[2] % 2 == 0);
  EXPECT_GE(m.mitralRing.size(), 8u);
  EXPECT_GE(m.aorticRing.size(), 6u);
  EXPECT_GT(m.flowPath.mitral.radius, m.flowPath.aortic.radius);
  Beat b;
  b.restMl = double(sim.cavityVolume()) * 1e6;
  b.minMl = b.restMl;
  const auto steps = std::int64_t(seconds / double(sim.scenario().simulation.dt));
  for (std::int64_t k = 0; k < steps; ++k) {
    sim.step();
    b.minMl = std::min(b.minMl, double(sim.cavityVolume()) * 1e6);
  }
  b.inverted = sim.tissueStats().invertedTets;
  return b;
}

TEST(ScenarioMeshModel, IdealizedLvHoldsTheBenchmarksVolumeAndBeats) {
  const Beat b = beatOf("idealized-lv", 0.3);
  EXPECT_NEAR(b.restMl, 167.5, 0.01 * 167.5);
  EXPECT_LT(b.minMl, 0.85 * b.restMl);  // mid-systole: the cavity has emptied
  EXPECT_EQ(b.inverted, 0u);
}

TEST(ScenarioMeshModel, PatientBivmeHoldsFrameZerosVolumeAndBeats) {
  const Beat b = beatOf("patient-biv-me", 0.3);
  EXPECT_NEAR(b.restMl, 174.5, 0.02 * 174.5);
  EXPECT_LT(b.minMl, 0.85 * b.restMl);
  EXPECT_EQ(b.inverted, 0u);
}

}  // namespace
}  // namespace hs::io
