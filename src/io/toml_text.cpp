#include "io/toml_text.h"

namespace hs::io {

TomlText parseTomlText(std::string_view text, const std::string& sourceName) {
  TomlText parsed;
  try {
    parsed.table = toml::parse(text, sourceName);
  } catch (const toml::parse_error& e) {
    const auto& begin = e.source().begin;
    std::string where = sourceName;
    if (begin.line != 0) where += ":" + std::to_string(begin.line) + ":" + std::to_string(begin.column);
    parsed.error = where + ": TOML syntax error: " + std::string(e.description());
  }
  return parsed;
}

}  // namespace hs::io
