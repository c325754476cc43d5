#pragma once
// The viewer's keys, as requests in ViewerControls (the help window and docs/viewer.md list
// them). Kept apart from the frame loop (viewer_app.cpp) so that the map of keys reads in one
// place. Needs an ImGui frame in progress (the keys come through ImGui's input state).
#include "viewer/ui_panel.h"

namespace hs::viewer {

// Reads this frame's key presses into `controls`; paintAvailable: the beating region can be
// painted (B). Returns true when Esc asks to quit.
bool readKeys(ViewerControls& controls, bool paintAvailable);

}  // namespace hs::viewer
