#pragma once
// Names on the heart in the scene: where blood comes from (the left atrium, through the inflow
// vessel), the mitral and aortic valves, where it goes (the aorta) and the apex, with arrows
// along the vessels that show which way blood flows forward. The anchors follow the moving
// wall (the orifices' rings and the vessels' far ends as they are now). Pure geometry here;
// ui_panel draws them over the scene (key N or the Display section toggles them).
#include <string>
#include <vector>

#include "cardiac/heart_simulation.h"
#include "render/camera.h"

namespace hs::viewer {

enum class LabelSide { Left, Right, Below };

struct SceneLabel {
  std::string text;
  render::Vec3f anchor = render::Vec3f::Zero();  // m, the point the label names
  LabelSide side = LabelSide::Left;             // where its text goes, seen from the front
  // Forward flow at the anchor: an arrow from `anchor - flow` to `anchor` (flows in) or from
  // `anchor` to `anchor + flow` (flows out); zero: no arrow.
  render::Vec3f flow = render::Vec3f::Zero();
  bool flowsIn = false;
};

// The labels of a simulation's heart; none without one.
std::vector<SceneLabel> anatomyLabels(const cardiac::HeartSimulation& sim);

// A label's anchor and arrow in window pixels (x right, y down); onScreen false when the point
// is behind the camera.
struct ProjectedLabel {
  float x = 0, y = 0;
  float arrowFromX = 0, arrowFromY = 0, arrowToX = 0, arrowToY = 0;
  bool hasArrow = false, onScreen = false;
};
ProjectedLabel projectLabel(const SceneLabel& label, const render::Camera& camera, int width, int height);

}  // namespace hs::viewer
