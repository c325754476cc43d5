#pragma once
// What the viewer draws over the scene itself, between the panels: the anatomy's names with
// the flow's arrows (scene_labels.h) and the message toasts (toasts.h). Needs an ImGui frame in
// progress.
#include <vector>

#include "render/camera.h"
#include "viewer/app/scene_framing.h"
#include "viewer/app/scene_labels.h"
#include "viewer/app/toasts.h"

namespace hs::viewer {

// Names and arrows for the labels, seen by `camera` in a window of width x height pixels,
// kept inside `area` (scene_framing.h: between the panels, above the strip).
void drawSceneLabels(const std::vector<SceneLabel>& labels, const render::Camera& camera, int width, int height,
                     const SceneArea& area);

// The toasts stacked at the top centre of `area`, newest on top, wrapped to its width (at most
// 560 px), each an ImGui window named "##toast<k>".
void drawToasts(const std::vector<Toast>& toasts, const SceneArea& area);

}  // namespace hs::viewer
