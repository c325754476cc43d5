// metrics.csv's `phase` is the heart's, read from the valves (cardiac/circulation/heart_phase.h),
// on every step of three beats of `normal`, `irregular`, `aortic-stenosis` and
// `mitral-regurgitation` (the lumped heart alone: the phase comes from its valves, the blood's
// particles play no part in it): ejection exactly while the aortic valve is open, filling whenever
// only the mitral valve is, the isovolumic phases with both shut, the four in the textbook's
// order, and the isovolumic contraction as long as the summary's (the same rule). In mitral
// regurgitation the isovolumic phases keep their names but lose volume into the atrium.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.h"

namespace {

using hs::testing::CliResult;
using hs::testing::runHeartsim;
using hs::testing::scratchDir;

struct Csv {
  std::map<std::string, std::size_t> column;
  std::vector<std::vector<std::string>> rows;
  const std::string& at(std::size_t row, const std::string& name) const { return rows.at(row).at(column.at(name)); }
  double number(std::size_t row, const std::string& name) const { return std::stod(at(row, name)); }
};

Csv readCsv(const std::filesystem::path& file) {
  Csv csv;
  std::ifstream in(file);
  std::string line;
  auto split = [](const std::string& l) {
    std::vector<std::string> out;
    std::stringstream s(l);
    for (std::string f; std::getline(s, f, ',');) out.push_back(f);
    if (!l.empty() && l.back() == ',') out.emplace_back();  // an empty last field (heart_sound)
    return out;
  };
  std::getline(in, line);
  const auto names = split(line);
  for (std::size_t i = 0; i < names.size(); ++i) csv.column[names[i]] = i;
  while (std::getline(in, line)) csv.rows.push_back(split(line));
  return csv;
}

struct PhaseRuns {
  std::vector<std::size_t> contraction, relaxation;  // steps of each isovolumic run, in order
};

// Every step against the valves, the order of the phases; returns the isovolumic runs.
PhaseRuns checkPhases(const Csv& csv) {
  const std::map<std::string, std::string> next = {{"isovolumic_contraction", "ejection"},
                                                   {"ejection", "isovolumic_relaxation"},
                                                   {"isovolumic_relaxation", "filling"},
                                                   {"filling", "isovolumic_contraction"}};
  PhaseRuns runs;
  std::string previous;
  std::size_t run = 0;
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    const std::string& phase = csv.at(i, "phase");
    const bool mitral = csv.at(i, "lumped_mitral_open") == "1", aortic = csv.at(i, "lumped_aortic_open") == "1";
    SCOPED_TRACE("step " + csv.at(i, "step") + " phase " + phase);
    EXPECT_TRUE(next.count(phase));
    if (!next.count(phase)) return runs;
    EXPECT_EQ(phase == "ejection", aortic) << "ejection exactly while the aortic valve is open";
    if (mitral && !aortic) {
      EXPECT_EQ(phase, "filling");
    }
    if (phase == "isovolumic_contraction" || phase == "isovolumic_relaxation") {
      EXPECT_FALSE(mitral || aortic);
    }
    if (!previous.empty() && phase != previous) {
      EXPECT_EQ(phase, next.at(previous)) << "after " << previous;
      if (previous == "isovolumic_contraction") runs.contraction.push_back(run);
      if (previous == "isovolumic_relaxation") runs.relaxation.push_back(run);
      run = 0;
    }
    ++run;
    previous = phase;
  }
  return runs;
}

