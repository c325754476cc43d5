#pragma once
// `heartsim bench [--case NAME]... [--scenario FILE]... [--threads N] [--json]`: end-to-end
// throughput cases; a scenario file is stepped as the real-size hearts are, with each stage's time.
// Each case runs in its own child process so that its peak resident memory is its own.
#include <string>
#include <vector>

namespace hs::app {

struct BenchOptions {
  std::vector<std::string> cases;      // empty: all (unless scenario files are named)
  std::vector<std::string> scenarios;  // .toml files benchmarked as the heart cases are
  int threads = 0;                 // 0 = all cores
  std::string resolution;          // --resolution: the scenarios' blood level; empty: as written (fine)
  bool json = false;
  double seconds = 3.0;            // measuring time per case (after warm-up)
};

std::vector<std::string> benchCaseNames();
int benchCommand(const BenchOptions& options);

}  // namespace hs::app
