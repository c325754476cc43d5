#include "viewer/app/scene_windows.h"

#include "viewer/lessons/lesson_panel.h"

namespace hs::viewer {

std::vector<render::LabelBox> drawSceneWindows(const ViewerStatus& status, const LessonPlayer* lesson,
                                               LessonRequests& requests, const SceneArea& area, int windowHeight) {
  const bool lessonOpen = lesson && !lesson->closed();
  const float bottom = float(windowHeight) - area.strip;
  // The key (260 px) and the status corner (about 230 px) side by side, with their margins.
  constexpr float kBothFit = 560;
  const OverlayBox key = drawColourKey(status, area.left, bottom, lessonOpen);
  const float statusBottom = area.right - area.left < kBothFit && key.height > 0 ? key.y - 4 : bottom;
  const OverlayBox corner = drawStatusOverlay(status, area.right, statusBottom, lessonOpen);
  if (lesson) drawLessonPanel(*lesson, requests, 0, area.left, windowHeight);
  std::vector<render::LabelBox> boxes;
  for (const OverlayBox& b : {key, corner})
    if (b.width > 0 && b.height > 0) boxes.push_back({b.x, b.y, b.width, b.height});
  return boxes;
}

}  // namespace hs::viewer
