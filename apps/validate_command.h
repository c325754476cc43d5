#pragma once
// `heartsim validate dam-break`: runs the dam-break scenario and compares its surge front with
// Martin & Moyce (1952), n^2 = 2 (docs/validation.md).
#include <string>
#include <vector>

namespace hs::app {

struct ValidateOptions {
  std::string scenario = "dam-break";  // built-in name or .toml path
  std::vector<std::string> overrides;  // --set KEY=VALUE
  std::string outDir = "results/validate-dam-break";
  int threads = 0;  // 0 = all cores
  bool json = false;
};

// Exit codes: kExitOk when it ran and met the bound, kExitValidationFailed when the front's
// error exceeds it, kExitBadInput for a scenario that is not a dam break of n^2 = 2.
int validateDamBreakCommand(const ValidateOptions& options);

}  // namespace hs::app
