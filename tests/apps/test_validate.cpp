// `heartsim validate dam-break`: the front arithmetic on synthetic data with known answers, the
// validation end to end against Martin & Moyce (1952), and clear errors for bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

#include "cli_runner.h"
#include "dam_break_validation.h"
#include "viz/image.h"

namespace hs::testing {
namespace {

using app::FrontCurve;

TEST(DamBreakValidation, FrontIgnoresParticlesAboveTheFloorBand) {
  const std::vector<pbd::Vec3> x = {pbd::Vec3(0.1f, 0.01f, 0), pbd::Vec3(0.3f, 0.011f, 0),
                                    pbd::Vec3(0.5f, 0.05f, 0)};  // a droplet ahead, in the air
  EXPECT_NEAR(app::surgeFront(x, 0.01, -0.1, 0.0, 0.02), 0.41, 1e-6);
  EXPECT_NEAR(app::surgeFront(x, 0.01, -0.1, 0.0, INFINITY), 0.61, 1e-6);
}

TEST(DamBreakValidation, TimeIsNTimesTSqrtGOverA) {
  EXPECT_NEAR(app::damBreakTime(0.1, 9.81, 0.05715, 2.0), 0.1 * std::sqrt(2 * 9.81 / 0.05715), 1e-12);
}

// A linear front Z = 1 + T: interpolation is exact, and a known offset gives known errors.
TEST(DamBreakValidation, InterpolationAndErrorOnSyntheticFront) {
  FrontCurve curve;
  for (int i = 0; i <= 30; ++i) {
    curve.T.push_back(0.1 * i);
    curve.Z.push_back(1.0 + 0.1 * i);
    curve.t.push_back(0.01 * i);
  }
  EXPECT_NEAR(app::interpolateFront(curve, 1.234), 2.234, 1e-12);
  EXPECT_EQ(app::interpolateFront(curve, -1.0), 1.0);
  EXPECT_EQ(app::interpolateFront(curve, 9.0), 4.0);

  const std::vector<app::DamBreakPoint> experiment = {{2.0, 1.0}, {2.5, 2.0}, {4.0, 3.0}};
  const auto points = app::compareFront(curve, experiment, 0.0, 2.5);
  ASSERT_EQ(points.size(), 2u);  // T = 3 is beyond the comparison
  EXPECT_NEAR(points[0].zSim, 2.0, 1e-12);
  EXPECT_NEAR(points[0].relativeError, 0.0, 1e-12);
  EXPECT_NEAR(points[1].zSim, 3.0, 1e-12);
  EXPECT_NEAR(points[1].relativeError, 0.2, 1e-12);
  EXPECT_NEAR(app::maxRelativeError(points), 0.2, 1e-12);

  // Delaying the simulated curve by 0.5 reads it at T - 0.5.
  const auto shifted = app::compareFront(curve, experiment, 0.5, 2.5);
  EXPECT_NEAR(shifted[0].tSim, 0.5, 1e-12);
  EXPECT_NEAR(shifted[0].zSim, 1.5, 1e-12);
  EXPECT_NEAR(shifted[0].relativeError, 0.25, 1e-12);
}

TEST(DamBreakValidation, ReferenceTableIsMonotone) {
  for (std::size_t i = 1; i < app::kMartinMoyceN2Front.size(); ++i) {
    EXPECT_GT(app::kMartinMoyceN2Front[i].z, app::kMartinMoyceN2Front[i - 1].z);
    EXPECT_GT(app::kMartinMoyceN2Front[i].t, app::kMartinMoyceN2Front[i - 1].t);
  }
}

// The acceptance figure: the front within 15% of the experiment at every point up to T = 2.5.
// Shortened to 0.2 s (T = 3.7; the comparison needs 0.135 s) to keep the test quick.
TEST(CliValidate, DamBreakFrontMatchesMartinMoyce) {
  const auto dir = scratchDir("validate_dam_break");
  const CliResult r = runHeartsim("validate dam-break --set simulation.duration=0.2 --json --out out", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_LE(j["max_relative_error"].get<double>(), 0.15);
  EXPECT_TRUE(j["pass"].get<bool>());
  EXPECT_EQ(j["particles"], 1728);
  EXPECT_EQ(j["points"].size(), 9u);  // the experimental points with T <= 2.5

  const std::string csv = readFile(dir / "out" / "front.csv");
  EXPECT_EQ(csv.rfind("t_s,T,Z", 0), 0u);
  int rows = 0;
  for (char c : csv) rows += c == '\n';
  EXPECT_EQ(rows, 402);  // header + t = 0 + 400 steps
  EXPECT_TRUE(nlohmann::json::parse(readFile(dir / "out" / "validation.json"))["pass"].get<bool>());

  const viz::Image png = viz::Image::loadPng((dir / "out" / "dam-break-front.png").string());
  ASSERT_GT(png.width(), 100);
  std::size_t dark = 0;
  for (std::uint8_t v : png.pixels()) dark += v < 128;
  EXPECT_GT(dark, 1000u) << "the plot looks blank";
}

TEST(CliValidate, UnknownScenarioIsBadInput) {
  const CliResult r = runHeartsim("validate dam-break --scenario no-such-scenario --out out",
                                  scratchDir("validate_unknown"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("heartsim: error:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no-such-scenario"), std::string::npos) << r.err;
}

TEST(CliValidate, ColumnOfWrongHeightIsBadInput) {
  const CliResult r = runHeartsim("validate dam-break --set 'blood.block_max=[0.05715,0.05715,0.028575]' --out out",
                                  scratchDir("validate_square"));
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("n^2 = 2"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace hs::testing
