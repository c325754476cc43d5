#pragma once
// `heartsim bench [--case NAME]... [--threads N] [--json]`: end-to-end throughput cases.
// Each case runs in its own child process so that its peak resident memory is its own.
#include <string>
#include <vector>

namespace hs::app {

struct BenchOptions {
  std::vector<std::string> cases;  // empty: all
  int threads = 0;                 // 0 = all cores
  bool json = false;
  double seconds = 3.0;            // measuring time per case (after warm-up)
};

std::vector<std::string> benchCaseNames();
int benchCommand(const BenchOptions& options);

}  // namespace hs::app
