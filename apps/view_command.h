#pragma once
// `heartsim view [SCENARIO|FILE.toml]`: the interactive viewer (docs/viewer.md). A window
// shows the simulation as it runs, with a mouse camera and a control panel; --frames,
// --screenshot and --size make it scriptable (tests, documentation images).
#include <string>
#include <vector>

namespace hs::app {

struct ViewOptions {
  std::string scenario = "heart-only";
  std::vector<std::string> overrides;  // --set KEY=VALUE
  std::string size = "1280x800";       // WxH window pixels
  int frames = 0;                      // > 0: quit after N frames
  std::string screenshot;              // save the last frame as PNG
  int threads = 0;                     // 0 = all cores but one (left to the drawing)
  std::string lesson;                  // --lesson NAME|FILE: run a lesson (docs/lessons.md)
  std::string resume;                  // --resume FILE: start from a checkpoint (its scenario)
  std::string resolution = "auto";     // --resolution coarse|medium|fine|finest|auto (blood)
  std::string bloodLook = "liquid";    // --blood-look liquid|spheres
  std::string flow = "off";            // --flow off|streaks|arrows
  std::string labels = "anatomy";      // --labels off|anatomy (the panel's checkbox, key N)
};

// With a lesson, the viewer starts on the lesson's scenario; with --frames it plays the lesson
// by itself and, with --screenshot, saves one picture per step beside the last.
// Exit codes: 0 closed; 2 bad option, scenario or lesson file (one line); 1 no display (one line saying
// that `heartsim render` works without one) or a screenshot that cannot be written.
int viewCommand(const ViewOptions& options);

}  // namespace hs::app
