// `heartsim run` with blood: the built-in fluid scenarios end with the properties the blood
// issue asks for (settled column, nothing lost, same state for 1 and 2 threads), and bad
// fluid parameters stop the run with exit 2 and a one-line message naming the key.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_runner.h"

namespace {

using hs::testing::CliResult;
using hs::testing::runHeartsim;
using hs::testing::scratchDir;

nlohmann::json report(const CliResult& r) {
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

int lines(const std::string& text) {
  int n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

void expectBadFluidInput(const std::string& args, const std::vector<std::string>& mustMention) {
  const auto dir = scratchDir("blood_bad");
  const CliResult r = runHeartsim(args, dir);
  EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  for (const std::string& word : mustMention)
    EXPECT_NE(r.err.find(word), std::string::npos) << "missing '" << word << "' in: " << r.err;
}

// fluid-at-rest: a 10 cm column of blood (2,000 particles) after 3 s in a closed box.
TEST(CliBlood, ColumnAtRestSettlesWithLowDensityErrorAndNothingLost) {
  const auto dir = scratchDir("blood_rest");
  const nlohmann::json j = report(runHeartsim("run fluid-at-rest --threads 1 --json", dir));
  const auto& b = j.at("blood");
  EXPECT_EQ(b.at("particles").get<int>(), 2000);
  EXPECT_EQ(b.at("lost").get<int>(), 0);
  EXPECT_LE(b.at("density_error_mean").get<double>(), 0.01);
  EXPECT_GT(b.at("full_neighbourhood").get<int>(), 1000);
  const double sqrtGH = std::sqrt(9.81 * 0.1);  // column height H = 0.1 m
  EXPECT_LT(b.at("max_speed_m_s").get<double>(), 0.01 * sqrtGH);
  EXPECT_FALSE(j.contains("tissue"));  // no heart in this scenario
  std::printf("fluid-at-rest: density error mean %.4f, max speed %.4f m/s = %.2f%% of sqrt(gH)\n",
              b.at("density_error_mean").get<double>(), b.at("max_speed_m_s").get<double>(),
              100 * b.at("max_speed_m_s").get<double>() / sqrtGH);
}

// The same column in a box made of triangles (static mesh collision) stays in the box.
TEST(CliBlood, MeshContainerKeepsTheBlood) {
  const auto dir = scratchDir("blood_mesh");
  const nlohmann::json j =
      report(runHeartsim("run fluid-at-rest --set container.mesh=true --duration 1 --threads 1 --json", dir));
  EXPECT_EQ(j.at("blood").at("lost").get<int>(), 0);
  EXPECT_LE(j.at("blood").at("density_error_mean").get<double>(), 0.01);
}

TEST(CliBlood, DamBreakSameStateForOneAndTwoThreadsAndNothingLost) {
  const auto dir = scratchDir("blood_threads");
  const nlohmann::json one = report(runHeartsim("run dam-break --duration 0.1 --threads 1 --json --out one", dir));
  const nlohmann::json two = report(runHeartsim("run dam-break --duration 0.1 --threads 2 --json --out two", dir));
  EXPECT_EQ(one.at("state_hash"), two.at("state_hash"));
  EXPECT_EQ(one.at("blood").at("lost").get<int>(), 0);
  EXPECT_GT(one.at("blood").at("max_speed_run_m_s").get<double>(), 0.3);  // it did collapse
  // metrics.csv has the blood columns.
  const std::string csv = hs::testing::readFile(dir / "one" / "metrics.csv");
  EXPECT_NE(csv.find("blood_density_error_mean"), std::string::npos);
  EXPECT_EQ(lines(csv), 201);  // header + 0.1 s / 0.5 ms
}

TEST(CliBlood, BadFluidParametersExitTwoNamingTheKey) {
  expectBadFluidInput("run fluid-at-rest --set blood.spacing=0", {"blood.spacing", ">= 1e-04"});
  expectBadFluidInput("run fluid-at-rest --set blood.spacing=-0.01", {"blood.spacing"});
  expectBadFluidInput("run fluid-at-rest --set blood.support_radius=0.004", {"blood.support_radius", "blood.spacing"});
  // A kernel support radius in the file smaller than the spacing names the file and line.
  expectBadFluidInput("run fluid-at-rest --set blood.radius=0", {"blood.radius"});
  expectBadFluidInput("run fluid-at-rest --set blood.particles=20000000", {"blood.particles"});
  // Filling the block at the least spacing the reader takes: far beyond this machine's memory
  // (without gravity, which at this spacing would be refused first: it moves a particle its
  // spacing per step).
  expectBadFluidInput("run fluid-at-rest --set blood.spacing=0.0001 --set blood.support_radius=0.0002 "
                      "--set blood.radius=0.0001 --set 'simulation.gravity=[0,0,0]'",
                      {"blood", "GB", "blood.spacing"});
  expectBadFluidInput("run fluid-at-rest --set blood.particles=5000", {"blood.particles", "holds 2000"});
  expectBadFluidInput("run fluid-at-rest --set blood.viscosity=100", {"blood.viscosity", "dt"});
  expectBadFluidInput("run fluid-at-rest --set blood.particle_collision=true --set blood.radius=0.004",
                      {"blood.radius", "spacing"});
  expectBadFluidInput("run fluid-at-rest --set container.max=[0.04,0.12,0.05]", {"block_min", "container"});
  // Without the closed loop no blood can wait outside the model: the chamber must hold it all.
  expectBadFluidInput("run heart-only --set blood.enabled=true --set blood.start=chamber --set circulation.loop=false "
                      "--set blood.particles=100000",
                      {"blood.particles", "chamber holds"});
}

}  // namespace
