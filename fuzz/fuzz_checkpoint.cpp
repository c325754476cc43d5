// Checkpoint files: any bytes as a `.hsck` file. The header, sections and checksum are read;
// what decodes is then read as a scenario and loaded into a `normal` simulation built once,
// and, where a monitor's state is present, into its run monitor.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

#include "cardiac/heart_simulation.h"
#include "cardiac/run_monitor.h"
#include "io/output/checkpoint.h"
#include "io/scenario/scenario_file.h"
#include "one_line.h"

namespace {

struct Target {
  hs::cardiac::HeartSimulation sim{hs::io::loadScenario("normal"), 1};
  hs::cardiac::RunMonitor monitor{sim};
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::unique_ptr<Target> target = std::make_unique<Target>();
  try {
    const hs::io::Checkpoint checkpoint = hs::io::decodeCheckpoint(std::span(data, size), "fuzz.hsck");
    (void)hs::io::checkpointScenario(checkpoint, "fuzz.hsck");
    hs::io::restoreSimulation(checkpoint, target->sim, "fuzz.hsck");
    if (!checkpoint.monitor.empty()) hs::io::restoreMonitor(checkpoint, target->monitor, "fuzz.hsck");
  } catch (const hs::io::CheckpointError& e) {
    hs::fuzz::requireOneLine(e.what());
  }
  return 0;
}
