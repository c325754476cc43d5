#pragma once
// Tests of the viewer's simulation thread: poll until a condition holds.
#include <chrono>
#include <functional>
#include <thread>

#include "viewer/app/simulation_runner.h"

namespace hs::viewer::test_support {

// Polls until `done` (read under access()) or a generous time-out (s): the machine may be busy.
inline bool waitFor(SimulationRunner& runner, const std::function<bool(SimulationState&)>& done, int seconds = 300) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (runner.access(done)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

}  // namespace hs::viewer::test_support
