// Bad input through the command line: exit code 2 and one line on stderr naming the file and
// key; nothing on stdout.
#include <gtest/gtest.h>

#include "cli_runner.h"

namespace hs::testing {
namespace {

int lineCount(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

void expectBadInput(const CliResult& r, const std::vector<std::string>& mustMention) {
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  for (const std::string& word : mustMention) EXPECT_NE(r.err.find(word), std::string::npos) << "missing '" << word << "' in: " << r.err;
}

void writeFile(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

TEST(CliErrors, MissingScenarioFile) {
  const auto dir = scratchDir("missing");
  expectBadInput(runHeartsim("run no-such-lesson.toml --json", dir), {"no-such-lesson.toml"});
}

// run, render and bench take the viewer's words for the blood's resolution, and only those.
TEST(CliErrors, AResolutionThatIsNotALevelIsNamed) {
  const auto dir = scratchDir("resolution");
  for (const char* command : {"run heart-only --json", "render heart-only", "bench --case normal --json"})
    expectBadInput(runHeartsim(std::string(command) + " --resolution huge", dir),
                   {"--resolution", "'huge'", "coarse, medium, fine", "finest"});
  // A resumed run keeps the checkpoint's blood: the switch is refused, not ignored.
  expectBadInput(runHeartsim("run --resume any.ckpt --resolution coarse", dir), {"--resolution", "checkpoint"});
}

TEST(CliErrors, MalformedTomlNamesFileAndLine) {
  const auto dir = scratchDir("malformed");
  writeFile(dir / "broken.toml", "[simulation]\ndt = 0.005\nduration = = 2\n");
  expectBadInput(runHeartsim("run broken.toml --json", dir), {"broken.toml", ":3"});
}

TEST(CliErrors, UnknownKeyNamesFileAndKey) {
  const auto dir = scratchDir("unknown");
  writeFile(dir / "typo.toml", "[cycle]\nbeat = 2\n");
  expectBadInput(runHeartsim("run typo.toml --json", dir), {"typo.toml", "cycle.beat"});
}

// A quoted string with no closing quote is an error, not a name with a quote in it.
TEST(CliErrors, AnUnterminatedStringInSetIsNamed) {
  const auto dir = scratchDir("unterminated");
  expectBadInput(runHeartsim("run heart-only --set scenario.name=\\\"abc --json", dir),
                 {"--set", "scenario.name", "closing quote"});
}

TEST(CliErrors, NegativeDtFromFileAndFromSet) {
  const auto dir = scratchDir("negative");
  writeFile(dir / "neg.toml", "[simulation]\ndt = -0.005\n");
  expectBadInput(runHeartsim("run neg.toml --json", dir), {"neg.toml", "simulation.dt"});
  expectBadInput(runHeartsim("run heart-only --set simulation.dt=-0.01 --json", dir), {"--set", "simulation.dt"});
}

TEST(CliErrors, NanDt) {
  const auto dir = scratchDir("nan");
  writeFile(dir / "nan.toml", "[simulation]\ndt = nan\n");
  expectBadInput(runHeartsim("run nan.toml --json", dir), {"nan.toml", "simulation.dt"});
}

TEST(CliErrors, BadDurationOption) {
  const auto dir = scratchDir("duration");
  expectBadInput(runHeartsim("run heart-only --duration -1 --json", dir), {"--duration"});
}

TEST(CliErrors, UnknownBenchCase) {
  const auto dir = scratchDir("bench");
  expectBadInput(runHeartsim("bench --case no-such-case --json", dir), {"no-such-case"});
}

TEST(CliErrors, BenchOfABadOrMissingScenarioFile) {
  const auto dir = scratchDir("bench_bad_file");
  writeFile(dir / "bad.toml", "[blood]\nparticles = \"many\"\n");
  expectBadInput(runHeartsim("bench --scenario bad.toml --seconds 0.1", dir), {"bad.toml", "blood.particles"});
  expectBadInput(runHeartsim("bench --scenario nowhere.toml --seconds 0.1", dir), {"nowhere.toml"});
}

TEST(CliErrors, OutOfRangeBeatingVertex) {
  const auto dir = scratchDir("vertex");
  expectBadInput(runHeartsim("run heart-only --set 'cycle.vertices=[999999]' --json", dir), {"cycle.vertices", "999999"});
}

TEST(CliErrors, GeometryThatLeavesNoValidMeshIsBadInput) {
  const auto dir = scratchDir("geometry");
  expectBadInput(runHeartsim("run heart-only --set model.endo_long_axis=0.31 --json", dir), {"model"});
  expectBadInput(runHeartsim("run heart-only --set model.wall_thickness=10 --json", dir), {"model"});
}

TEST(CliErrors, TooManyStepsIsBadInput) {
  const auto dir = scratchDir("steps");
  expectBadInput(runHeartsim("run heart-only --set simulation.dt=1e-6 --duration 36000 --json", dir),
                 {"simulation.duration", "steps"});
}

TEST(CliErrors, BloodInAChamberNeedsAHeart) {
  const auto dir = scratchDir("blood");
  expectBadInput(runHeartsim("run fluid-at-rest --set blood.start=chamber --json", dir), {"blood.start", "heart"});
}

// A wall pushed as far each step as the reader allows (cycle.beating_displace), with the least
// stiffness and solving each allows, folds at step 4: exit 3, one line saying when and where. (A
// single key at its extreme runs, test_scenario_extremes.cpp; these four together do not.)
TEST(CliErrors, InvalidSimulationIsExitThreeWithWhenAndWhere) {
  const auto dir = scratchDir("invalid");
  const CliResult r = runHeartsim("run heart-only --set cycle.beating_displace=0.14 --set tissue.volume_stiffness=0.25 "
                                  "--set simulation.iterations=1 --set simulation.volume_passes=0 --json",
                                  dir);
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  for (const char* word : {"step 4", "inverted", "tet ", "x = "})
    EXPECT_NE(r.err.find(word), std::string::npos) << "missing '" << word << "' in: " << r.err;
  // The summary is still written, with the reason and where.
  const std::string summary = readFile(dir / "results" / "heart-only" / "summary.json");
  for (const char* word : {"\"failure\"", "inverted", "\"step\": 4", "\"time_s\""})
    EXPECT_NE(summary.find(word), std::string::npos) << "missing '" << word << "' in: " << summary;
}

// A word where a command or a validation is expected names itself and the valid ones.
TEST(CliErrors, UnknownOrMissingSubcommandNamesTheValidOnes) {
  const auto dir = scratchDir("subcommands");
  expectBadInput(runHeartsim("frobnicate", dir), {"unknown command 'frobnicate'", "run, render, view, bench, validate"});
  expectBadInput(runHeartsim("validate foo", dir), {"unknown validation 'foo'", "dam-break"});
  expectBadInput(runHeartsim("validate", dir), {"missing validation", "dam-break"});
  expectBadInput(runHeartsim("", dir), {"missing command", "run, render, view, bench, validate"});
  expectBadInput(runHeartsim("bench --case nonsense", dir), {"nonsense", "tissue-lv"});
}

// --json on a stdout that cannot take it (a full disk): exit 1 and a line saying so, for every
// command that prints JSON.
TEST(CliErrors, JsonOnAFullStdoutIsAWriteFailure) {
  const auto dir = scratchDir("full_stdout");
  for (const std::string command : {"run heart-only --duration 0.01 --out o --json", "bench --case tissue-lv --seconds 0.1 --json"}) {
    const std::string line = "cd '" + dir.string() + "' && OMP_WAIT_POLICY=PASSIVE '" + HS_HEARTSIM_EXE + "' " + command +
                             " >/dev/full 2>err.txt";
    const int status = std::system(line.c_str());
    ASSERT_TRUE(WIFEXITED(status)) << command;
    EXPECT_EQ(WEXITSTATUS(status), 1) << command;
    EXPECT_NE(readFile(dir / "err.txt").find("stdout: cannot write the JSON report"), std::string::npos) << command;
  }
}

TEST(CliErrors, BeatingRegionThatSelectsNothingIsBadInput) {
  const auto dir = scratchDir("empty_region");
  expectBadInput(runHeartsim("run heart-only --set 'cycle.sphere.centre=[100,100,100]' --set cycle.sphere.radius=0.1", dir),
                 {"heart-only", "cycle.sphere", "selects no wall vertex"});
}

// Switches that the lumped circulation would silently ignore are refused, naming why.
TEST(CliErrors, SwitchesTheLumpedCirculationCannotHonourAreBadInput) {
  const auto dir = scratchDir("lumped_switches");
  expectBadInput(runHeartsim("run normal --set circulation.valves=timing", dir),
                 {"normal", "circulation.valves", "lumped circulation's pressures", "expected \"pressure\", got \"timing\""});
  expectBadInput(runHeartsim("run irregular --set circulation.valves=open", dir), {"circulation.valves", "got \"open\""});
  expectBadInput(runHeartsim("run normal --set circulation.two_way=true", dir),
                 {"normal", "circulation.two_way", "drives every vertex", "circulation.lumped = false"});
  // The vessels' ends pass the lumped flows: blood leaving the aorta must come back.
  expectBadInput(runHeartsim("run normal --set circulation.loop=false", dir),
                 {"normal", "circulation.loop", "needs the closed loop", "expected true"});
}

// The held wall (cycle.base_held) returns to rest only along the relaxation: without one it would
// jump there.
TEST(CliErrors, AHeldWallWithoutARelaxationIsBadInput) {
  const auto dir = scratchDir("held_relaxation");
  expectBadInput(runHeartsim("run patient-biv-me --set cycle.relaxation_fraction=0", dir),
                 {"patient-biv-me", "cycle.relaxation_fraction", "got 0", "expected more than 0 with cycle.base_held"});
}

// Without the lumped circulation the wall travels cycle.contraction per systole: the default
// 0.3 m on a 3 cm heart folds it, so it is refused before any work, naming the limit.
TEST(CliErrors, AContractionThatFoldsTheWallIsBadInput) {
  const auto dir = scratchDir("contraction");
  expectBadInput(runHeartsim("run normal --set circulation.lumped=false", dir),
                 {"normal", "cycle.contraction", "0.3 m folds this wall", "at most 0.0104 m", "a third of the cavity"});
  expectBadInput(runHeartsim("run normal --set circulation.lumped=false --set cycle.contraction=0.011", dir),
                 {"cycle.contraction", "0.011 m"});
}

// Blood leaving the domain stops `run` with exit 3, when and where, and the summary; a scenario
// that expects the loss says so (blood.loss_allowed).
TEST(CliErrors, LostBloodIsExitThreeUnlessTheScenarioAllowsIt) {
  const auto dir = scratchDir("lost_blood");
  // A strong upward gravity (the most the reader takes, about 10 g) throws the heart's blood out
  // through its vessels' open ends.
  const std::string throwOut = "run normal --set circulation.lumped=false --set cycle.contraction=0.0095 "
                               "--set circulation.loop=false --set blood.particles=3000 "
                               "--set 'simulation.gravity=[0, 100, 0]' --duration 0.05";
  const CliResult r = runHeartsim(throwOut + " --json", dir);
  EXPECT_EQ(r.exitCode, 3) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  for (const char* word : {"simulation became invalid at step", "blood particles lost outside the domain", "first at x = ",
                           "blood.loss_allowed = 0"})
    EXPECT_NE(r.err.find(word), std::string::npos) << "missing '" << word << "' in: " << r.err;
  EXPECT_NE(readFile(dir / "results" / "normal" / "summary.json").find("lost outside the domain"), std::string::npos);
  const CliResult allowed = runHeartsim(throwOut + " --set blood.loss_allowed=3000 --out ok", dir);
  EXPECT_EQ(allowed.exitCode, 0) << allowed.err;
}

// A start block outside the heart's surroundings is refused before any work.
TEST(CliErrors, AStartBlockOutsideTheDomainIsBadInput) {
  const auto dir = scratchDir("block_outside");
  expectBadInput(runHeartsim("run normal --set blood.start=block", dir),
                 {"normal", "blood.block_min, blood.block_max", "[-0.8, -2.4, -0.8]..[0.8, -0.8, 0.8] m",
                  "reaches outside the domain"});
}

// A documented limit is a value that works: the lumped circulation's keys at their upper ends
// (kept in float SI, checked again in clinical units) run.
TEST(CliErrors, TheLumpedKeysAcceptTheirDocumentedLimits) {
  const auto dir = scratchDir("lumped_limits");
  for (const char* set : {"circulation.contractility_mmhg_per_ml=20", "circulation.peripheral_resistance_mmhg_s_per_ml=20",
                          "circulation.arterial_compliance_ml_per_mmhg=20", "circulation.characteristic_impedance_mmhg_s_per_ml=1",
                          "circulation.atrial_pressure_mmhg=100", "circulation.venous_pressure_mmhg=30", "circulation.lv_v0_ml=200",
                          "circulation.lv_stiffness_mmhg=20", "circulation.lv_stiffness_per_ml=0.05"}) {
    const CliResult r = runHeartsim(std::string("run normal --duration 0.001 --threads 1 --out o --set ") + set, dir);
    EXPECT_EQ(r.exitCode, 0) << set << ": " << r.err;
  }
}

// A particle as wide as the cavity (radius 3 cm in a 3.2 cm heart) is refused, naming the limit.
TEST(CliErrors, ABloodRadiusBeyondItsSpacingIsBadInput) {
  const auto dir = scratchDir("blood_radius");
  expectBadInput(runHeartsim("run normal --set blood.radius=0.03", dir),
                 {"--set blood.radius=0.03", "blood.radius: must not exceed blood.spacing (0.0036 m)", "got 0.03 m"});
}

}  // namespace
}  // namespace hs::testing
