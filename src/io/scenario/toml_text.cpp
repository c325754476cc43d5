#include "io/scenario/toml_text.h"

#include <cstdio>

namespace hs::io {

TomlText parseTomlText(std::string_view text, const std::string& sourceName) {
  TomlText parsed;
  try {
    parsed.table = toml::parse(text, sourceName);
  } catch (const toml::parse_error& e) {
    const auto& begin = e.source().begin;
    std::string where = sourceName;
    if (begin.line != 0) where += ":" + std::to_string(begin.line) + ":" + std::to_string(begin.column);
    // The description quotes the offending character: a carriage return or another control
    // character there would break the one-line message on a terminal, so it is written as \xNN.
    std::string description;
    for (const char c : e.description()) {
      if (static_cast<unsigned char>(c) >= 0x20) {
        description += c;
        continue;
      }
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      description += escaped;
    }
    parsed.error = where + ": TOML syntax error: " + description;
  }
  return parsed;
}

}  // namespace hs::io
