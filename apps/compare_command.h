#pragma once
// `heartsim compare A B`: two scenarios with the lumped circulation run one after the other,
// and their last complete beats drawn as two loops on one pressure-volume plot
// (pv_compare.png), e.g. `heartsim compare normal dilated-cardiomyopathy`; with 3D blood, both
// runs' flow components (summary.json's heart.flow_components) printed side by side.
#include <string>
#include <vector>

namespace hs::app {

struct CompareOptions {
  std::vector<std::string> scenarios;  // exactly two names or .toml paths
  double duration = 1.8;               // s: two beats at 72 bpm, the second complete
  int threads = 0;                     // 0 = all cores
  std::string outDir;                  // empty: results/compare_<a>_<b>
};

int compareCommand(const CompareOptions& options);

}  // namespace hs::app
