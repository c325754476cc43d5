#pragma once
// Names on the heart in the scene: the left ventricle, where blood comes from (the left atrium,
// through the inflow vessel), the mitral and aortic valves, where it goes (the aorta), the apex
// and the septum, with arrows along the vessels that show which way blood flows forward. Every
// anchor is taken from the model's own data as it is now (the orifices' rings, the vessels'
// pinned far ends, the AHA septal segments, the wall's lowest point), never from fixed
// coordinates, so the labels follow the moving wall and any shape of the model. The viewer
// draws them with ImGui (viewer/app/scene_overlays.h), `heartsim render --labels` into its images.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cardiac/heart_simulation.h"
#include "render/camera.h"
#include "viz/image.h"

namespace hs::render {

// Which labels: none, or the anatomy (all seven names with the flow's arrows).
enum class LabelSet { Off, Anatomy };
const char* labelSetName(LabelSet set);
std::optional<LabelSet> parseLabelSet(std::string_view name);
std::string labelSetNames();  // "off, anatomy"

enum class LabelSide { Left, Right, Below };

struct SceneLabel {
  std::string text;
  Vec3f anchor = Vec3f::Zero();     // m, the point the label names
  LabelSide side = LabelSide::Left;  // where its text goes, seen from the front
  // Forward flow at the anchor: an arrow from `anchor - flow` to `anchor` (flows in) or from
  // `anchor` to `anchor + flow` (flows out); zero: no arrow.
  Vec3f flow = Vec3f::Zero();
  bool flowsIn = false;
};

// The labels of a simulation's heart; none without one or for LabelSet::Off.
std::vector<SceneLabel> anatomyLabels(const cardiac::HeartSimulation& sim, LabelSet set = LabelSet::Anatomy);

// A label's anchor and arrow in window pixels (x right, y down); onScreen false when the point
// is behind the camera.
struct ProjectedLabel {
  float x = 0, y = 0;
  float arrowFromX = 0, arrowFromY = 0, arrowToX = 0, arrowToY = 0;
  bool hasArrow = false, onScreen = false;
};
ProjectedLabel projectLabel(const SceneLabel& label, const Camera& camera, int width, int height);

// The labels drawn into a finished image seen by `camera`: a dot at each anchor, a leader line
// out to a pale box with the name (placed by label_layout.h: outward from the heart, none on
// another), the flow arrows in white with a dark rim.
// `avoid`: boxes already on the image (the colour key) that no name may cover.
void drawLabels(viz::Image& image, const std::vector<SceneLabel>& labels, const Camera& camera,
                const std::vector<viz::Rect>& avoid = {});

}  // namespace hs::render
