// Scenario files: any bytes as a scenario's TOML text. A text that parses must also give a
// heart model or the model's one-line refusal (std::invalid_argument); anything else is a bug.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "cardiac/anatomy/lv_model.h"
#include "io/scenario/scenario_file.h"
#include "one_line.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  hs::cardiac::Scenario scenario;
  try {
    scenario = hs::io::parseScenario(text, "fuzz.toml");
  } catch (const hs::io::ScenarioError& e) {
    hs::fuzz::requireOneLine(e.what());
    return 0;
  }
  if (!scenario.heart) return 0;
  // The model is built in milliseconds at the default resolutions; a very fine one would
  // take the fuzzer's time without finding more.
  if (scenario.geometry.resolution > 2) return 0;
  try {
    (void)hs::cardiac::buildLvModel(scenario.geometry);
  } catch (const std::invalid_argument& e) {
    hs::fuzz::requireOneLine(e.what());
  }
  return 0;
}
