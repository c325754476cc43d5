#pragma once
// The interactive viewer behind `heartsim view`: a GLFW window with an OpenGL 3.3 core context,
// the scene drawn by the same render::Renderer as `heartsim render`, Dear ImGui panels (the
// controls on the left, the heart as a pump on the right), and the simulation stepped at
// real-time pace in its own thread (simulation_runner.h, docs/viewer.md).
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cardiac/scenario.h"
#include "io/output/checkpoint.h"
#include "render/scene.h"
#include "viewer/lessons/lesson.h"
#include "viewer/panels/blood_resolution.h"

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
  // --resolution: the blood's level; nullopt: the finest that holds real time here, measured at
  // start-up (blood_resolution.h), unless bloodFixedBy names what fixed the blood's count (a
  // scenario file, --set blood.particles, a lesson, a checkpoint): then it runs as given.
  std::optional<BloodResolution> resolution;
  std::string bloodFixedBy;
  std::optional<Lesson> lesson;    // a lesson to run (lesson.h); scripted when frames > 0
  // --resume FILE: the checkpoint to start from (its scenario is `scenario`) and the file's name.
  std::optional<io::Checkpoint> resume;
  std::string resumeSource;
  // --blood-look, --flow, --labels: the display's first settings (the panel changes them).
  render::BloodLook bloodLook = render::BloodLook::Liquid;
  render::FlowView flow = render::FlowView::Off;
  bool labels = true;
};

// Opens the window and runs until it is closed (or `frames` have been drawn). Throws
// DisplayError when no window can be opened, std::invalid_argument when the scenario is
// rejected by the model, std::runtime_error when the screenshot cannot be written.
void runViewer(const ViewerOptions& options);

}  // namespace hs::viewer
