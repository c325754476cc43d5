// `heartsim bench --scenario FILE`: a scenario file stepped as the built-in hearts are, with each
// stage's time and the blood in the flow counted (a bad file: test_cli_errors.cpp).
#include <gtest/gtest.h>

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

}  // namespace
