#pragma once
// The windows over the scene, placed so that the heart stays in sight: the colour key at the
// scene's bottom left, the status corner at its bottom right (above the key where the scene is
// too narrow for both side by side). With a lesson open the lesson window covers the control
// panel (lesson_panel.h), and the key and the status fold to their essentials (ui_panel.h): the
// scene is the heart's. Needs an ImGui frame in progress.
#include <vector>

#include "render/label_layout.h"
#include "viewer/app/scene_framing.h"
#include "viewer/lessons/lesson_player.h"
#include "viewer/panels/ui_panel.h"

namespace hs::viewer {

// Draws the key, the status and the lesson (if any) for a scene `area` of a window
// `windowHeight` pixels tall. Returns the boxes the key and the status cover in the scene, for
// the anatomy's names to avoid.
std::vector<render::LabelBox> drawSceneWindows(const ViewerStatus& status, const LessonPlayer* lesson,
                                               LessonRequests& requests, const SceneArea& area, int windowHeight);

}  // namespace hs::viewer
