#pragma once
// The viewer's keys, as requests in ViewerControls (the help window and docs/viewer.md list
// them). Kept apart from the frame loop (viewer_app.cpp) so that the map of keys reads in one
// place. Keys arrive as events (GLFW's key callback) and wait in a KeyEvents queue until the
// next frame reads them: at 10 fps a tap shorter than a frame is pressed and released between
// two frames, and a key state polled once per frame would never see it.
#include <span>
#include <vector>

#include "viewer/panels/ui_panel.h"

namespace hs::viewer {

// One press (or, held down, one repeat) of a key, GLFW key codes.
struct KeyPress {
  int key = 0;
  bool repeat = false;  // sent by the system while the key is held
  bool shift = false;
};

// The presses since the last take(), in order. Releases are not needed: a tap is its press.
class KeyEvents {
 public:
  // From GLFW's key callback: action GLFW_PRESS, GLFW_REPEAT or GLFW_RELEASE; mods its bit set.
  void push(int key, int action, int mods);
  std::vector<KeyPress> take();

 private:
  std::vector<KeyPress> m_presses;
};

// Applies this frame's presses to `controls`; paintAvailable: the beating region can be
// painted (B). Returns true when Esc asks to quit.
bool applyKeys(std::span<const KeyPress> presses, ViewerControls& controls, bool paintAvailable);

}  // namespace hs::viewer
