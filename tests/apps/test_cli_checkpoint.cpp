// Checkpoints end to end: `heartsim run --checkpoint-every` and `--resume` give the state hash,
// the summary and the checkpoint of the run without a stop, on 1 and 2 threads, for the
// physiological heart with blood, the thesis-scale chamber and the irregular rhythm (whose
// beat lengths are random); every bad checkpoint or refused resume exits 2 with one line that
// names the file and what is wrong.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "io/output/checkpoint.h"

namespace hs::testing {
namespace {

namespace fs = std::filesystem;

nlohmann::json runJson(const std::string& args, const fs::path& dir) {
  const CliResult r = runHeartsim("run " + args + " --json", dir);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return r.exitCode == 0 ? nlohmann::json::parse(r.out) : nlohmann::json{};
}

// The summary's figures that do not depend on timing or on where the files went.
nlohmann::json figures(nlohmann::json report) {
  for (const char* key : {"setup_s", "wall_s", "steps_per_s", "threads", "output_dir"}) report.erase(key);
  return report;
}

// Runs `scenario` to `end` with a checkpoint every `every` s, then resumes its first checkpoint
// to `end` on 1 and 2 threads: the same hash, figures and last checkpoint as without a stop.
void expectResumeMatches(const std::string& scenario, double every, double end, const std::string& name) {
  const fs::path dir = scratchDir(name);
  const std::string tail = " --duration " + std::to_string(end);
  const nlohmann::json whole =
      runJson(scenario + tail + " --threads 1 --checkpoint-every " + std::to_string(every) + " --out whole", dir);
  std::vector<fs::path> written;
  for (const auto& entry : fs::directory_iterator(dir / "whole"))
    if (entry.path().extension() == ".hsck") written.push_back(entry.path());
  std::sort(written.begin(), written.end());
  ASSERT_GE(written.size(), 2u);
  for (const int threads : {1, 2}) {
    SCOPED_TRACE(threads);
    const std::string out = "resumed" + std::to_string(threads);
    const nlohmann::json resumed =
        runJson("--resume whole/" + written.front().filename().string() + tail + " --threads " +
                    std::to_string(threads) + " --checkpoint-every " + std::to_string(every) + " --out " + out,
                dir);
    EXPECT_EQ(resumed["state_hash"], whole["state_hash"]);
    EXPECT_EQ(figures(resumed), figures(whole));
    EXPECT_EQ(readFile(dir / out / written.back().filename()), readFile(written.back()));
  }
}

TEST(CliCheckpoint, NormalResumedGivesTheUninterruptedRun) {
  expectResumeMatches("normal", 0.1, 0.2, "ckpt_normal");
}

TEST(CliCheckpoint, PaperChamberBeatingResumedGivesTheUninterruptedRun) {
  expectResumeMatches("paper-chamber-beating", 0.25, 0.5, "ckpt_paper");
}

// At 120 bpm the first diastole's random length is drawn before the checkpoint at 0.4 s and
// the second after it, from the generator's saved state.
TEST(CliCheckpoint, IrregularResumedGivesTheUninterruptedRun) {
  expectResumeMatches("irregular --set cycle.heart_rate_bpm=120", 0.4, 0.8, "ckpt_irregular");
}

// A small valid checkpoint (heart-only at 10 steps), and the command's one-line error on a
// copy of it changed by `spoil`.
class BadCheckpoint : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // ctest runs each test of the suite in its own process, side by side: each needs its own
    // folder (a shared one was removed and rewritten under the other, and the suite skipped).
    s_dir = scratchDir("ckpt_bad_" + std::to_string(::getpid()));
    const CliResult r = runHeartsim("run heart-only --duration 0.1 --checkpoint-every 0.05 --out made", s_dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    s_good = readFile(s_dir / "made" / "checkpoint_0000.050s.hsck");
    ASSERT_GT(s_good.size(), 100u);
  }
  static CliResult resume(const std::string& bytes, const std::string& extra = " --duration 0.1") {
    std::ofstream(s_dir / "bad.hsck", std::ios::binary) << bytes;
    return runHeartsim("run --resume bad.hsck --out resumed" + extra, s_dir);
  }
  static void expectOneLine(const CliResult& r, const std::string& words) {
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("bad.hsck"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
  }
  static inline fs::path s_dir;
  static inline std::string s_good;
};

TEST_F(BadCheckpoint, GoodOneResumes) { EXPECT_EQ(resume(s_good).exitCode, 0); }

TEST_F(BadCheckpoint, ForeignFileHasBadMagic) { expectOneLine(resume("{\"not\": \"a checkpoint\"}\n"), "bad magic"); }

TEST_F(BadCheckpoint, OtherVersionIsNamed) {
  std::string bytes = s_good;
  bytes[8] = 9;
  expectOneLine(resume(bytes), "format version 9; this heartsim reads version " + std::to_string(hs::io::kCheckpointVersion));
}

TEST_F(BadCheckpoint, TruncatedFileSaysAtWhichByte) {
  expectOneLine(resume(s_good.substr(0, 1000)), "truncated at byte 1000");
}

TEST_F(BadCheckpoint, CorruptByteFailsTheChecksum) {
  std::string bytes = s_good;
  bytes[bytes.size() - 100] ^= 0x01;
  expectOneLine(resume(bytes), "checksum mismatch");
}

TEST_F(BadCheckpoint, AnotherScenarioIsRefused) {
  std::ofstream(s_dir / "bad.hsck", std::ios::binary) << s_good;
  expectOneLine(runHeartsim("run normal --resume bad.hsck --duration 0.1 --out resumed", s_dir), "scenario mismatch");
}

TEST_F(BadCheckpoint, SetThatChangesPhysicsIsRefused) {
  expectOneLine(resume(s_good, " --duration 0.1 --set tissue.damping=3"), "scenario mismatch: --set changes the simulation (tissue.damping");
}

TEST_F(BadCheckpoint, DurationBeforeTheCheckpointIsRefused) {
  expectOneLine(resume(s_good, " --duration 0.01"), "ends before the checkpoint");
}

TEST_F(BadCheckpoint, MissingFileIsNamed) {
  const CliResult r = runHeartsim("run --resume nowhere.hsck --duration 0.1 --out resumed", s_dir);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("nowhere.hsck: cannot open the checkpoint"), std::string::npos) << r.err;
}

TEST_F(BadCheckpoint, RunWithoutScenarioOrResumeIsRefused) {
  const CliResult r = runHeartsim("run --duration 0.1", s_dir);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("a scenario is required (or --resume FILE)"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace hs::testing
