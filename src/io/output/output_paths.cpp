#include "io/output/output_paths.h"

namespace hs::io {

std::string safeFileStem(std::string_view name) {
  std::string stem;
  stem.reserve(name.size());
  for (const char c : name) {
    const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    const bool digit = c >= '0' && c <= '9';
    stem += letter || digit || c == '-' || c == '_' ? c : '_';
  }
  return stem.empty() ? std::string("scenario") : stem;
}

std::filesystem::path defaultOutputFolder(std::string_view scenarioName) {
  return std::filesystem::path("results") / safeFileStem(scenarioName);
}

}  // namespace hs::io
