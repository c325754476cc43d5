#include "viewer/viewer_keys.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>

namespace hs::viewer {

bool readKeys(ViewerControls& c, bool paintAvailable) {
  // ImGui 1.86 with the GLFW backend indexes its key state by GLFW key codes.
  const auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  if (pressed(GLFW_KEY_1) || pressed(GLFW_KEY_F)) c.viewRequested = render::View::Front;
  if (pressed(GLFW_KEY_2) || pressed(GLFW_KEY_L)) c.viewRequested = render::View::Left;
  if (pressed(GLFW_KEY_3)) c.viewRequested = render::View::Right;
  if (pressed(GLFW_KEY_4) || pressed(GLFW_KEY_T)) c.viewRequested = render::View::Top;
  if (pressed(GLFW_KEY_R)) c.resetCameraRequested = true;
  if (pressed(GLFW_KEY_SPACE)) c.playing = !c.playing;
  if (ImGui::IsKeyPressed(GLFW_KEY_S, true)) c.stepRequested = true;
  if (pressed(GLFW_KEY_BACKSPACE)) c.resetRequested = true;
  if (pressed(GLFW_KEY_P)) c.screenshotRequested = true;
  if (pressed(GLFW_KEY_H) || pressed(GLFW_KEY_F1)) c.showHelp = !c.showHelp;
  if (pressed(GLFW_KEY_C)) c.showCirculation = !c.showCirculation;
  RegionControls& region = c.region;
  if (pressed(GLFW_KEY_B) && paintAvailable) region.paintMode = !region.paintMode;
  // Each press scales the brush by 1.25, so the range is crossed in a dozen presses.
  if (ImGui::IsKeyPressed(GLFW_KEY_LEFT_BRACKET, true)) region.brushRadiusPx /= 1.25f;
  if (ImGui::IsKeyPressed(GLFW_KEY_RIGHT_BRACKET, true)) region.brushRadiusPx *= 1.25f;
  region.brushRadiusPx =
      std::clamp(region.brushRadiusPx, RegionControls::kMinBrushPx, RegionControls::kMaxBrushPx);
  if (pressed(GLFW_KEY_ENTER) || pressed(GLFW_KEY_KP_ENTER)) region.applyRequested = true;
  return pressed(GLFW_KEY_ESCAPE);
}

}  // namespace hs::viewer
