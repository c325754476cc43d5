#include "viewer/app/scene_framing.h"

#include <algorithm>
#include <cmath>

namespace hs::viewer {
namespace {

// Zoom steps (CameraController::zoom: distance x 0.9^steps) that make what filled the window's
// height fill its height less the strip's: distance x h / (h - strip).
float stripZoomSteps(float strip, int windowHeight) {
  const float h = float(std::max(windowHeight, 1));
  const float kept = std::clamp(h - strip, 0.2f * h, h);
  return std::log(h / kept) / std::log(0.9f);
}

// Fits a camera framed for the whole height to the area above the strip: zoom first, about
// the target at the window's centre, then pan the scene up by half the strip.
void fitStrip(CameraController& camera, float strip, int windowHeight) {
  if (strip <= 0) return;
  camera.zoom(stripZoomSteps(strip, windowHeight));
  camera.pan(0, -strip / 2, windowHeight);
}

void unfitStrip(CameraController& camera, float strip, int windowHeight) {
  if (strip <= 0) return;
  camera.pan(0, strip / 2, windowHeight);
  camera.zoom(-stripZoomSteps(strip, windowHeight));
}

}  // namespace

void frameView(CameraController& camera, render::View view, const SceneArea& area, int windowWidth,
               int windowHeight) {
  const float w = float(windowWidth), h = float(std::max(windowHeight, 1));
  const float free = std::max(area.right - area.left, w * 0.3f);
  const float tall = std::max(h - area.strip, 0.2f * h);
  // Framed as if the area were the whole viewport (its aspect decides whether the width or the
  // height limits), then fitted to the area's place in the window.
  camera.setAspect(free / tall);
  camera.setView(view);
  fitStrip(camera, area.strip, windowHeight);
  camera.pan((area.left + area.right - w) / 2, 0, windowHeight);
}

void refitForStrip(CameraController& camera, float from, float to, int windowHeight) {
  if (from == to) return;
  unfitStrip(camera, from, windowHeight);
  fitStrip(camera, to, windowHeight);
}

}  // namespace hs::viewer
