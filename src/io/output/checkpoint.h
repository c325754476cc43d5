#pragma once
// Checkpoints: a run's whole state in one file, from which `heartsim run --resume` (and the
// viewer) continue bitwise as if the run had never stopped. The file (little-endian):
//   magic        8 bytes  "HSCK\r\n\x1a\n" (a text transfer that mangles line ends shows)
//   version      u32      kCheckpointVersion
//   real size    u32      sizeof(pbd::Real): 4, or 8 for a double-precision build
//   scenario     u64 length + bytes: the resolved scenario as TOML (scenarioToToml), to read
//   values       u64 length + bytes: every key's exact value (saveScenarioValues); the
//                simulation is rebuilt from the two, and a checkpoint of one scenario is
//                refused for another
//   step, time   i64, f64: steps taken and simulated seconds
//   simulation   u64 length + bytes: HeartSimulation::save (state_stream.h sections)
//   monitor      u64 length + bytes: RunMonitor::save, or empty (the viewer's checkpoints:
//                a run resumed from one reports from the checkpoint on)
//   checksum     u64 FNV-1a of every byte before it
// Every error is a CheckpointError whose message is one line naming the file and what is
// wrong: bad magic, version, real size, truncated at byte N, checksum, state that does not fit
// the scenario.
#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "cardiac/heart_simulation.h"
#include "cardiac/run_monitor.h"

namespace hs::io {

struct CheckpointError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// 3: the blood's push on the wall in the run monitor; 4: the heart's phase; 5: the ventricle's
// blood (flow components, kinetic energy); 6: the Doppler velocities in the orifices; 7: the
// E-wave filling vortex
inline constexpr std::uint32_t kCheckpointVersion = 7;

struct Checkpoint {
  std::string scenarioToml;
  std::vector<std::uint8_t> scenarioValues;
  std::int64_t step = 0;
  double time = 0;  // s
  std::vector<std::uint8_t> simulation;
  std::vector<std::uint8_t> monitor;  // empty: no monitor state
  // Byte offsets of the two blobs in the file they were read from (for error messages).
  std::size_t simulationOffset = 0, monitorOffset = 0;
};

// The state of `sim` (and of `monitor`, when given) now.
Checkpoint captureCheckpoint(const cardiac::HeartSimulation& sim, const cardiac::RunMonitor* monitor);

std::vector<std::uint8_t> encodeCheckpoint(const Checkpoint& checkpoint);
// `source` (the file's name) starts every error message.
Checkpoint decodeCheckpoint(std::span<const std::uint8_t> bytes, const std::string& source);

// Written to a temporary file beside `path`, then renamed: a run stopped while writing leaves
// no half checkpoint under the final name.
void writeCheckpointFile(const std::filesystem::path& path, const Checkpoint& checkpoint);
Checkpoint readCheckpointFile(const std::filesystem::path& path);

// The checkpoint's scenario, exactly; throws CheckpointError when its text or values do not
// read (a file written by another version of heartsim).
cardiac::Scenario checkpointScenario(const Checkpoint& checkpoint, const std::string& source);

// Loads the saved state into a simulation built from checkpointScenario() (and a monitor of
// it); a state that does not fit throws CheckpointError naming the piece and the file offset.
void restoreSimulation(const Checkpoint& checkpoint, cardiac::HeartSimulation& sim, const std::string& source);
void restoreMonitor(const Checkpoint& checkpoint, cardiac::RunMonitor& monitor, const std::string& source);

// "checkpoint_0003.000s.hsck": the simulated time, zero-padded so that names sort by time.
std::string checkpointFileName(double time);

}  // namespace hs::io
