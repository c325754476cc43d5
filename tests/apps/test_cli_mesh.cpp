// `heartsim mesh FILE [--json]`: exit 0 with the summary of a good mesh, exit 2 with one line on
// stderr (and nothing on stdout) for a bad one.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_runner.h"

namespace hs::testing {
namespace {

const std::string kEndocardium = std::string(HS_TEST_DATA_DIR) + "/meshes/bivme_patient1/patient1_LV_ENDOCARDIAL_000.obj";
const std::string kIdealizedLv = std::string(HS_TEST_DATA_DIR) + "/meshes/arostica2025_idealized_lv/ellipsoid_0.005.node";

void expectBadMesh(const CliResult& r, const std::string& mention) {
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(mention), std::string::npos) << r.err;
}

TEST(CliMesh, SurfaceJsonHasCountsLoopsAndCappedVolume) {
  const CliResult r = runHeartsim("mesh '" + kEndocardium + "' --json", scratchDir("mesh_surface"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["vertices"], 1572);
  EXPECT_EQ(j["triangles"], 3072);
  EXPECT_EQ(j["unit_guess"], "mm");
  EXPECT_FALSE(j["closed"].get<bool>());
  ASSERT_EQ(j["boundary_loops"].size(), 2u);
  EXPECT_NEAR(j["capped_volume_ml"].get<double>(), 174.5, 0.1);
}

TEST(CliMesh, VolumeMeshTextNamesMarkersAndQuality) {
  const CliResult r = runHeartsim("mesh '" + kIdealizedLv + "'", scratchDir("mesh_volume"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* line : {"vertices 4577, triangles 6230, tetrahedra 17625", "marker 1: 2500 triangles",
                           "marker 3: 256 triangles", "smallest dihedral angle", "units: m"})
    EXPECT_NE(r.out.find(line), std::string::npos) << "no '" << line << "' in:\n" << r.out;
}

TEST(CliMesh, BadInputExitsTwoWithOneLine) {
  const auto dir = scratchDir("mesh_bad");
  expectBadMesh(runHeartsim("mesh missing.vtu", dir), "missing.vtu: no such mesh file");
  std::ofstream(dir / "shape.dae") << "<COLLADA/>";
  expectBadMesh(runHeartsim("mesh shape.dae", dir), "unknown mesh extension");
  std::ofstream(dir / "bad.msh") << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 zero 0\n$EndNodes\n";
  expectBadMesh(runHeartsim("mesh bad.msh --json", dir), "bad.msh:6:");
  const CliResult noFile = runHeartsim("mesh", dir);
  EXPECT_EQ(noFile.exitCode, 2);
}

}  // namespace
}  // namespace hs::testing
