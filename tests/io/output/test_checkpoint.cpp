// Checkpoint files: the format round-trips (write, read, write gives the same bytes), a
// simulation's state taken, loaded into a new simulation and taken again is byte-identical
// (a field saved but not loaded shows here), the scenario comes back exactly (clinical units
// included), and each kind of bad file gets its one-line error naming the file.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "cardiac/heart_simulation.h"
#include "cardiac/run_monitor.h"
#include "io/output/checkpoint.h"
#include "io/scenario/scenario_file.h"
#include "thrown_message.h"

namespace hs::io {
namespace {

using testing::thrownMessage;

// `normal` (heart, blood, lumped circulation, vessel ends, the loop) after a few steps.
struct SteppedRun {
  cardiac::HeartSimulation sim;
  cardiac::RunMonitor monitor;
  explicit SteppedRun(const cardiac::Scenario& scenario, int steps = 12)
      : sim(scenario, 1), monitor(sim, everyColumn()) {
    for (int k = 0; k < steps; ++k) {
      sim.step();
      monitor.observe();
    }
  }
  static cardiac::MonitorSettings everyColumn() {
    cardiac::MonitorSettings s;
    s.everyColumn = true;
    s.endTime = 1;
    return s;
  }
};

const std::vector<std::uint8_t>& normalCheckpointBytes() {
  static const std::vector<std::uint8_t> bytes = [] {
    const SteppedRun run(loadScenario("normal"));
    return encodeCheckpoint(captureCheckpoint(run.sim, &run.monitor));
  }();
  return bytes;
}

TEST(Checkpoint, FormatRoundTripsByteForByte) {
  const std::vector<std::uint8_t>& bytes = normalCheckpointBytes();
  const Checkpoint read = decodeCheckpoint(bytes, "a.hsck");
  EXPECT_EQ(read.step, 12);
  EXPECT_FALSE(read.monitor.empty());
  EXPECT_EQ(encodeCheckpoint(read), bytes);
}

TEST(Checkpoint, StateTakenLoadedAndTakenAgainIsIdentical) {
  for (const char* name : {"normal", "paper-chamber-beating", "irregular", "dam-break"}) {
    SCOPED_TRACE(name);
    const SteppedRun run(loadScenario(name));
    const Checkpoint taken = captureCheckpoint(run.sim, &run.monitor);
    const cardiac::Scenario scenario = checkpointScenario(taken, "a.hsck");
    cardiac::HeartSimulation sim(scenario, 2);
    cardiac::RunMonitor monitor(sim, SteppedRun::everyColumn());
    restoreSimulation(taken, sim, "a.hsck");
    restoreMonitor(taken, monitor, "a.hsck");
    const Checkpoint again = captureCheckpoint(sim, &monitor);
    EXPECT_EQ(again.simulation, taken.simulation);
    EXPECT_EQ(again.monitor, taken.monitor);
    EXPECT_EQ(again.scenarioValues, taken.scenarioValues);
    EXPECT_EQ(again.scenarioToml, taken.scenarioToml);
    EXPECT_EQ(pbd::stateHash(sim.particles()), pbd::stateHash(run.sim.particles()));
  }
}

TEST(Checkpoint, ScenarioComesBackExactlyWhereItsTextRounds) {
  const cardiac::Scenario normal = loadScenario("normal");
  // The TOML text alone gives the clinical-unit parameters back only to its printed digits.
  const cardiac::Scenario fromText = parseScenario(scenarioToToml(normal), "text");
  EXPECT_NE(firstDifferentKey(normal, fromText, {}, {}), "");
  const SteppedRun run(normal, 0);
  const cardiac::Scenario exact = checkpointScenario(captureCheckpoint(run.sim, nullptr), "a.hsck");
  EXPECT_EQ(firstDifferentKey(normal, exact, {}, {}), "");
}

TEST(Checkpoint, ForeignFileHasBadMagic) {
  const std::string png = "\x89PNG\r\n\x1a\n rest of an image";
  const std::vector<std::uint8_t> bytes(png.begin(), png.end());
  EXPECT_EQ(thrownMessage<CheckpointError>([&] { decodeCheckpoint(bytes, "x.png"); }),
            "x.png: bad magic: not a heartsim checkpoint (.hsck)");
}

TEST(Checkpoint, OtherVersionIsNamed) {
  std::vector<std::uint8_t> bytes = normalCheckpointBytes();
  const std::uint8_t other = kCheckpointVersion + 1;  // a version this heartsim does not read
  bytes[8] = other;
  EXPECT_EQ(thrownMessage<CheckpointError>([&] { decodeCheckpoint(bytes, "a.hsck"); }),
            "a.hsck: format version " + std::to_string(other) + "; this heartsim reads version " +
                std::to_string(kCheckpointVersion));
}

TEST(Checkpoint, OtherPrecisionIsNamed) {
  std::vector<std::uint8_t> bytes = normalCheckpointBytes();
  bytes[12] = sizeof(pbd::Real) == 4 ? 8 : 4;
  EXPECT_NE(thrownMessage<CheckpointError>([&] { decodeCheckpoint(bytes, "a.hsck"); }).find("-byte reals; this heartsim build uses"),
            std::string::npos);
}

TEST(Checkpoint, TruncatedFileSaysWhereItEnds) {
  std::vector<std::uint8_t> bytes = normalCheckpointBytes();
  for (const std::size_t size : {std::size_t(5), std::size_t(12), bytes.size() / 2, bytes.size() - 3}) {
    SCOPED_TRACE(size);
    const std::vector<std::uint8_t> cut(bytes.begin(), bytes.begin() + std::ptrdiff_t(size));
    const std::string message = thrownMessage<CheckpointError>([&] { decodeCheckpoint(cut, "a.hsck"); });
    EXPECT_EQ(message.rfind("a.hsck: truncated at byte " + std::to_string(size) + " (", 0), 0u) << message;
  }
}

TEST(Checkpoint, FlippedByteFailsTheChecksum) {
  std::vector<std::uint8_t> bytes = normalCheckpointBytes();
  bytes[bytes.size() / 2] ^= 0x10;
  const std::string message = thrownMessage<CheckpointError>([&] { decodeCheckpoint(bytes, "a.hsck"); });
  EXPECT_EQ(message.rfind("a.hsck: checksum mismatch (stored ", 0), 0u) << message;
  EXPECT_NE(message.find("the file is corrupt"), std::string::npos);
}

TEST(Checkpoint, StateOfAnotherScenarioDoesNotFit) {
  const Checkpoint normal = decodeCheckpoint(normalCheckpointBytes(), "a.hsck");
  cardiac::HeartSimulation heartOnly(loadScenario("heart-only"), 1);
  const std::string message = thrownMessage<CheckpointError>([&] { restoreSimulation(normal, heartOnly, "a.hsck"); });
  EXPECT_EQ(message.rfind("a.hsck: state does not fit the scenario at byte ", 0), 0u) << message;
  EXPECT_NE(message.find("particles: positions:"), std::string::npos) << message;
}

TEST(Checkpoint, FileNamesSortByTime) {
  EXPECT_EQ(checkpointFileName(3), "checkpoint_0003.000s.hsck");
  EXPECT_LT(checkpointFileName(3), checkpointFileName(10.5));
}

}  // namespace
}  // namespace hs::io
