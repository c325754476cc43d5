// `heartsim bench --scenario FILE`: a scenario file stepped as the built-in hearts are, with each
// stage's time and the blood in the flow counted (a bad file: test_cli_errors.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.h"
#include "io/scenario/scenario_file.h"

namespace {

using hs::testing::CliResult;
using hs::testing::runHeartsim;
using hs::testing::scratchDir;

TEST(CliBench, AScenarioFileIsSteppedWithItsStagesAndTheBloodInTheFlow) {
  const auto dir = scratchDir("bench_scenario_file");
  std::ofstream(dir / "mine.toml") << hs::io::builtinScenarioText("paper-chamber-beating");
  const CliResult r = runHeartsim("bench --scenario mine.toml --threads 1 --seconds 0.3 --json", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(r.out);
  ASSERT_EQ(report["cases"].size(), 1u);  // the file alone: no built-in case unless named
  const nlohmann::json& c = report["cases"][0];
  EXPECT_EQ(c["name"], "mine.toml");
  EXPECT_GT(c["steps_per_s"].get<double>(), 0);
  EXPECT_TRUE(c["stages_ms_per_step"].contains("density_kernels"));
  // The thesis's chamber holds its blood in the heart: the particles in the flow are all of it,
  // and the time per particle in the flow is the time per particle.
  const double particles = c["particles"].get<double>(), active = c["active_particles_mean"].get<double>();
  EXPECT_GT(active, 0);
  EXPECT_LE(active, particles);
  EXPECT_NEAR(c["ns_per_active_particle_step"].get<double>() * active, c["ns_per_particle_step"].get<double>() * particles,
              1e-6 * c["ns_per_particle_step"].get<double>() * particles);
}

// --resolution: the bench's scenario at the viewer's level (a quarter of the particles at
// coarse), said in its report; the thread governor's share of steps on fewer threads is there.
TEST(CliBench, AResolutionBenchesTheBloodAtThatLevel) {
  const auto dir = scratchDir("bench_resolution");
  std::ofstream(dir / "mine.toml") << hs::io::builtinScenarioText("paper-chamber-beating");
  const CliResult fine = runHeartsim("bench --scenario mine.toml --threads 2 --seconds 0.3 --json", dir);
  const CliResult coarse =
      runHeartsim("bench --scenario mine.toml --threads 2 --seconds 0.3 --json --resolution coarse", dir);
  ASSERT_EQ(fine.exitCode, 0) << fine.err;
  ASSERT_EQ(coarse.exitCode, 0) << coarse.err;
  const nlohmann::json f = nlohmann::json::parse(fine.out)["cases"][0];
  const nlohmann::json c = nlohmann::json::parse(coarse.out)["cases"][0];
  EXPECT_EQ(f["resolution"], "fine");
  EXPECT_EQ(c["resolution"], "coarse");
  const int blood = f["particles"].get<int>();  // paper-chamber-beating's blood count
  EXPECT_GT(blood, 0);
  EXPECT_EQ(c["particles"].get<int>(), int(std::lround(0.25 * blood)));
  const double share = c["fewer_threads_share"].get<double>();
  EXPECT_GE(share, 0);
  EXPECT_LE(share, 1);
}

}  // namespace
