#include "viewer/app/viewer_keys.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <utility>

namespace hs::viewer {

void KeyEvents::push(int key, int action, int mods) {
  // A queue no frame reads (a window being dragged) must not grow without bound.
  constexpr std::size_t kMaxPending = 256;
  if (action == GLFW_RELEASE || m_presses.size() >= kMaxPending) return;
  m_presses.push_back({key, action == GLFW_REPEAT, (mods & GLFW_MOD_SHIFT) != 0});
}

std::vector<KeyPress> KeyEvents::take() { return std::exchange(m_presses, {}); }

bool applyKeys(std::span<const KeyPress> presses, ViewerControls& c, bool paintAvailable) {
  bool quit = false;
  RegionControls& region = c.region;
  for (const KeyPress& press : presses) {
    // Held keys repeat only where repeating means something: stepping and the brush's size.
    switch (press.key) {
      case GLFW_KEY_S: c.stepRequested = true; continue;
      // Each press scales the brush by 1.25, so the range is crossed in a dozen presses.
      case GLFW_KEY_LEFT_BRACKET: region.brushRadiusPx /= 1.25f; continue;
      case GLFW_KEY_RIGHT_BRACKET: region.brushRadiusPx *= 1.25f; continue;
      default: break;
    }
    if (press.repeat) continue;
    switch (press.key) {
      case GLFW_KEY_1:
      case GLFW_KEY_F: c.viewRequested = render::View::Front; break;
      case GLFW_KEY_2:
      case GLFW_KEY_L: c.viewRequested = render::View::Left; break;
      case GLFW_KEY_3: c.viewRequested = render::View::Right; break;
      case GLFW_KEY_4:
      case GLFW_KEY_T: c.viewRequested = render::View::Top; break;
      case GLFW_KEY_R: c.resetCameraRequested = true; break;
      case GLFW_KEY_SPACE: c.playing = !c.playing; break;
      case GLFW_KEY_BACKSPACE: c.resetRequested = true; break;
      case GLFW_KEY_P: c.screenshotRequested = true; break;
      case GLFW_KEY_F5: c.saveStateRequested = true; break;
      case GLFW_KEY_H:
      case GLFW_KEY_F1: c.showHelp = !c.showHelp; break;
      case GLFW_KEY_C: c.showCirculation = !c.showCirculation; break;
      case GLFW_KEY_N: c.showLabels = !c.showLabels; break;
      case GLFW_KEY_B:
        if (paintAvailable) region.paintMode = !region.paintMode;
        break;
      case GLFW_KEY_ENTER:
      case GLFW_KEY_KP_ENTER: region.applyRequested = true; break;
      // Esc closes an open window first (help, compare): a student closing one must not quit.
      case GLFW_KEY_ESCAPE:
        if (c.showHelp)
          c.showHelp = false;
        else if (c.pump.showCompare)
          c.pump.showCompare = false;
        else
          quit = true;
        break;
      default: break;
    }
  }
  region.brushRadiusPx = std::clamp(region.brushRadiusPx, RegionControls::kMinBrushPx, RegionControls::kMaxBrushPx);
  return quit;
}

}  // namespace hs::viewer
