#pragma once
// What the viewer draws over the scene itself, between the panels: the anatomy's names with
// the flow's arrows (scene_labels.h) and the message toasts (toasts.h). Needs an ImGui frame in
// progress.
#include <vector>

#include "render/camera.h"
#include "render/label_layout.h"
#include "viewer/app/scene_framing.h"
#include "viewer/app/scene_labels.h"
#include "viewer/app/toasts.h"

namespace hs::viewer {

// The leader lines' length and the names' paper margin in the viewer (px).
inline constexpr render::LabelSpacing kLabelSpacing{34, 3};

// Names and arrows for the labels, seen by `camera` in a window of width x height pixels,
// kept inside `area` (scene_framing.h: between the panels, above the strip) and clear of the
// `avoid` boxes (the windows over the scene), placed by render::layoutLabels: no two overlap.
void drawSceneLabels(const std::vector<SceneLabel>& labels, const render::Camera& camera, int width, int height,
                     const SceneArea& area, const std::vector<render::LabelBox>& avoid);
// Each label's text size in the current ImGui font (px).
std::vector<std::pair<float, float>> labelTextSizes(const std::vector<SceneLabel>& labels);

// The toasts stacked at the top centre of `area`, newest on top, wrapped to its width (at most
// 560 px), each an ImGui window named "##toast<k>".
void drawToasts(const std::vector<Toast>& toasts, const SceneArea& area);

}  // namespace hs::viewer