TEST(CliHeartPhase, ThePhaseFollowsTheValvesOnEveryStepOfThreeBeats) {
  const auto dir = scratchDir("heart_phase");
  for (const std::string scenario : {"normal", "irregular", "aortic-stenosis", "mitral-regurgitation"}) {
    SCOPED_TRACE(scenario);
    const CliResult r = runHeartsim(
        "run " + scenario + " --set blood.enabled=false --duration 2.6 --threads 1 --json --out " + scenario, dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Csv csv = readCsv(dir / scenario / "metrics.csv");
    ASSERT_GE(csv.rows.size(), 2500u);
    ASSERT_TRUE(csv.column.count("wall_phase")) << "the wall's own clock keeps a column of its own";
    const PhaseRuns runs = checkPhases(csv);
    ASSERT_GE(runs.contraction.size(), 3u) << "three beats";
    ASSERT_GE(runs.relaxation.size(), 3u);
    // The summary averages the complete beats after the first; each beat's isovolumic
    // contraction is the run that begins it (the run at t = 0 begins the first).
    const nlohmann::json run = nlohmann::json::parse(r.out);
    const nlohmann::json& heart = run.at("heart");
    const double stepMs = 1e3 * run.at("dt_s").get<double>();
    const int averaged = heart.at("beats_averaged").get<int>();
    ASSERT_GE(averaged, 1);
    ASSERT_GE(int(runs.contraction.size()), averaged + 1);
    double sum = 0;
    for (int b = 1; b <= averaged; ++b) sum += double(runs.contraction[std::size_t(b)]);
    EXPECT_NEAR(sum / averaged * stepMs, heart.at("isovolumic_contraction_ms").get<double>(), 0.51 * stepMs)
        << "one rule for the phase and the summary";
    if (scenario == "mitral-regurgitation") {
      // Both forward valves shut, yet blood leaves backward through the mitral valve: the
      // "isovolumic" contraction loses volume.
      double leaked = 0;
      for (std::size_t i = 0; i < csv.rows.size(); ++i)
        if (csv.at(i, "phase") == "isovolumic_contraction")
          leaked -= std::min(0.0, csv.number(i, "lumped_mitral_flow_ml_s")) * 1e-3;
      EXPECT_GT(leaked, 1.0) << "mL back into the atrium in the isovolumic contractions";
    }
  }
}

// The ECG (motion/ecg.h) and the heart sounds in metrics.csv: in `normal` each R peak comes
// before the mitral valve's closure (S1, the isovolumic contraction's start) and each T wave ends
// near the aortic valve's closure (S2); a P wave before every QRS. In `irregular` (atrial
// fibrillation) no P wave, and the RR intervals vary.
struct EcgBeats {
  std::vector<double> s1, s2;                 // s, the rows whose heart_sound is S1 / S2
  std::vector<double> rPeak, tEnd, pMax;      // per beat with both neighbours inside the run
};

EcgBeats ecgBeats(const Csv& csv) {
  EcgBeats e;
  std::vector<double> t, v;
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    t.push_back(csv.number(i, "time_s"));
    v.push_back(csv.number(i, "ecg_mv"));
    if (csv.at(i, "heart_sound") == "S1") e.s1.push_back(t.back());
    if (csv.at(i, "heart_sound") == "S2") e.s2.push_back(t.back());
  }
  auto argmax = [&](double from, double to) {
    std::size_t best = 0;
    bool any = false;
    for (std::size_t i = 0; i < t.size(); ++i)
      if (t[i] >= from && t[i] <= to && (!any || v[i] > v[best])) best = i, any = true;
    return best;
  };
  for (std::size_t b = 0; b < e.s1.size(); ++b) {
    const double mc = e.s1[b];
    if (mc < 0.35) continue;  // the first beat has no P wave recorded before it
    e.rPeak.push_back(t[argmax(mc - 0.15, mc + 0.05)]);
    e.pMax.push_back(v[argmax(mc - 0.30, mc - 0.09)]);
    const auto ac = std::find_if(e.s2.begin(), e.s2.end(), [&](double x) { return x > mc; });
    if (ac == e.s2.end()) continue;
    const std::size_t peak = argmax(mc + 0.12, *ac + 0.05);
    std::size_t end = peak;
    while (end + 1 < v.size() && v[end] > 0.1 * v[peak]) ++end;
    e.tEnd.push_back(t[end] - *ac);
  }
  return e;
}

TEST(CliHeartPhase, TheEcgPlacesItsWavesByTheValvesAndFibrillationHasNoPWave) {
  const auto dir = scratchDir("heart_ecg");
  EcgBeats beats[2];
  const std::string names[2] = {"normal", "irregular"};
  for (int k = 0; k < 2; ++k) {
    const CliResult r = runHeartsim(
        "run " + names[k] + " --set blood.enabled=false --duration 6 --threads 1 --out " + names[k], dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    beats[k] = ecgBeats(readCsv(dir / names[k] / "metrics.csv"));
  }
  const EcgBeats& normal = beats[0];
  ASSERT_GE(normal.rPeak.size(), 5u);
  ASSERT_GE(normal.tEnd.size(), 5u);
  EXPECT_NEAR(double(normal.s1.size()), double(normal.s2.size()), 1.0) << "one S1 and one S2 a beat";
  for (std::size_t b = 0; b < normal.rPeak.size(); ++b) {
    const double mc = *std::find_if(normal.s1.begin(), normal.s1.end(), [&](double x) { return x >= normal.rPeak[b]; });
    EXPECT_LT(normal.rPeak[b], mc) << "beat " << b << ": the R peak before the mitral valve's closure";
    EXPECT_GT(normal.pMax[b], 0.12) << "beat " << b << ": a P wave";
  }
  for (const double offset : normal.tEnd) EXPECT_LT(std::abs(offset), 0.04) << "the T wave ends at aortic closure";
  const EcgBeats& af = beats[1];
  ASSERT_GE(af.pMax.size(), 4u);
  for (const double p : af.pMax) EXPECT_LT(p, 0.1) << "no P wave in atrial fibrillation";
  auto variation = [](const std::vector<double>& s1) {
    std::vector<double> rr;
    for (std::size_t i = 1; i < s1.size(); ++i) rr.push_back(s1[i] - s1[i - 1]);
    double mean = 0, var = 0;
    for (const double x : rr) mean += x / double(rr.size());
    for (const double x : rr) var += (x - mean) * (x - mean) / double(rr.size());
    return std::sqrt(var) / mean;
  };
  EXPECT_LT(variation(normal.s1), 0.01) << "a regular rhythm";
  EXPECT_GT(variation(af.s1), 0.05) << "irregular RR intervals";
}

}  // namespace
