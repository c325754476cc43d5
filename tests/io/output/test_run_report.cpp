// summary.json's content from a run's summary: the keys in their order, the heart's and the
// blood's parts only when they exist, beats and pump figures in mL, and the stderr line.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "io/output/run_report.h"

namespace hs::io {
namespace {

std::vector<std::string> keys(const nlohmann::ordered_json& j) {
  std::vector<std::string> out;
  for (const auto& [key, value] : j.items()) out.push_back(key);
  return out;
}

// Three 1 s beats (systole 0.3 s) from 120 mL down to 50 mL, at 10 ms steps.
cardiac::BeatTracker threeBeats() {
  cardiac::BeatTracker beats(120e-6, 0.01);
  for (int k = 0; k < 300; ++k) {
    const double t = 0.01 * k;
    const double inBeat = t - std::floor(t);
    const cardiac::Phase phase = inBeat < 0.3 ? cardiac::Phase::Systole : cardiac::Phase::Diastole;
    beats.record(t, phase, phase == cardiac::Phase::Systole ? 50e-6 : 120e-6);
  }
  beats.finish();
  return beats;
}

cardiac::RunSummary heartRun() {
  cardiac::RunSummary run;
  run.steps = 300;
  run.time = 3.0;
  run.stateHash = 0xabcdef;
  run.heart = true;
  run.vertices = 10, run.tets = 20, run.surfaceTriangles = 30;
  run.cavityMin = 50e-6, run.cavityMax = 120e-6;
  run.beats = threeBeats();
  return run;
}

cardiac::Scenario scenario() {
  cardiac::Scenario s;
  s.name = "test-heart";
  s.simulation.dt = cardiac::Real(0.01);
  return s;
}

TEST(RunReport, HeartRunHasItsKeysInOrder) {
  const RunTiming timing{0.5, 2.0, 2};
  const nlohmann::ordered_json report = runReport(scenario(), timing, heartRun(), "out/dir");
  EXPECT_EQ(keys(report), (std::vector<std::string>{"scenario", "steps", "sim_time_s", "dt_s", "setup_s", "wall_s",
                                                    "steps_per_s", "threads", "iterations", "state_hash", "tissue",
                                                    "cavity", "beats", "heart", "motion", "output_dir"}));
  EXPECT_EQ(report["state_hash"], "0000000000abcdef");
  EXPECT_DOUBLE_EQ(report["steps_per_s"].get<double>(), 150.0);
  EXPECT_EQ(report["beats"], 3);
  EXPECT_EQ(report["cavity"]["beats"].size(), 3u);
  EXPECT_NEAR(report["cavity"]["beats"][0]["edv_ml"].get<double>(), 120.0, 1e-9);
  EXPECT_NEAR(report["cavity"]["beats"][0]["esv_ml"].get<double>(), 50.0, 1e-9);
  // Means over the complete beats after the first: the second only (the third ends the run).
  EXPECT_EQ(report["heart"]["beats_averaged"], 1);
  EXPECT_NEAR(report["heart"]["stroke_volume_ml"].get<double>(), 70.0, 1e-9);
  EXPECT_NEAR(report["heart"]["cardiac_output_l_min"].get<double>(), 4.2, 1e-9);
  EXPECT_FALSE(report.contains("blood"));
  EXPECT_TRUE(report["motion"].is_null());  // no recorded beat: nothing to compare, not zeros
}

TEST(RunReport, ARecordedBeatIsReportedBesideTheHeart) {
  cardiac::RunSummary run = heartRun();
  run.motionFrameVolumes = {120e-6, 80e-6, 50e-6, 90e-6};
  run.motionPeriod = 0.9;
  run.motionVolumeErrorMax = 0.012;
  const nlohmann::ordered_json m = runReport(scenario(), RunTiming{0.5, 2.0, 2}, run, "out/dir")["motion"];
  EXPECT_EQ(m["frames"], 4);
  EXPECT_DOUBLE_EQ(m["period_s"].get<double>(), 0.9);
  EXPECT_NEAR(m["recorded_edv_ml"].get<double>(), 120.0, 1e-9);
  EXPECT_NEAR(m["recorded_esv_ml"].get<double>(), 50.0, 1e-9);
  EXPECT_NEAR(m["recorded_ejection_fraction"].get<double>(), 70.0 / 120.0, 1e-12);
  EXPECT_DOUBLE_EQ(m["volume_error_max"].get<double>(), 0.012);
}

TEST(RunReport, BloodPartTakesTheRunsWorst) {
  cardiac::RunSummary run;
  run.blood = true;
  run.bloodFinal.particles = 1000;
  run.bloodFinal.lost = 1;
  run.bloodLost = 4;
  run.bloodInsideWall = 2;
  run.densityErrorMean = 0.01;
  const nlohmann::ordered_json report = runReport(scenario(), RunTiming{}, run, "d");
  EXPECT_FALSE(report.contains("tissue"));
  const auto& blood = report["blood"];
  EXPECT_EQ(keys(blood), (std::vector<std::string>{"particles", "lost", "inside_wall", "density_error_mean",
                                                   "density_error_max", "full_neighbourhood", "mean_neighbours",
                                                   "max_speed_m_s", "max_speed_run_m_s", "smoothed_speed_max_run_m_s",
                                                   "iterations"}));
  EXPECT_EQ(blood["lost"], 4);
  EXPECT_EQ(report["steps_per_s"], 0.0) << "no time measured";
  const std::string line = runSummaryLine(scenario(), RunTiming{}, run, "d");
  EXPECT_NE(line.find("1000 blood particles, 4 lost, 2 inside the wall"), std::string::npos) << line;
}

TEST(RunReport, SummaryLineGivesThePumpInClinicalUnits) {
  const std::string line = runSummaryLine(scenario(), RunTiming{1, 2, 2}, heartRun(), "out/dir");
  for (const char* part : {"test-heart: 300 steps in 2 s (150 steps/s, 2 threads)", "over 3 beats",
                           "stroke volume 70 mL", "cardiac output 4.2 L/min", "results in out/dir"})
    EXPECT_NE(line.find(part), std::string::npos) << "missing '" << part << "' in: " << line;
}

// At 40 bpm a 1.5 s run has one beat and nothing to average: the pump's figures are not
// measured and must read as null ("n/a"), never as a 0 that looks like an empty heart.
TEST(RunReport, FiguresNotMeasuredAreNullNotZero) {
  cardiac::RunSummary run = heartRun();
  run.beats = cardiac::BeatTracker(120e-6, 0.01);
  for (int k = 0; k < 150; ++k) run.beats.record(0.01 * k, k < 45 ? cardiac::Phase::Systole : cardiac::Phase::Diastole,
                                                 k < 45 ? 50e-6 : 120e-6);
  run.beats.finish();
  const nlohmann::ordered_json one = runReport(scenario(), RunTiming{}, run, "d");
  EXPECT_EQ(one["beats"], 1);
  EXPECT_EQ(one["heart"]["beats_averaged"], 0);
  for (const char* key : {"edv_ml", "esv_ml", "stroke_volume_ml", "ejection_fraction", "cardiac_output_l_min",
                          "regurgitant_volume_ml", "aortic_net_forward_ml"})
    EXPECT_TRUE(one["heart"][key].is_null()) << key << " = " << one["heart"][key];
  EXPECT_TRUE(one["cavity"]["ejection_fraction"].is_number()) << "one beat was seen: its EF is measured";

  run.beats = cardiac::BeatTracker(120e-6, 0.01);
  const nlohmann::ordered_json none = runReport(scenario(), RunTiming{}, run, "d");
  EXPECT_TRUE(none["cavity"]["ejection_fraction"].is_null());
  const std::string line = runSummaryLine(scenario(), RunTiming{}, run, "d");
  EXPECT_NE(line.find("EF n/a"), std::string::npos) << line;
  EXPECT_EQ(line.find("stroke volume"), std::string::npos) << line;
}

}  // namespace
}  // namespace hs::io

