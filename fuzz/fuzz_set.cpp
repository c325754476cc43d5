// `--set key=value`: any bytes as one override of the built-in `normal` scenario.
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/scenario/scenario_file.h"
#include "one_line.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string normal = hs::io::builtinScenarioText("normal");
  const std::string setting(reinterpret_cast<const char*>(data), size);
  try {
    (void)hs::io::parseScenario(normal, "normal", {setting});
  } catch (const hs::io::ScenarioError& e) {
    hs::fuzz::requireOneLine(e.what());
  }
  return 0;
}
