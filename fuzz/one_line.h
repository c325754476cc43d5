#pragma once
// What every fuzz target checks of an error it catches: one line, saying something.
#include <cstdlib>
#include <cstring>
#include <iostream>

namespace hs::fuzz {

inline void requireOneLine(const char* message) {
  if (std::strchr(message, '\n') != nullptr || std::strchr(message, '\r') != nullptr || message[0] == '\0') {
    std::cerr << "fuzz: an error message that is not one line: [" << message << "]\n";
    std::abort();
  }
}

}  // namespace hs::fuzz
