#pragma once
// The lesson window: over the scene's top-left corner, semi-opaque, its text wrapped to a
// fixed width, so the heart (framed to its right, viewer_app.cpp) stays in sight. It shows
// "step k of n", the step's text, the question's choices as buttons, then the result with the
// chosen answer marked right or wrong and the explanation, and Back / Next. Like the other
// panels it only reads the player and writes requests (LessonRequests); the app hands them to
// the player. Needs an ImGui frame in progress.
#include "viewer/lessons/lesson_player.h"

namespace hs::viewer {

// The window's width for a scene `sceneWidth` pixels wide (between the side panels).
float lessonPanelWidth(float sceneWidth);

// left, top: the scene's top-left corner (pixels); maxHeight: what the window may cover
// downwards (it scrolls beyond).
void drawLessonPanel(const LessonPlayer& player, LessonRequests& requests, float left, float top, float width,
                     float maxHeight);

}  // namespace hs::viewer
