// The run monitor: each health check fails on its own kind of trouble and names what and
// where, on plain statistics (no heart run); then a short healthy run passes, a wall pushed
// too far fails at its first step with the tet's place, and the figures of a run add up.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cardiac/heart_simulation.h"
#include "cardiac/run_monitor.h"

namespace hs::cardiac {
namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

const LvModel& smallModel() {
  static const LvModel model = [] {
    LvGeometryParams params;
    params.resolution = Real(0.5);
    return buildLvModel(params);
  }();
  return model;
}

TEST(RunMonitorChecks, HealthyStatisticsPass) {
  EXPECT_EQ(checkTissue(TissueStats{}, true, &smallModel(), smallModel().mesh.vertices).check,
            HealthCheck::Healthy);
  BloodStats blood;
  blood.particles = 100;
  blood.lost = 5;
  blood.insideWall = 7;
  EXPECT_EQ(checkBlood(blood, HealthLimits{}).check, HealthCheck::Healthy) << "unlimited by default";
  EXPECT_EQ(checkBlood(blood, HealthLimits{5, 7}).check, HealthCheck::Healthy) << "at the limit is fine";
}

TEST(RunMonitorChecks, NonFiniteNamesTheParticle) {
  TissueStats tissue;
  tissue.finite = false;
  tissue.firstNonFinite = 42;
  const HealthIssue issue = checkTissue(tissue, true, nullptr, {});
  EXPECT_EQ(issue.check, HealthCheck::NonFinite);
  EXPECT_TRUE(contains(issue.what, "particle 42")) << issue.what;
  EXPECT_TRUE(contains(issue.what, "non-finite")) << issue.what;
  // A cavity volume that is not a number is the same failure.
  EXPECT_EQ(checkTissue(TissueStats{}, false, nullptr, {}).check, HealthCheck::NonFinite);
}

TEST(RunMonitorChecks, InvertedTetNamesItsPlace) {
  const LvModel& model = smallModel();
  TissueStats tissue;
  tissue.invertedTets = 3;
  tissue.firstInvertedTet = 5;
  const HealthIssue issue = checkTissue(tissue, true, &model, model.mesh.vertices);
  EXPECT_EQ(issue.check, HealthCheck::InvertedTets);
  for (const char* part : {"3 wall tetrahedra inverted", "tet 5", "x = ", " m, "})
    EXPECT_TRUE(contains(issue.what, part)) << "missing '" << part << "' in: " << issue.what;
  const Index v = model.mesh.tets[5][0];
  const std::string where = tetLocation(model, model.mesh.vertices, 5);
  if (model.region[v] == Region::Myocardium) {
    EXPECT_TRUE(contains(where, "AHA segment " + std::to_string(int(model.segment[v])))) << where;
  }
  EXPECT_TRUE(contains(issue.what, where)) << issue.what;
}

TEST(RunMonitorChecks, LostAndInsideWallBloodFailOverTheLimit) {
  BloodStats blood;
  blood.particles = 100;
  blood.lost = 3;
  const HealthIssue lost = checkBlood(blood, HealthLimits{0, HealthLimits::kUnlimited});
  EXPECT_EQ(lost.check, HealthCheck::BloodLost);
  EXPECT_TRUE(contains(lost.what, "3 of 100 blood particles lost")) << lost.what;

  blood.lost = 0;
  blood.insideWall = 4;
  const HealthIssue inside = checkBlood(blood, HealthLimits{HealthLimits::kUnlimited, 1});
  EXPECT_EQ(inside.check, HealthCheck::BloodInsideWall);
  EXPECT_TRUE(contains(inside.what, "4 of 100 blood particles inside the wall")) << inside.what;
}

TEST(RunMonitorChecks, VerdictMessageSaysWhen) {
  Verdict verdict;
  verdict.step = 12;
  verdict.time = 0.06;
  verdict.issue = {HealthCheck::NonFinite, "particle 3 has a non-finite position or velocity"};
  EXPECT_FALSE(verdict.healthy());
  EXPECT_EQ(verdict.message(),
            "simulation became invalid at step 12 (t = 0.06 s): particle 3 has a non-finite position or velocity");
}

TEST(RunMonitorChecks, ExtremesAverageDensityOverTheLastSecond) {
  RunExtremes extremes;
  extremes.lastSecondFrom = 1.0;
  for (int i = 1; i <= 4; ++i) {
    StepSample sample;
    sample.time = 0.5 * i;  // 0.5, 1, 1.5, 2: the last two are in the last second
    sample.cavity = double(i);
    sample.tissue.volumeErrorMax = Real(0.01 * i);
    BloodStats blood;
    blood.densityErrorMean = 0.1 * i;
    blood.densityErrorMax = 0.2 * i;
    blood.lost = std::size_t(5 - i);
    sample.blood = blood;
    extremes.add(sample, true);
  }
  EXPECT_EQ(extremes.lastSecondSteps, 2u);
  EXPECT_NEAR(extremes.densityErrorMeanSum, 0.3 + 0.4, 1e-12);
  EXPECT_NEAR(extremes.densityErrorMax, 0.8, 1e-12);
  EXPECT_EQ(extremes.bloodLostMax, 4u);
  EXPECT_EQ(extremes.cavityMin, 1.0);
  EXPECT_EQ(extremes.cavityMax, 4.0);
  EXPECT_NEAR(extremes.volumeErrorMax, 0.04, 1e-6);
}

Scenario smallHeart() {
  Scenario s;
  s.geometry.resolution = Real(0.5);
  s.cycle.beatingDuration = 4;
  return s;
}

TEST(RunMonitor, ShortHealthyRunPassesAndCountsBeats) {
  HeartSimulation sim(smallHeart(), 1);
  MonitorSettings settings;
  settings.everyColumn = true;
  RunMonitor monitor(sim, settings);
  EXPECT_EQ(monitor.last().step, 0);
  EXPECT_GT(monitor.last().cavity, 0.0);
  for (int k = 0; k < 20; ++k) {
    sim.step();
    ASSERT_TRUE(monitor.observe().healthy()) << monitor.verdict().message();
    EXPECT_EQ(monitor.last().step, k + 1);
    EXPECT_DOUBLE_EQ(monitor.last().cavity, double(sim.cavityVolume()));
  }
  monitor.finish();
  EXPECT_TRUE(monitor.checkNow().healthy());
  const RunSummary summary = monitor.summary();
  EXPECT_EQ(summary.steps, 20);
  EXPECT_TRUE(summary.heart);
  EXPECT_FALSE(summary.blood);
  EXPECT_GE(summary.beats.beats().size(), 2u) << "4 steps per phase: a beat every 8 steps";
  EXPECT_LT(summary.cavityMin, summary.cavityMax);
  EXPECT_EQ(summary.tets, sim.model().mesh.tets.size());
  EXPECT_EQ(summary.stateHash, pbd::stateHash(sim.particles()));
}

// As `heartsim run heart-only --set cycle.beating_displace=3`: the wall folds at once.
TEST(RunMonitor, FoldedWallFailsAtItsFirstStepWithThePlace) {
  Scenario s = smallHeart();
  s.cycle.beatingDisplace = Real(3);
  HeartSimulation sim(s, 1);
  RunMonitor monitor(sim, MonitorSettings::healthOnly());
  sim.step();
  const Verdict& verdict = monitor.observe();
  ASSERT_FALSE(verdict.healthy());
  EXPECT_EQ(verdict.issue.check, HealthCheck::InvertedTets);
  for (const char* part : {"step 1 ", "inverted", "tet ", "x = "})
    EXPECT_TRUE(contains(verdict.message(), part)) << "missing '" << part << "' in: " << verdict.message();
  EXPECT_EQ(monitor.observedSteps(), 0) << "a failed step adds no figures";
}

}  // namespace
}  // namespace hs::cardiac
