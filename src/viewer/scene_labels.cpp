#include "viewer/scene_labels.h"

#include <algorithm>

namespace hs::viewer {
namespace {

using render::Vec3f;

// The centroid of the vertices' current positions.
template <typename Ids>
Vec3f centroid(const Ids& ids, const std::vector<pbd::Vec3>& x) {
  pbd::Vec3 sum = pbd::Vec3::Zero();
  for (const auto v : ids) sum += x[std::size_t(v)];
  return ids.empty() ? Vec3f::Zero() : Vec3f((sum / pbd::Real(ids.size())).cast<float>());
}

}  // namespace

std::vector<SceneLabel> anatomyLabels(const cardiac::HeartSimulation& sim) {
  if (!sim.hasHeart()) return {};
  const cardiac::LvModel& model = sim.model();
  const std::vector<pbd::Vec3>& x = sim.particles().position;
  // The vessels' far rings are the pinned vertices, told apart by their region.
  std::vector<cardiac::Index> inflowEnd, outflowEnd;
  for (const cardiac::Index v : model.pinned)
    (model.region[v] == cardiac::Region::InflowVessel ? inflowEnd : outflowEnd).push_back(v);
  cardiac::Index apex = 0;
  for (cardiac::Index v = 0; v < cardiac::Index(model.region.size()); ++v)
    if (model.region[v] == cardiac::Region::Myocardium && x[v].y() < x[apex].y()) apex = v;

  // Arrows as long as the vessel is wide, pointing along it (+y is up the vessels).
  const Vec3f up(0, 1, 0);
  const float inflowArrow = 2 * float(model.params.mitralRadius);
  const float outflowArrow = 2 * float(model.params.aorticRadius);
  std::vector<SceneLabel> labels;
  // The arrows run inside the vessels, ending (inflow) or starting (outflow) at the far end's
  // plane less an arrow's length, so that they stay in the picture framed on the heart.
  labels.push_back({"from the left atrium", centroid(inflowEnd, x) - inflowArrow * up, LabelSide::Left,
                    -inflowArrow * up, true});
  labels.push_back({"mitral valve (inflow)", centroid(model.mitralRing, x), LabelSide::Left, Vec3f::Zero(), false});
  labels.push_back({"aortic valve (outflow)", centroid(model.aorticRing, x), LabelSide::Right, Vec3f::Zero(), false});
  labels.push_back({"to the aorta", centroid(outflowEnd, x) - 1.5f * outflowArrow * up, LabelSide::Right,
                    outflowArrow * up, false});
  labels.push_back({"apex", x[apex].cast<float>(), LabelSide::Below, Vec3f::Zero(), false});
  return labels;
}

ProjectedLabel projectLabel(const SceneLabel& label, const render::Camera& camera, int width, int height) {
  ProjectedLabel p;
  const Vec3f at = camera.project(label.anchor, width, height);
  // Behind the eye the projection's depth leaves [0, 1].
  p.onScreen = at.z() > 0 && at.z() < 1;
  p.x = at.x(), p.y = at.y();
  if (label.flow.squaredNorm() > 0) {
    const Vec3f from = label.flowsIn ? label.anchor - label.flow : label.anchor;
    const Vec3f to = label.flowsIn ? label.anchor : label.anchor + label.flow;
    const Vec3f a = camera.project(from, width, height), b = camera.project(to, width, height);
    p.arrowFromX = a.x(), p.arrowFromY = a.y(), p.arrowToX = b.x(), p.arrowToY = b.y();
    p.hasArrow = true;
  }
  return p;
}

}  // namespace hs::viewer
