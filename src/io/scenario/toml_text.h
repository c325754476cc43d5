#pragma once
// TOML text parsed with its syntax errors located: what the scenario and lesson readers share.
#include <toml++/toml.h>

#include <string>
#include <string_view>

namespace hs::io {

struct TomlText {
  toml::table table;
  std::string error;  // "" when parsed; else one line: "<source>:<line>:<column>: TOML syntax error: ..."
};

// sourceName: the file's name (or "scenario" for built-in text), used in the error's location.
TomlText parseTomlText(std::string_view text, const std::string& sourceName);

}  // namespace hs::io
