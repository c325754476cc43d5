// The headless runner end to end: the JSON report, its acceptance figures, determinism across
// thread counts, and the files it writes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "io/output/vtk_writer.h"

namespace hs::testing {
namespace {

nlohmann::json runJson(const std::string& args, const std::string& name) {
  const auto dir = scratchDir(name);
  const CliResult r = runHeartsim("run " + args + " --json --out out", dir);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

TEST(CliRun, VersionPrintsVersionAndRevision) {
  const CliResult r = runHeartsim("--version", scratchDir("version"));
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_NE(r.out.find("heartsim 0."), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("git "), std::string::npos) << r.out;
}

TEST(CliRun, JsonReportHasEveryField) {
  const nlohmann::json j = runJson("heart-only --duration 0.1", "fields");
  for (const char* key : {"scenario", "steps", "sim_time_s", "dt_s", "setup_s", "wall_s", "steps_per_s", "threads",
                          "state_hash", "beats"})
    EXPECT_TRUE(j.contains(key)) << key;
  for (const char* key : {"vertices", "tets", "surface_triangles", "volume_error_max", "volume_error_mean",
                          "inverted_tets", "rest_deviation_final_rel", "min_dihedral_deg", "max_aspect_ratio"})
    EXPECT_TRUE(j["tissue"].contains(key)) << key;
  for (const char* key : {"volume_min_m3", "volume_max_m3", "ejection_fraction"})
    EXPECT_TRUE(j["cavity"].contains(key)) << key;
  // The heart's sizes, measured on the model (cardiac/anatomy/lv_anatomy.h): here the thesis's scale.
  for (const char* key : {"mitral_area_cm2", "aortic_area_cm2", "aortic_root_diameter_mm", "long_axis_mm"})
    EXPECT_GT(j["model"][key].get<double>(), 0) << key;
  EXPECT_GT(j["model"]["mitral_area_cm2"].get<double>(), j["model"]["aortic_area_cm2"].get<double>());
  EXPECT_EQ(j["steps"], 20);
  EXPECT_EQ(j["scenario"], "heart-only");
}

// The real-size hearts are an adult's left heart, measured on the mesh they run (docs/lv-model.md,
// "normal: an adult's left heart"): the annuli's areas, the aortic root across its sinuses and
// the ventricle's length within the adult ranges a lecture quotes, the inflow larger than the
// outflow (the thesis's expert). The dilated heart is left out: it is meant to be too large.
// --resolution scales the blood as the viewer's levels do (a quarter, half, the scenario, twice
// its particles; docs/viewer.md), and `fine` is the scenario as written, bit for bit.
TEST(CliRun, ResolutionScalesTheBloodAsTheViewerDoes) {
  const nlohmann::json written = runJson("normal --duration 0.005", "resolution-written");
  const int particles = written["blood"]["particles"].get<int>();
  ASSERT_GT(particles, 1000);
  const std::pair<const char*, double> levels[] = {{"coarse", 0.25}, {"medium", 0.5}, {"fine", 1.0}, {"finest", 2.0}};
  for (const auto& [word, factor] : levels) {
    const nlohmann::json j =
        runJson(std::string("normal --duration 0.005 --resolution ") + word, std::string("resolution-") + word);
    EXPECT_EQ(j["blood"]["particles"].get<int>(), int(std::lround(particles * factor))) << word;
    EXPECT_EQ(j["blood"]["lost"].get<int>(), 0) << word;
    if (factor == 1.0) EXPECT_EQ(j["state_hash"], written["state_hash"]);
    else EXPECT_NE(j["state_hash"], written["state_hash"]) << word;
  }
}

TEST(CliRun, TheRealSizeHeartsHaveAnAdultsSizes) {
  for (const char* name : {"normal", "irregular", "inconsistent", "anterior-infarct", "aortic-stenosis",
                           "heart-failure-preserved-ef", "mitral-regurgitation"}) {
    SCOPED_TRACE(name);
    const nlohmann::json m = runJson(std::string(name) + " --duration 0.002 --threads 1", "adult_sizes")["model"];
    const double mitral = m["mitral_area_cm2"].get<double>(), aortic = m["aortic_area_cm2"].get<double>();
    EXPECT_GE(mitral, 4.0);
    EXPECT_LE(mitral, 6.0);
    EXPECT_GE(aortic, 3.0);
    EXPECT_LE(aortic, 4.0);
    EXPECT_GT(mitral, aortic);
    EXPECT_GE(m["aortic_root_diameter_mm"].get<double>(), 30.0);
    EXPECT_LE(m["aortic_root_diameter_mm"].get<double>(), 34.0);
    EXPECT_GE(m["long_axis_mm"].get<double>(), 80.0);
    EXPECT_LE(m["long_axis_mm"].get<double>(), 90.0);
  }
}

// The foundation's acceptance figures: the thesis-scale wall keeps its tet volumes, never
// inverts, and ejects while beating.
TEST(CliRun, HeartOnlyKeepsVolumeAndEjects) {
  const nlohmann::json j = runJson("heart-only", "accept");
  EXPECT_LE(j["tissue"]["volume_error_mean"].get<double>(), 0.01);
  EXPECT_EQ(j["tissue"]["inverted_tets"], 0);
  EXPECT_GT(j["cavity"]["ejection_fraction"].get<double>(), 0.1);
  EXPECT_GT(j["beats"].get<int>(), 5);
}

TEST(CliRun, WallReturnsToRestAfterTwoBeats) {
  const nlohmann::json j = runJson("heart-only --set cycle.beats=2 --duration 3", "rest");
  EXPECT_EQ(j["beats"], 2);
  EXPECT_LE(j["tissue"]["rest_deviation_final_rel"].get<double>(), 0.01);
}

TEST(CliRun, SameStateHashForOneAndTwoThreads) {
  const nlohmann::json one = runJson("heart-only --duration 0.5 --threads 1", "threads1");
  const nlohmann::json two = runJson("heart-only --duration 0.5 --threads 2", "threads2");
  EXPECT_EQ(one["state_hash"], two["state_hash"]);
  EXPECT_EQ(two["threads"], 2);
}

TEST(CliRun, WritesMetricsCsvAndVtkSeries) {
  const auto dir = scratchDir("files");
  const CliResult r = runHeartsim("run heart-only --duration 0.1 --vtk --set output.vtk_every=5 --out out", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string csv = readFile(dir / "out" / "metrics.csv");
  EXPECT_EQ(csv.rfind("step,time_s,phase,wall_phase,cavity_volume_m3", 0), 0u);
  int rows = 0;
  for (char c : csv) rows += c == '\n';
  EXPECT_EQ(rows, 21);  // header + 20 steps
  const std::string pvd = readFile(dir / "out" / "wall.pvd");
  EXPECT_NE(pvd.find("wall_20.vtu"), std::string::npos);
  const io::VtuFrame frame = io::readVtu(dir / "out" / "wall_20.vtu");
  EXPECT_GT(frame.points.size(), 500u);
  EXPECT_GT(frame.tets.size(), 1000u);
}

// A scenario's name may hold anything; its default output folder stays directly inside
// results/ of the working directory.
TEST(CliRun, DefaultOutputFolderStaysInsideResults) {
  const auto dir = scratchDir("output_name") / "work";
  for (const auto& [name, folder] : {std::pair{"..", "__"}, std::pair{"/tmp/x", "_tmp_x"}, std::pair{"a b", "a_b"}}) {
    const CliResult r = runHeartsim(std::string("run heart-only --duration 0.01 --set 'scenario.name=") + name + "'", dir);
    ASSERT_EQ(r.exitCode, 0) << name << ": " << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "results" / folder / "summary.json")) << name;
    EXPECT_TRUE(std::filesystem::exists(dir / "results" / folder / "metrics.csv")) << name;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "summary.json"));
  EXPECT_FALSE(std::filesystem::exists(dir.parent_path() / "summary.json"));
}

}  // namespace
}  // namespace hs::testing
