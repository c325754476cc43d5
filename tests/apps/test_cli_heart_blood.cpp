// `heartsim run` with heart and blood: the thesis's four experiments (Table 5.5) run their
// 400 steps with nothing lost and no particle left inside the wall, report the flow columns
// and the pump figures, and a bad blood start is a one-line error.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <algorithm>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.h"

namespace {

using hs::testing::CliResult;
using hs::testing::csvColumn;
using hs::testing::readFile;
using hs::testing::runHeartsim;
using hs::testing::scratchDir;

class PaperScenario : public ::testing::TestWithParam<const char*> {};

TEST_P(PaperScenario, RunsTwoSecondsWithNothingLostAndNothingInsideTheWall) {
  const std::string name = GetParam();
  const auto dir = scratchDir("paper_" + name);
  const CliResult r = runHeartsim("run " + name + " --threads 2 --json --out out", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("steps").get<int>(), 400);  // 2 s at dt = 5 ms, as in the thesis
  const auto& b = j.at("blood");
  EXPECT_EQ(b.at("particles").get<int>(), 1000);
  EXPECT_EQ(b.at("lost").get<int>(), 0);
  EXPECT_EQ(b.at("inside_wall").get<int>(), 0);
  const auto& h = j.at("heart");
  for (const char* key : {"beats", "edv_ml", "esv_ml", "stroke_volume_ml", "ejection_fraction",
                          "cardiac_output_l_min", "regurgitant_volume_ml"})
    EXPECT_TRUE(h.contains(key)) << key;
  const bool beating = name.find("beating") != std::string::npos;
  EXPECT_EQ(h.at("beats").get<int>() > 0, beating);
  // Without a beat nothing was measured: null, not 0.
  if (!beating) {
    EXPECT_TRUE(h.at("ejection_fraction").is_null()) << h.at("ejection_fraction");
  }
  const double ef = h.at("ejection_fraction").is_null() ? NAN : h.at("ejection_fraction").get<double>();
  // Every step's particles are accounted for, region by region.
  std::istringstream csv(readFile(dir / "out" / "metrics.csv"));
  std::string header, row;
  std::getline(csv, header);
  for (const char* column : {"mitral_open", "aortic_open", "particles_lv", "mitral_forward_ml",
                             "aortic_backward_ml", "pressure_lv_pa"})
    EXPECT_NE(header.find(column), std::string::npos) << column;
  int rows = 0;
  while (std::getline(csv, row)) ++rows;
  EXPECT_EQ(rows, 400);
  std::printf("%s: wall %.2f s for 400 steps, EF %.3f, inside_wall %d, lost %d\n", name.c_str(),
              j.at("wall_s").get<double>(), ef, b.at("inside_wall").get<int>(), b.at("lost").get<int>());
}

// A scenario name as a test name: paper-chamber -> paper_chamber.
std::string testName(const ::testing::TestParamInfo<const char*>& param) {
  std::string n = param.param;
  for (char& c : n)
    if (c == '-') c = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(CliHeartBlood, PaperScenario,
                         ::testing::Values("paper-vessel", "paper-vessel-beating", "paper-chamber",
                                           "paper-chamber-beating"),
                         testName);

// The physiological scenarios start: real size (a cavity of about 127 mL), 4,600 particles
// filling the cavity, the atrium and the aorta, the first systole under way after 0.2 s.
TEST(CliHeartBlood, PhysiologicalScenariosStartAtRealSize) {
  for (const std::string name : {"normal", "irregular", "inconsistent"}) {
    SCOPED_TRACE(name);
    const auto dir = scratchDir("physiological_" + name);
    const CliResult r = runHeartsim("run " + name + " --duration 0.2 --threads 2 --json --out out", dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("blood").at("particles").get<int>(), 4600);
    EXPECT_EQ(j.at("blood").at("lost").get<int>(), 0);
    EXPECT_NEAR(j.at("cavity").at("volume_rest_m3").get<double>() * 1e6, 127, 5);
    std::istringstream csv(readFile(dir / "out" / "metrics.csv"));
    std::string header, row, last;
    std::getline(csv, header);
    while (std::getline(csv, row)) last = row;
    EXPECT_NE(last.find(",systole,"), std::string::npos) << last;
  }
}

// What a rhythm costs, 4 s of each (the figures are the complete beats after the first):
// nothing lost or inside the wall, most of each stroke through the 3D aortic orifice;
// `irregular` (atrial fibrillation) beats both sooner and later than `normal`, without an A
// wave, and pumps less; `inconsistent`'s strong and weak beats differ in systolic aortic
// pressure from one beat to the next more than `normal`'s. The 10 s figures: docs/validation.md.
struct Rhythm {
  nlohmann::json heart, blood;
  std::vector<double> intervals;     // s, between the starts of complete beats
  double systolicChangeMean = 0;     // mmHg, mean |S_k - S_k-1| over complete beats after the first
};

Rhythm runRhythm(const std::string& name) {
  const auto dir = scratchDir("rhythm_" + name);
  const CliResult r = runHeartsim("run " + name + " --duration 4 --threads 2 --json --out out", dir);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  Rhythm rhythm{j.at("heart"), j.at("blood"), {}, 0};
  std::vector<double> starts, systolic;
  for (const auto& b : rhythm.heart.at("lumped_beats")) {
    starts.push_back(b.at("start_s").get<double>());
    if (b.at("complete").get<bool>() && b.at("beat").get<int>() > 1) systolic.push_back(b.at("aortic_systolic_mmhg").get<double>());
  }
  for (std::size_t k = 1; k < starts.size(); ++k) rhythm.intervals.push_back(starts[k] - starts[k - 1]);
  for (std::size_t k = 1; k < systolic.size(); ++k) rhythm.systolicChangeMean += std::abs(systolic[k] - systolic[k - 1]);
  if (systolic.size() > 1) rhythm.systolicChangeMean /= double(systolic.size() - 1);
  std::printf("%s: SV %.1f mL, 3D aortic %.1f mL, EF %.3f, CO %.2f L/min, aortic %.0f/%.0f, beat-to-beat %.2f mmHg\n",
              name.c_str(), rhythm.heart.at("stroke_volume_ml").get<double>(),
              rhythm.heart.at("aortic_net_forward_ml").get<double>(), rhythm.heart.at("ejection_fraction").get<double>(),
              rhythm.heart.at("cardiac_output_l_min").get<double>(), rhythm.heart.at("aortic_systolic_mmhg").get<double>(),
              rhythm.heart.at("aortic_diastolic_mmhg").get<double>(), rhythm.systolicChangeMean);
  return rhythm;
}

TEST(CliHeartBlood, RhythmsCostWhatPhysiologySays) {
  const Rhythm normal = runRhythm("normal"), irregular = runRhythm("irregular"), inconsistent = runRhythm("inconsistent");
  for (const Rhythm* r : {&normal, &irregular, &inconsistent}) {
    EXPECT_EQ(r->blood.at("lost").get<int>(), 0);
    EXPECT_EQ(r->blood.at("inside_wall").get<int>(), 0);
    EXPECT_GE(r->heart.at("aortic_net_forward_ml").get<double>(), 0.8 * r->heart.at("stroke_volume_ml").get<double>());
  }
  ASSERT_FALSE(normal.intervals.empty());
  const double beat = normal.intervals.front();
  EXPECT_NEAR(beat, 60.0 / 72, 0.002);
  ASSERT_GE(irregular.intervals.size(), 2u);
  EXPECT_LT(*std::min_element(irregular.intervals.begin(), irregular.intervals.end()), beat - 0.05);
  EXPECT_GT(*std::max_element(irregular.intervals.begin(), irregular.intervals.end()), beat + 0.05);
  EXPECT_TRUE(irregular.heart.at("e_to_a").is_null()) << "atrial fibrillation has no A wave";
  EXPECT_LT(irregular.heart.at("cardiac_output_l_min").get<double>(), normal.heart.at("cardiac_output_l_min").get<double>());
  EXPECT_GT(inconsistent.systolicChangeMean, normal.systolicChangeMean + 2);
}

// Wall, blood, valves, loop and two-way coupling together give bitwise the same state for 1
// and 2 threads (the wall's share of two-way pushes is applied serially, in particle order).
TEST(CliHeartBlood, SameStateForOneAndTwoThreadsWithTwoWayCoupling) {
  std::string hashes[2];
  for (int threads = 1; threads <= 2; ++threads) {
    const auto dir = scratchDir("paper_threads_" + std::to_string(threads));
    const CliResult r = runHeartsim("run paper-chamber-beating --duration 0.5 --set circulation.two_way=true "
                                    "--set circulation.valves=pressure --json --threads " + std::to_string(threads),
                                    dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    hashes[threads - 1] = nlohmann::json::parse(r.out).at("state_hash").get<std::string>();
  }
  EXPECT_EQ(hashes[0], hashes[1]);
}

// Two-way, the blood pushes the wall: `normal` beating by its own cycle (the lumped circulation
// drives every vertex, so two-way needs it off; the held wall then keeps its mass) reports how
// much the blood's contacts moved its cavity in a step, and null one-way. The push is the
// blood's contact with the wall its constraints moved into it, so the constraints stay between
// the density solve and the contacts (with them before the blood, the blood moved the cavity by
// 0.01 mL at most in 10 s instead of 0.76).
TEST(CliHeartBlood, TwoWayTheBloodMovesTheWall) {
  nlohmann::json tissue[2];
  for (const int twoWay : {0, 1}) {
    const auto dir = scratchDir("two_way_" + std::to_string(twoWay));
    const CliResult r = runHeartsim(std::string("run normal --duration 0.3 --threads 2 --json --out out ") +
                                        "--set circulation.lumped=false --set cycle.contraction=0.0095 " +
                                        "--set circulation.two_way=" + (twoWay ? "true" : "false"),
                                    dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    tissue[twoWay] = j.at("tissue");
    EXPECT_EQ(j.at("blood").at("lost").get<int>(), 0);
  }
  EXPECT_TRUE(tissue[0].at("moved_by_blood_ml_max").is_null());
  EXPECT_TRUE(tissue[0].at("moved_by_blood_ml_mean").is_null());
  const double largest = tissue[1].at("moved_by_blood_ml_max").get<double>();
  const double mean = tissue[1].at("moved_by_blood_ml_mean").get<double>();
  std::printf("two-way: the blood moved the cavity by at most %.3f mL in a step, %.4f mL on average\n", largest, mean);
  EXPECT_GT(largest, 0.01) << "mL: the blood must move a wall it can move";
  EXPECT_LT(largest, 5.0) << "mL: a cavity of 127 mL, pushed by blood much lighter than its wall";
  EXPECT_GT(mean, 0);
  EXPECT_LE(mean, largest);
}

// The same for `normal`: the real-size heart with free slip along the wall, its last-resort
// exits and the closed loop, 0.3 s.
TEST(CliHeartBlood, NormalGivesTheSameStateForOneAndTwoThreads) {
  std::string hashes[2];
  for (int threads = 1; threads <= 2; ++threads) {
    const auto dir = scratchDir("normal_threads_" + std::to_string(threads));
    const CliResult r = runHeartsim("run normal --duration 0.3 --json --threads " + std::to_string(threads), dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    hashes[threads - 1] = nlohmann::json::parse(r.out).at("state_hash").get<std::string>();
  }
  EXPECT_EQ(hashes[0], hashes[1]);
}

// A real-size heart started from its chamber: the chamber holds fewer than the scenario's 4,600
// particles, the rest wait in the body and enter through the inflow vessel (the closed loop).
TEST(CliHeartBlood, AChamberStartKeepsEveryParticleTheChamberCannotHold) {
  const auto dir = scratchDir("chamber_start");
  const CliResult r = runHeartsim("run normal --set blood.start=chamber --duration 0.02 --threads 1 --json", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json blood = nlohmann::json::parse(r.out).at("blood");
  EXPECT_EQ(blood.at("particles").get<int>(), 4600);
  EXPECT_EQ(blood.at("lost").get<int>(), 0);
  EXPECT_EQ(blood.at("inside_wall").get<int>(), 0);
  // Without the closed loop nothing can wait: a chamber too small is refused, naming its size.
  const CliResult open = runHeartsim(
      "run normal --set circulation.lumped=false --set cycle.contraction=0.0095 --set circulation.loop=false "
      "--set blood.start=chamber",
      dir);
  EXPECT_EQ(open.exitCode, 2) << open.err;
  EXPECT_NE(open.err.find("the chamber holds"), std::string::npos) << open.err;
}

TEST(CliHeartBlood, VesselStartWithoutAHeartIsAOneLineError) {
  const auto dir = scratchDir("vessel_no_heart");
  const CliResult r =
      runHeartsim("run dam-break --set blood.start=vessel --set blood.particles=10", dir);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("blood.start"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("vessel"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(CliHeartBlood, UnknownValveModeIsAOneLineError) {
  const auto dir = scratchDir("bad_valves");
  const CliResult r = runHeartsim("run paper-chamber --set circulation.valves=sometimes", dir);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("circulation.valves"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(CliHeartBlood, UnknownWallContactIsAOneLineError) {
  const auto dir = scratchDir("bad_wall_contact");
  const CliResult r = runHeartsim("run normal --set blood.wall_contact=swept", dir);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("blood.wall_contact"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("\"continuous\", \"thesis\""), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace
