// `heartsim mesh FILE --wall`: the wall the file would make, its quality, annuli and frame, in
// text and JSON; bad options or a surface that makes no wall exit 2 with one line naming the
// file and what was expected.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_runner.h"

namespace hs::testing {
namespace {

const std::string kBivme =
    std::string(HS_TEST_DATA_DIR) + "/meshes/bivme_patient1/patient1_LV_ENDOCARDIAL_000.obj";
const std::string kBivmeEpi =
    std::string(HS_TEST_DATA_DIR) + "/meshes/bivme_patient1/patient1_EPICARDIAL_000.obj";
const std::string kIdealizedLv =
    std::string(HS_TEST_DATA_DIR) + "/meshes/arostica2025_idealized_lv/ellipsoid_0.005.node";

void expectBadWall(const CliResult& r, const std::string& line) {
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(r.err, "heartsim: error: " + line + "\n");
}

TEST(CliMeshWall, BivmeJsonReportsTheWallItsQualityAndAnnuli) {
  const CliResult r = runHeartsim("mesh '" + kBivme + "' --wall --json", scratchDir("mesh_wall_json"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json w = nlohmann::json::parse(r.out)["wall"];
  EXPECT_EQ(w["layers"], 2);
  EXPECT_DOUBLE_EQ(w["edge_length"].get<double>(), 0.005);
  EXPECT_DOUBLE_EQ(w["thickness"].get<double>(), 0.010);
  EXPECT_EQ(w["vertices"].get<std::size_t>(), 3 * w["endocardial_vertices"].get<std::size_t>());
  EXPECT_EQ(w["inverted_tets"], 0);
  EXPECT_GT(w["min_dihedral_deg"].get<double>(), 8);
  EXPECT_LT(w["max_aspect_ratio"].get<double>(), 6);
  EXPECT_FALSE(w["base_opened"].get<bool>());
  EXPECT_GT(w["mitral_ring_vertices"].get<int>(), w["aortic_ring_vertices"].get<int>());
  EXPECT_NEAR(w["cavity_volume_ml"].get<double>(), 174.49, 3.5);
  EXPECT_EQ(w["septum_from"], "aortic annulus");
  EXPECT_NEAR(w["long_axis"][0].get<double>() * w["long_axis"][0].get<double>() +
                  w["long_axis"][1].get<double>() * w["long_axis"][1].get<double>() +
                  w["long_axis"][2].get<double>() * w["long_axis"][2].get<double>(),
              1.0, 1e-9);
}

TEST(CliMeshWall, ResolutionAndEpicardiumOptionsChangeTheWall) {
  const auto dir = scratchDir("mesh_wall_options");
  const auto wallOf = [&](const std::string& args) {
    const CliResult r = runHeartsim("mesh '" + kBivme + "' --wall --json " + args, dir);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return nlohmann::json::parse(r.out)["wall"];
  };
  const auto coarse = wallOf("--resolution coarse"), fine = wallOf("--resolution fine");
  EXPECT_EQ(coarse["layers"], 1);
  EXPECT_EQ(fine["layers"], 3);
  EXPECT_LT(4 * coarse["tets"].get<int>(), fine["tets"].get<int>());
  EXPECT_DOUBLE_EQ(wallOf("--thickness 0.012")["thickness"].get<double>(), 0.012);
  EXPECT_EQ(wallOf("--epicardium '" + kBivmeEpi + "'")["septum_from"], "right ventricle");
  EXPECT_EQ(wallOf("--septum 1,0,0")["septum_from"], "setting");
  // Loop 2 (24 vertices) as the mitral annulus: the rings swap.
  const auto swapped = wallOf("--mitral-loop 2");
  EXPECT_LT(swapped["mitral_ring_vertices"].get<int>(), swapped["aortic_ring_vertices"].get<int>());
}

TEST(CliMeshWall, TextNamesTheWallAndTheOpenedBase) {
  const CliResult r = runHeartsim("mesh '" + kIdealizedLv + "' --wall", scratchDir("mesh_wall_text"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* line :
       {"wall: 5 mm edges, 2 layers, up to the epicardium", "worst tetrahedron: smallest dihedral angle",
        "annuli: opened in the flat base: mitral", "cavity: length 116", "from the file axis"})
    EXPECT_NE(r.out.find(line), std::string::npos) << "no '" << line << "' in:\n" << r.out;
}

TEST(CliMeshWall, BadOptionsAndSurfacesExitTwoWithOneLine) {
  const auto dir = scratchDir("mesh_wall_bad");
  const std::string f = "'" + kBivme + "'";
  expectBadWall(runHeartsim("mesh " + f + " --wall --units m", dir),
                kBivme +
                    ": a heart 91.6 m across (9.16e+03 cm) is implausible; expected 3-30 cm; is the file in "
                    "mm? (units = \"mm\" makes it 9.16 cm)");
  expectBadWall(runHeartsim("mesh " + f + " --wall --units inch", dir),
                kBivme + ": --units 'inch': expected mm or m");
  expectBadWall(runHeartsim("mesh " + f + " --wall --thickness 10", dir),
                kBivme + ": --thickness 10: expected a wall thickness in m within [0.002, 0.03]");
  expectBadWall(runHeartsim("mesh " + f + " --wall --thickness thick", dir),
                kBivme + ": --thickness: expected a wall thickness in m, e.g. 0.010, got 'thick'");
  expectBadWall(runHeartsim("mesh " + f + " --wall --resolution medium", dir),
                kBivme + ": --resolution 'medium': expected coarse, default or fine");
  expectBadWall(runHeartsim("mesh " + f + " --wall --septum 1,0", dir),
                kBivme + ": --septum '1,0': expected three numbers x,y,z, not all zero");
  expectBadWall(runHeartsim("mesh " + f + " --wall --mitral-loop 3", dir),
                kBivme + ": mitral loop 3: expected a loop number in [1, 2]");
  // A closed ball (a UV sphere, 5 cm across): no annuli and no flat base.
  {
    std::ofstream ball(dir / "ball.off");
    const int rings = 12, sectors = 24;
    ball << "OFF\n"
         << 2 + (rings - 1) * sectors << ' ' << 2 * sectors + (rings - 2) * sectors
         << " 0\n0 0 25\n0 0 -25\n";
    for (int i = 1; i < rings; ++i)
      for (int j = 0; j < sectors; ++j) {
        const double theta = 3.14159265358979 * i / rings, phi = 2 * 3.14159265358979 * j / sectors;
        ball << 25 * std::sin(theta) * std::cos(phi) << ' ' << 25 * std::sin(theta) * std::sin(phi) << ' '
             << 25 * std::cos(theta) << '\n';
      }
    const auto id = [&](int i, int j) { return 2 + (i - 1) * sectors + (j % sectors); };
    for (int j = 0; j < sectors; ++j) {
      ball << "3 0 " << id(1, j) << ' ' << id(1, j + 1) << '\n';
      ball << "3 1 " << id(rings - 1, j + 1) << ' ' << id(rings - 1, j) << '\n';
      for (int i = 1; i + 1 < rings; ++i)
        ball << "4 " << id(i, j) << ' ' << id(i + 1, j) << ' ' << id(i + 1, j + 1) << ' ' << id(i, j + 1)
             << '\n';
    }
  }
  expectBadWall(runHeartsim("mesh ball.off --wall", dir),
                "ball.off: a closed surface without a flat base; expected boundary loops at the mitral and "
                "aortic annuli or a flat "
                "truncated base");
  std::ofstream(dir / "tiny.off") << "OFF\n3 1 0\n0 0 0\n0.001 0 0\n0 0.001 0\n3 0 1 2\n";
  expectBadWall(runHeartsim("mesh tiny.off --wall", dir),
                "tiny.off: cannot guess the units from the size 0.001; expected --units mm or --units m");
}

}  // namespace
}  // namespace hs::testing
