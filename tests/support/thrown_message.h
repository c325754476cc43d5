#pragma once
// Shared by the test suites: the message of the exception a call throws.
#include <gtest/gtest.h>

#include <exception>
#include <string>

namespace hs::testing {

// Runs f, expects it to throw an E, and returns the exception's message. Records a test
// failure (and returns "") when f returns normally.
template <class E = std::exception, class F>
std::string thrownMessage(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  ADD_FAILURE() << "no exception thrown";
  return {};
}

}  // namespace hs::testing
