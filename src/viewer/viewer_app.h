#pragma once
// The interactive viewer behind `heartsim view`: a GLFW window with an OpenGL 3.3 core context,
// the scene drawn by the same render::Renderer as `heartsim render`, a Dear ImGui control
// panel, and the simulation stepped between frames at real-time pace (docs/viewer.md).
#include <stdexcept>
#include <string>
#include <vector>

#include "cardiac/scenario.h"

namespace hs::viewer {

// No window can be opened: no display, or no OpenGL 3.3 context on it. One line.
struct DisplayError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ViewerOptions {
  cardiac::Scenario scenario;      // what to show first
  std::string builtinName;         // its built-in name, "" when it came from a file
  int width = 1280, height = 800;  // window size, pixels
  int frames = 0;                  // > 0: quit after this many frames (scripted use, tests)
  std::string screenshot;          // non-empty: save the last frame there as PNG
  int threads = 1;                 // simulation worker threads
};

// Opens the window and runs until it is closed (or `frames` have been drawn). Throws
// DisplayError when no window can be opened, std::invalid_argument when the scenario is
// rejected by the model, std::runtime_error when the screenshot cannot be written.
void runViewer(const ViewerOptions& options);

// The time step budget of one frame: stepping stops after this much wall time so the window
// keeps answering (s).
inline constexpr double kStepBudgetSeconds = 1.0 / 30;

// Steps to take this frame to keep simulated time on wall time: `debt` (simulated seconds
// owed, carried between frames) grows by wallSeconds * speed; returns whole steps of dt.
struct Pacing {
  double debt = 0;
  // Adds the frame's share; returns how many steps are owed now.
  long owe(double wallSeconds, double speed, double dt);
  // After stepping: `taken` of the owed steps were done. When the budget ran out first the
  // rest is dropped (true is returned: the simulation is behind real time).
  bool settle(long owed, long taken, double dt);
};

}  // namespace hs::viewer
