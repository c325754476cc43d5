// The blood's resolution levels: each scales the scenario's blood (spacing, radius and support
// radius alike, the count by the cube of the spacing's inverse) and nothing else; the start-up
// pick takes the finest level that holds real time; the panel's line and the scripted run's
// last line say what runs and how fast.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "io/scenario/scenario_file.h"
#include "viewer/app/pacing.h"
#include "viewer/app/resolution_probe.h"
#include "viewer/panels/blood_resolution.h"

namespace hs::viewer {
namespace {

using R = BloodResolution;

TEST(BloodResolution, EachLevelOfNormalHasItsSpacingRadiusSupportAndCount) {
  const cardiac::Scenario normal = io::loadScenario("normal");
  ASSERT_EQ(normal.blood.particles, 4600);
  ASSERT_NEAR(double(normal.blood.spacing), 0.0036, 1e-9);
  const struct {
    R level;
    double spacing;
    int particles;
  } expected[] = {{R::Coarse, 0.0036 * std::cbrt(4.0), 1150},
                  {R::Medium, 0.0036 * std::cbrt(2.0), 2300},
                  {R::Fine, 0.0036, 4600},
                  {R::Finest, 0.0036 / std::cbrt(2.0), 9200}};
  for (const auto& e : expected) {
    cardiac::Scenario s = normal;
    applyResolution(e.level, s);
    SCOPED_TRACE(resolutionName(e.level));
    EXPECT_NEAR(double(s.blood.spacing), e.spacing, 1e-6);
    EXPECT_NEAR(double(s.blood.radius), e.spacing / 2, 1e-6);
    EXPECT_NEAR(double(s.blood.supportRadius), 2 * e.spacing, 1e-6);
    EXPECT_EQ(s.blood.particles, e.particles);
    // The same volume of blood: count x spacing^3 as the scenario's, within the count's rounding.
    EXPECT_NEAR(double(s.blood.particles) * std::pow(double(s.blood.spacing), 3),
                4600 * std::pow(0.0036, 3), 4600 * std::pow(0.0036, 3) * 1e-3);
    // The blood's physics otherwise as the scenario says.
    EXPECT_EQ(s.blood.restDensity, normal.blood.restDensity);
    EXPECT_EQ(s.blood.viscosity, normal.blood.viscosity);
    EXPECT_EQ(s.blood.xsph, normal.blood.xsph);
    EXPECT_EQ(s.blood.iterations, normal.blood.iterations);
    EXPECT_EQ(s.simulation.dt, normal.simulation.dt);
  }
}

TEST(BloodResolution, TheScenarioLevelIsTheScenarioBitwiseAndAFillCountStaysAFill) {
  const cardiac::Scenario dam = io::loadScenario("dam-break");
  ASSERT_EQ(dam.blood.particles, 0);
  cardiac::Scenario fine = dam;
  applyResolution(R::Fine, fine);
  EXPECT_EQ(fine.blood.spacing, dam.blood.spacing);
  EXPECT_EQ(fine.blood.supportRadius, dam.blood.supportRadius);
  cardiac::Scenario coarse = dam;
  applyResolution(R::Coarse, coarse);
  EXPECT_EQ(coarse.blood.particles, 0);  // the block is filled at the coarser spacing
  EXPECT_GT(coarse.blood.spacing, dam.blood.spacing);
  // The scenario's own proportions kept: dam-break's support is 2 spacings, its radius its own.
  EXPECT_NEAR(double(coarse.blood.supportRadius / coarse.blood.spacing),
              double(dam.blood.supportRadius / dam.blood.spacing), 1e-6);
  EXPECT_NEAR(double(coarse.blood.radius / coarse.blood.spacing), double(dam.blood.radius / dam.blood.spacing),
              1e-6);
}

TEST(BloodResolution, NamesParseBackAndNothingElseDoes) {
  for (const ResolutionLevel& l : kResolutionLevels) EXPECT_EQ(parseResolution(l.name), l.level);
  for (const char* bad : {"auto", "Fine", "", "finer", "fine "}) EXPECT_FALSE(parseResolution(bad)) << bad;
}

TEST(BloodResolution, CountsAtOtherLevelsFollowTheRunningCount) {
  EXPECT_EQ(particlesAtLevel(R::Finest, R::Medium, 2100), 8400);
  EXPECT_EQ(particlesAtLevel(R::Coarse, R::Fine, 4200), 1050);
  EXPECT_EQ(particlesAtLevel(R::Medium, R::Medium, 2101), 2101);
}

std::vector<LevelMeasurement> measured(std::vector<std::pair<R, double>> paces) {
  std::vector<LevelMeasurement> m;
  for (auto [level, pace] : paces) m.push_back({level, pace >= 0, std::max(pace, 0.0)});
  return m;
}

TEST(BloodResolution, ThePickIsTheFinestLevelThatHoldsRealTime) {
  EXPECT_EQ(chooseResolution(measured({{R::Coarse, 3.0}, {R::Medium, 1.5}, {R::Fine, 0.6}, {R::Finest, -1}})),
            R::Medium);
  EXPECT_EQ(chooseResolution(measured({{R::Coarse, 9}, {R::Medium, 6}, {R::Fine, 3}, {R::Finest, 1.2}})), R::Finest);
  // At the margin: 1.1x holds, just below does not.
  EXPECT_EQ(chooseResolution(measured({{R::Coarse, 2}, {R::Medium, kHoldsRealTimePace}})), R::Medium);
  EXPECT_EQ(chooseResolution(measured({{R::Coarse, 2}, {R::Medium, kHoldsRealTimePace - 0.01}})), R::Coarse);
  // A level that could not be built is skipped.
  EXPECT_EQ(chooseResolution(measured({{R::Coarse, -1}, {R::Medium, 2}, {R::Fine, 0.5}})), R::Medium);
}

TEST(BloodResolution, NoneHoldingGivesTheCoarsestMeasuredAndNoneMeasuredTheScenarios) {
  EXPECT_EQ(chooseResolution(measured({{R::Coarse, 0.4}, {R::Medium, -1}, {R::Fine, -1}})), R::Coarse);
  EXPECT_EQ(chooseResolution(measured({{R::Coarse, -1}, {R::Medium, 0.3}})), R::Medium);
  EXPECT_EQ(chooseResolution(measured({{R::Coarse, -1}, {R::Medium, -1}})), kScenarioResolution);
  EXPECT_EQ(chooseResolution({}), kScenarioResolution);
}

TEST(BloodResolution, MeasuringStopsAtTheFirstLevelTooSlow) {
  EXPECT_TRUE(worthMeasuring({}));
  EXPECT_TRUE(worthMeasuring(measured({{R::Coarse, 2}})));
  EXPECT_TRUE(worthMeasuring(measured({{R::Coarse, -1}})));  // not built: the next may be
  EXPECT_FALSE(worthMeasuring(measured({{R::Coarse, 2}, {R::Medium, 0.9}})));
}

TEST(BloodResolution, ThousandsAreSeparated) {
  EXPECT_EQ(withThousands(0), "0");
  EXPECT_EQ(withThousands(999), "999");
  EXPECT_EQ(withThousands(4200), "4,200");
  EXPECT_EQ(withThousands(1234567), "1,234,567");
  EXPECT_EQ(withThousands(-1050), "-1,050");
}

TEST(BloodResolution, ThePanelLineSaysTheLevelCountAndPace) {
  ResolutionStatus s;
  s.level = R::Medium;
  s.particles = 2100;
  s.measuredPace = 1.3;
  EXPECT_EQ(resolutionLine(s, 1.0, false), "blood: medium, 2,100 particles, holds real time (1.3x)");
  // Paused: no pace claimed, measured or not.
  EXPECT_EQ(resolutionLine(s, 0.0, false, true), "blood: medium, 2,100 particles, paused");
  // Picked finer than the machine holds: the pace meter's slow motion.
  s.level = R::Finest;
  s.particles = 8400;
  s.measuredPace.reset();
  EXPECT_EQ(resolutionLine(s, 0.45, true), "blood: finest, 8,400 particles, 0.45x real time: slow motion");
  EXPECT_EQ(resolutionLine(s, 1.0, false), "blood: finest, 8,400 particles, holds real time");
  // The coarsest measured below real time says so before the meter has a window.
  s.level = R::Coarse;
  s.particles = 1050;
  s.measuredPace = 0.4;
  EXPECT_EQ(resolutionLine(s, 1.0, false), "blood: coarse, 1,050 particles, measured 0.4x real time: slow motion");
  s.measuring = true;
  s.measuringWhat = "medium (2 of 4)";
  EXPECT_EQ(resolutionLine(s, 1.0, false), "measuring this computer's pace: medium (2 of 4)");
}

TEST(BloodResolution, AFixedCountIsReportedAsGivenUntilAnotherLevelIsPicked) {
  ResolutionStatus s;
  s.particles = 1000;
  s.fixedBy = "as --set blood.particles sets it";
  EXPECT_EQ(resolutionLine(s, 0.3, true),
            "blood: 1,000 particles (as --set blood.particles sets it), 0.3x real time: slow motion");
  s.level = R::Coarse;
  s.particles = 250;
  EXPECT_EQ(resolutionLine(s, 1.0, false), "blood: coarse, 250 particles, holds real time");
}

TEST(ScriptedRunLine, GivesFramesThenTheSimulationsPaceAndCountOnOneLine) {
  FrameTimeSummary f;
  f.frames = 590, f.meanMs = 26.04, f.fps = 38.4, f.p95Ms = 33.7;
  SimulationPace p;
  p.simulatedSeconds = 10.2, p.wallSeconds = 10, p.steppingSeconds = 6.4, p.particles = 2100;
  EXPECT_EQ(scriptedRunLine(f, p),
            "heartsim: 590 frames: 26.0 ms mean, 38.4 fps, 95% within 33.7 ms; simulation 1.02x real time "
            "(stepping 64% of the time), 2,100 particles");
  p.particles = 0;
  EXPECT_NE(scriptedRunLine(f, p).find("real time (stepping 64% of the time), no blood"), std::string::npos);
  EXPECT_EQ(scriptedRunLine(f, std::nullopt),
            "heartsim: 590 frames: 26.0 ms mean, 38.4 fps, 95% within 33.7 ms; simulation not started");
  EXPECT_EQ(scriptedRunLine(f, p).find('\n'), std::string::npos);
}

TEST(ResolutionProbe, MeasuresAFixedStretchOfSimulatedTime) {
  EXPECT_EQ(ResolutionProbe::measuredSteps(0.001), 100);
  EXPECT_EQ(ResolutionProbe::measuredSteps(0.05), ResolutionProbe::kMinSteps);
  EXPECT_EQ(ResolutionProbe::measuredSteps(1e-5), ResolutionProbe::kMaxSteps);
}

// The probe on a small scenario: one result per level in order, the coarsest measured, and no
// level measured after one that fell short (whatever this machine's pace).
TEST(ResolutionProbe, MeasuresCoarsestFirstAndStopsAfterTheFirstTooSlow) {
  const cardiac::Scenario base = io::loadScenario("fluid-at-rest");
  std::vector<std::pair<R, cardiac::Scenario>> levels;
  for (const ResolutionLevel& l : kResolutionLevels) {
    cardiac::Scenario s = base;
    applyResolution(l.level, s);
    levels.emplace_back(l.level, s);
  }
  ResolutionProbe probe(levels, 1);
  while (!probe.done()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const std::vector<LevelMeasurement> m = probe.measurements();
  ASSERT_EQ(m.size(), kResolutionLevels.size());
  for (std::size_t i = 0; i < m.size(); ++i) {
    EXPECT_EQ(m[i].level, kResolutionLevels[i].level);
    if (m[i].measured) {
      EXPECT_GT(m[i].pace, 0);
      EXPECT_TRUE(worthMeasuring(std::span(m).first(i))) << i;
    }
  }
  EXPECT_TRUE(m[0].measured);
}

}  // namespace
}  // namespace hs::viewer
