#pragma once
// `heartsim run SCENARIO|FILE.toml`: the headless runner; `heartsim run --resume FILE`
// continues a checkpoint (io/output/checkpoint.h) to --duration, bitwise as the run without a stop.
#include <optional>
#include <string>
#include <vector>

namespace hs::app {

struct RunOptions {
  std::string scenario = "heart-only";
  std::vector<std::string> overrides;  // --set KEY=VALUE
  std::string resolution;              // --resolution: the blood's level; empty: as written (fine)
  std::optional<double> duration;      // --duration S
  int threads = 0;                     // 0 = all cores
  std::string outDir;                  // empty: results/<scenario name>
  bool json = false;
  bool vtk = false;
  std::optional<double> checkpointEvery;  // --checkpoint-every S: a checkpoint every S simulated seconds
  std::string resume;                     // --resume FILE: continue this checkpoint (scenario may be empty)
};

int runCommand(const RunOptions& options);

}  // namespace hs::app