namespace hs::io {
namespace {

// The E-wave vortex: every beat listed; the means over the complete beats after the first two
// in which a ring was found (beat 3 at 0.2 and beat 5 at 0.3; beat 4 found none).
TEST(RunReport, EVortexMeansTheFoundCompleteBeatsAfterTheSecond) {
  cardiac::FillingVortex vortex;
  const double positions[] = {0.9, 0.8, 0.2, -1, 0.3};
  vortex.step(false, 0);
  for (const double p : positions) {
    vortex.step(true, 1.0);
    cardiac::EVortexView view;
    view.sample.found = p >= 0;
    view.sample.position = p;
    view.sample.circulation = p >= 0 ? 10 * p : 0;
    vortex.keep(view);
    vortex.step(false, 0);
  }
  cardiac::RunSummary run = heartRun();
  run.fillingVortex = vortex;
  const nlohmann::ordered_json heart = runReport(scenario(), RunTiming{}, run, "d")["heart"];
  EXPECT_NEAR(heart["e_vortex_position"].get<double>(), 0.25, 1e-12);
  EXPECT_NEAR(heart["e_vortex_circulation_m2_s"].get<double>(), 2.5, 1e-12);
  ASSERT_EQ(heart["e_vortex_beats"].size(), 5u);
  EXPECT_TRUE(heart["e_vortex_beats"][3]["position"].is_null());
  EXPECT_EQ(heart["e_vortex_beats"][4]["beat"], 5);
  // Two beats only: nothing after the first two, null rather than 0.
  cardiac::FillingVortex two;
  two.step(false, 0);
  for (int k = 0; k < 2; ++k) two.step(true, 1.0), two.keep(cardiac::EVortexView{}), two.step(false, 0);
  run.fillingVortex = two;
  EXPECT_TRUE(runReport(scenario(), RunTiming{}, run, "d")["heart"]["e_vortex_position"].is_null());
}

}  // namespace
}  // namespace hs::io
