#include "render/anatomy_labels.h"

#include <algorithm>
#include <cmath>

#include "render/label_layout.h"

namespace hs::render {
namespace {

// The centroid of the vertices' current positions.
template <typename Ids>
Vec3f centroid(const Ids& ids, const std::vector<pbd::Vec3>& x) {
  pbd::Vec3 sum = pbd::Vec3::Zero();
  for (const auto v : ids) sum += x[std::size_t(v)];
  return ids.empty() ? Vec3f::Zero() : Vec3f((sum / pbd::Real(ids.size())).cast<float>());
}

// AHA segments of the septum (1-based): basal anteroseptal and inferoseptal, the same at mid
// level, apical septal (Cerqueira et al. 2002, Circulation 105:539).
constexpr std::uint8_t kSeptalSegments[] = {2, 3, 8, 9, 14};

// A vessel's bulge (an anatomical heart's atrium or aortic sinuses, cardiac/anatomy/vessel_shape.h): its
// lumen's vertices at rest more than a fifth wider from the vessel's axis than the orifice. None
// for a straight vessel.
std::vector<cardiac::Index> bulgeOf(const cardiac::LvModel& model, bool inflow) {
  const cardiac::FlowPath& path = model.flowPath;
  const cardiac::Region region = inflow ? cardiac::Region::InflowVessel : cardiac::Region::OutflowVessel;
  const pbd::Real wider = pbd::Real(1.2) * (inflow ? path.mitral.radius : path.aortic.radius);
  std::vector<cardiac::Index> bulge;
  if ((inflow ? path.inflowShape : path.outflowShape).bulgeRadius == 0) return bulge;
  for (cardiac::Index v = 0; v < cardiac::Index(model.region.size()); v += 2) {
    if (model.region[v] != region) continue;
    const pbd::Vec3& rest = model.mesh.vertices[v];
    if ((inflow ? path.inflowSection(rest.y()) : path.outflowSection(rest.y())).radial(rest) > wider) bulge.push_back(v);
  }
  return bulge;
}

}  // namespace

const char* labelSetName(LabelSet set) { return set == LabelSet::Off ? "off" : "anatomy"; }

std::optional<LabelSet> parseLabelSet(std::string_view name) {
  for (const LabelSet set : {LabelSet::Off, LabelSet::Anatomy})
    if (name == labelSetName(set)) return set;
  return std::nullopt;
}

std::string labelSetNames() { return "off, anatomy"; }

std::vector<SceneLabel> anatomyLabels(const cardiac::HeartSimulation& sim, LabelSet set) {
  if (!sim.hasHeart() || set == LabelSet::Off) return {};
  const cardiac::LvModel& model = sim.model();
  const std::vector<pbd::Vec3>& x = sim.particles().position;
  // The vessels' far rings are the pinned vertices, told apart by their region.
  std::vector<cardiac::Index> inflowEnd, outflowEnd, cavitySide, septum;
  for (const cardiac::Index v : model.pinned)
    (model.region[v] == cardiac::Region::InflowVessel ? inflowEnd : outflowEnd).push_back(v);
  cardiac::Index apex = 0;
  for (cardiac::Index v = 0; v < cardiac::Index(model.region.size()); ++v) {
    if (model.region[v] != cardiac::Region::Myocardium) continue;
    if (x[v].y() < x[apex].y() || model.region[apex] != cardiac::Region::Myocardium) apex = v;
    if (v % 2 != 0) continue;  // the shell's inner (cavity-side) layer has the even ids (lv_model.h)
    cavitySide.push_back(v);
    if (std::find(std::begin(kSeptalSegments), std::end(kSeptalSegments), model.segment[v]) !=
        std::end(kSeptalSegments))
      septum.push_back(v);
  }

  // Arrows as long as the vessel is wide, pointing along it (+y is up the vessels).
  const Vec3f up(0, 1, 0);
  const float inflowArrow = 2 * float(model.params.mitralRadius);
  const float outflowArrow = 2 * float(model.params.aorticRadius);
  const Vec3f mitral = centroid(model.mitralRing, x), aortic = centroid(model.aorticRing, x);
  const LabelSide inflowSide = mitral.x() <= aortic.x() ? LabelSide::Left : LabelSide::Right;
  const LabelSide outflowSide = inflowSide == LabelSide::Left ? LabelSide::Right : LabelSide::Left;
  const Vec3f septumAt = centroid(septum, x), ventricle = centroid(cavitySide, x);
  std::vector<SceneLabel> labels;
  // The arrows run inside the vessels, ending (inflow) or starting (outflow) at the far end's
  // plane less an arrow's length, so that they stay in the picture framed on the heart.
  labels.push_back({"from the left atrium", centroid(inflowEnd, x) - inflowArrow * up, inflowSide,
                    -inflowArrow * up, true});
  labels.push_back({"mitral valve (inflow)", mitral, inflowSide, Vec3f::Zero(), false});
  labels.push_back({"aortic valve (outflow)", aortic, outflowSide, Vec3f::Zero(), false});
  labels.push_back({"to the aorta", centroid(outflowEnd, x) - 1.5f * outflowArrow * up, outflowSide,
                    outflowArrow * up, false});
  // An anatomical heart's atrium and aortic root, named where their bulges are now.
  if (const auto atrium = bulgeOf(model, true); !atrium.empty())
    labels.push_back({"left atrium", centroid(atrium, x), inflowSide, Vec3f::Zero(), false});
  if (const auto root = bulgeOf(model, false); !root.empty())
    labels.push_back({"aortic root (sinuses)", centroid(root, x), outflowSide, Vec3f::Zero(), false});
  labels.push_back({"left ventricle", ventricle, septumAt.x() <= ventricle.x() ? LabelSide::Right : LabelSide::Left,
                    Vec3f::Zero(), false});
  labels.push_back({"septum", septumAt, septumAt.x() <= ventricle.x() ? LabelSide::Left : LabelSide::Right,
                    Vec3f::Zero(), false});
  labels.push_back({"apex", x[apex].cast<float>(), LabelSide::Below, Vec3f::Zero(), false});
  return labels;
}

ProjectedLabel projectLabel(const SceneLabel& label, const Camera& camera, int width, int height) {
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

namespace {

constexpr viz::Rgb kInk{30, 30, 40}, kPaper{255, 255, 255}, kArrow{255, 255, 255};

void drawArrow(viz::Image& image, float x0, float y0, float x1, float y1, int scale) {
  const float dx = x1 - x0, dy = y1 - y0, length = std::hypot(dx, dy);
  if (length < 4) return;
  const float ux = dx / length, uy = dy / length, head = std::min(7.0f * float(scale), 0.5f * length);
  const float bx = x1 - head * ux, by = y1 - head * uy;
  for (const auto& [colour, width] : {std::pair{kInk, 3.5f * float(scale)}, std::pair{kArrow, 1.75f * float(scale)}}) {
    image.drawLine(x0, y0, bx, by, colour, width);
    // The head as lines fanning from the tip to its base, wide enough to fill it.
    for (float s = -1; s <= 1; s += 0.1f)
      image.drawLine(x1, y1, bx + 0.55f * head * uy * s, by - 0.55f * head * ux * s, colour, width * 0.6f);
  }
}

}  // namespace

void drawLabels(viz::Image& image, const std::vector<SceneLabel>& labels, const Camera& camera,
                const std::vector<viz::Rect>& avoid) {
  const int w = image.width(), h = image.height();
  const int scale = std::max(1, std::min(w, h) / 300);
  const LabelSpacing spacing{22.0f * float(scale), 2.0f * float(scale)};
  std::vector<std::pair<float, float>> sizes;
  for (const SceneLabel& label : labels)
    sizes.emplace_back(float(viz::Image::textWidth(label.text, scale)), float(viz::Image::capHeight(scale)));
  std::vector<LabelBox> keep;
  for (const viz::Rect& r : avoid) keep.push_back({float(r.x), float(r.y), float(r.width), float(r.height)});
  const LabelBox bounds{0, 0, float(w), float(h)};
  for (const PlacedLabel& placed : layoutLabels(labels, sizes, camera, w, h, bounds, spacing, keep)) {
    const ProjectedLabel& p = placed.at;
    if (p.hasArrow) drawArrow(image, p.arrowFromX, p.arrowFromY, p.arrowToX, p.arrowToY, scale);
    const viz::Rect box{int(std::lround(placed.box.x)), int(std::lround(placed.box.y)),
                        int(std::lround(placed.box.width)), int(std::lround(placed.box.height))};
    image.drawLine(p.x, p.y, placed.leaderX, placed.leaderY, kInk, 1.5 * scale);
    image.drawCircle(p.x, p.y, 2.5 * scale, kInk);
    image.fillRect(box, kPaper);
    image.strokeRect(box, {150, 150, 160});
    const int pad = int(spacing.pad);
    image.drawText(box.x + pad, box.y + pad, labels[placed.label].text, scale, kInk);
  }
}

}  // namespace hs::render
