#pragma once
// `heartsim run SCENARIO|FILE.toml`: the headless runner.
#include <optional>
#include <string>
#include <vector>

namespace hs::app {

struct RunOptions {
  std::string scenario = "heart-only";
  std::vector<std::string> overrides;  // --set KEY=VALUE
  std::optional<double> duration;      // --duration S
  int threads = 0;                     // 0 = all cores
  std::string outDir;                  // empty: results/<scenario name>
  bool json = false;
  bool vtk = false;
};

int runCommand(const RunOptions& options);

}  // namespace hs::app
