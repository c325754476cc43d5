// patient-biv-me replaying a recorded beat that moves as a left ventricle does
// (tests/support/lv_beat_frames.h) through the command line: with blood, nothing is lost; a
// recording with a frame folded through the cavity is exit 2 with one line, before the first step.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.h"
#include "io/scenario/scenario_file.h"
#include "lv_beat_frames.h"

namespace hs::testing {
namespace {

// The built-in patient-biv-me (its mesh paths made absolute) replaying `frames` from dir/beat:
// dir/recorded.toml.
void writeBivmeRecording(const std::filesystem::path& dir, const std::vector<cardiac::Surface>& frames) {
  std::string text = io::builtinScenarioText("patient-biv-me");
  for (std::size_t at = text.find("../tests/data"); at != std::string::npos; at = text.find("../tests/data"))
    text.replace(at, 13, HS_TEST_DATA_DIR);
  writeFrames(dir / "beat", frames);
  std::ofstream(dir / "recorded.toml") << text
                                       << "\n[motion]\nframes = \"beat/frame_{frame:03d}.obj\"\ncount = 25\nperiod = 0.8\n";
}

std::vector<cardiac::Surface> bivmeBeat() {
  return lvBeatFrames(io::loadScenario("patient-biv-me").patient.endocardiumSurface);
}

// A beat with blood (4,200 particles, the valves by timing, the closed loop): the wall follows
// the recording, and no blood is lost or left inside the wall while it ejects 60%.
TEST(CliRecordedLv, ARecordedVentriclePumpsBloodAndLosesNone) {
  const auto dir = scratchDir("recorded_lv_blood");
  writeBivmeRecording(dir, bivmeBeat());
  const CliResult r = runHeartsim("run recorded.toml --duration 0.8 --threads 2 --json --out out", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["blood"]["lost"], 0);
  EXPECT_EQ(j["blood"]["inside_wall"], 0);
  EXPECT_EQ(j["tissue"]["inverted_tets"], 0);
  EXPECT_LT(j["motion"]["volume_error_max"].get<double>(), 0.02);
  EXPECT_NEAR(j["motion"]["recorded_ejection_fraction"].get<double>(), 0.6, 0.005);
}

// A frame with a patch of the mid-ventricle pushed through the cavity: refused as the scenario's
// simulation is built, exit 2, one line, nothing written to stdout.
TEST(CliRecordedLv, AFoldedFrameIsExitTwoBeforeTheFirstStep) {
  const auto dir = scratchDir("recorded_lv_folded");
  writeBivmeRecording(dir, foldedFrames(bivmeBeat(), 9, 25));
  const CliResult r = runHeartsim("run recorded.toml --duration 0.8 --threads 1 --json --out out", dir);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind("heartsim: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("motion.frames: the default wall (5 mm edges) cannot follow frames "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no wall resolution (coarse, default, fine) follows it"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "metrics.csv"));
}

}  // namespace
}  // namespace hs::testing
