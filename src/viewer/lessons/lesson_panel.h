#pragma once
// The lesson window: over the control panel, its whole height, so that the scene keeps its
// width for the heart and the longest step shows without scrolling. It shows "step k of n",
// the step's text, the question's choices as buttons (their labels wrapped), then the result
// with the chosen answer marked right or wrong and the explanation, with Back / Next at the
// top. "hide" uncovers the control panel; a button at the scene's top left corner shows the
// lesson again. Like the other panels it only reads the player and writes requests
// (LessonRequests); the app hands them to the player. Needs an ImGui frame in progress.
#include "viewer/lessons/lesson_player.h"

namespace hs::viewer {

// `left`, `width`: the control panel's column (pixels); the window is `windowHeight` tall.
void drawLessonPanel(const LessonPlayer& player, LessonRequests& requests, float left, float width,
                     int windowHeight);

}  // namespace hs::viewer
