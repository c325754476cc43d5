#include "render/scene.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <utility>

#include "cardiac/circulation/clinical_units.h"
#include "render/blood_field.h"
#include "render/valve_leaflets.h"

namespace hs::render {
namespace {

Vec3f toVec3f(const pbd::Vec3& v) { return v.cast<float>(); }

// Corners of a box as the 12 edges' point pairs.
std::vector<Vec3f> boxEdges(const Vec3f& lo, const Vec3f& hi) {
  std::vector<Vec3f> points;
  auto corner = [&](int i) {
    return Vec3f((i & 1) ? hi.x() : lo.x(), (i & 2) ? hi.y() : lo.y(), (i & 4) ? hi.z() : lo.z());
  };
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if ((i & bit) == 0) {
        points.push_back(corner(i));
        points.push_back(corner(i | bit));
      }
  return points;
}

// Vertex normals that stay smooth across gentle bends and keep creases (the wall's rim, the
// vessel ends): each triangle corner averages the area-weighted normals of the triangles at
// its vertex that lie within ~50 degrees of its own.
// beating: per model vertex, nonzero = drawn in beatingColour; outOfStep: nonzero = drawn in
// outOfStepColour, over the beating colour (either may be empty).
void addWall(const cardiac::HeartSimulation& sim, const std::vector<std::uint8_t>& beating,
             const std::vector<std::uint8_t>& outOfStep, WallMesh& wall) {
  const auto& model = sim.model();
  const auto& x = sim.particles().position;
  const std::size_t n = model.surface.size();
  std::vector<Vec3f> faceNormal(n);  // area-weighted (length = 2 area)
  std::vector<std::vector<std::uint32_t>> facesAt(model.mesh.vertices.size());
  for (std::size_t f = 0; f < n; ++f) {
    const auto& t = model.surface[f];
    faceNormal[f] = (toVec3f(x[t[1]]) - toVec3f(x[t[0]])).cross(toVec3f(x[t[2]]) - toVec3f(x[t[0]]));
    for (pbd::Index v : t) facesAt[v].push_back(std::uint32_t(f));
  }
  constexpr float kCreaseCos = 0.64f;  // cos 50 degrees
  wall.positions.reserve(3 * n);
  wall.normals.reserve(3 * n);
  wall.colours.reserve(3 * n);
  for (std::size_t f = 0; f < n; ++f) {
    const Vec3f own = faceNormal[f].normalized();
    for (pbd::Index v : model.surface[f]) {
      Vec3f sum = Vec3f::Zero();
      for (std::uint32_t g : facesAt[v])
        if (faceNormal[g].normalized().dot(own) >= kCreaseCos) sum += faceNormal[g];
      wall.positions.push_back(toVec3f(x[v]));
      wall.normals.push_back(sum.squaredNorm() > 0 ? sum.normalized() : own);
      const Vec3f colour = regionColour(model.region[v]);
      wall.colours.push_back(v < outOfStep.size() && outOfStep[v] ? outOfStepColour(colour)
                             : v < beating.size() && beating[v] ? beatingColour(colour)
                                                                : colour);
    }
  }
}

}  // namespace

Vec3f regionColour(cardiac::Region region) {
  switch (region) {
    case cardiac::Region::Myocardium: return {0.80f, 0.27f, 0.30f};
    case cardiac::Region::BasePlate: return {0.95f, 0.84f, 0.74f};
    case cardiac::Region::InflowVessel: return {0.93f, 0.66f, 0.70f};
    case cardiac::Region::OutflowVessel: return {0.96f, 0.74f, 0.62f};
  }
  return {1, 1, 1};
}

Vec3f beatingColour(const Vec3f& base) {
  // Two thirds of the way to a saturated orange: on the red myocardium (0.80, 0.27, 0.30) this
  // gives (0.93, 0.53, 0.17), orange in light and in shade alike.
  const Vec3f orange(1.0f, 0.66f, 0.10f);
  return base / 3 + orange * (2.0f / 3);
}

Vec3f outOfStepColour(const Vec3f& base) {
  // Two thirds of the way to violet: apart from the red wall, the orange region and the pale
  // vessels, and from every blood colour but the origin key's ventricle violet, which is
  // bluer and only seen inside.
  const Vec3f violet(0.55f, 0.25f, 0.85f);
  return base / 3 + violet * (2.0f / 3);
}

std::vector<std::uint8_t> outOfStepRegion(const cardiac::HeartSimulation& sim) {
  const cardiac::CycleSettings& cycle = sim.scenario().cycle;
  if (!sim.hasHeart() || !cycle.enabled || cycle.pattern != cardiac::BeatPattern::Inconsistent) return {};
  const cardiac::LvModel& model = sim.model();
  std::vector<std::uint8_t> flags(model.mesh.vertices.size(), 0);
  for (std::size_t v = 0; v < flags.size(); ++v)
    flags[v] = model.region[v] == cardiac::Region::Myocardium &&
               std::find(cycle.inconsistentSegments.begin(), cycle.inconsistentSegments.end(),
                         int(model.segment[v])) != cycle.inconsistentSegments.end();
  return flags;
}

std::vector<std::uint8_t> chosenBeatingRegion(const cardiac::HeartSimulation& sim) {
  const cardiac::CycleSettings& cycle = sim.scenario().cycle;
  const bool chosen = !cycle.segments.empty() || !cycle.vertices.empty() || cycle.sphereEnabled;
  if (!sim.hasHeart() || !cycle.enabled || !chosen) return {};
  std::vector<std::uint8_t> flags(sim.model().mesh.vertices.size(), 0);
  for (const cardiac::Index v : cardiac::selectBeatingVertices(cycle, sim.model())) flags[v] = 1;
  return flags;
}

Vec3f speedColour(double fraction) {
  static const Vec3f kStops[] = {{0.16f, 0.30f, 0.85f}, {0.10f, 0.68f, 0.88f}, {0.30f, 0.80f, 0.42f},
                                 {0.98f, 0.86f, 0.18f}};
  constexpr int kSegments = 3;
  const double t = std::clamp(std::isfinite(fraction) ? fraction : 1.0, 0.0, 1.0) * kSegments;
  const int i = std::min(int(t), kSegments - 1);
  const float u = float(t - i);
  return kStops[i] * (1 - u) + kStops[i + 1] * u;
}

viz::Rgb toRgb(const Vec3f& c) {
  auto byte = [](float v) { return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255)); };
  return {byte(c.x()), byte(c.y()), byte(c.z())};
}

namespace {

// The height blood can fall through: the heart's (apex to the vessels' far ends), else the
// start block's.
double fallHeight(const cardiac::Scenario& scenario) {
  const auto& model = scenario.geometry;
  const double heartHeight = double(model.endoLongAxis + model.wallThickness + model.baseThickness +
                                    std::max(model.inflowVesselLength, model.outflowVesselLength));
  return std::max(scenario.heart ? heartHeight : double(scenario.blood.blockMax.y() - scenario.blood.blockMin.y()),
                  1e-6);
}

// Up to 1, 1.5, 2, 3, 4, 5, 6 or 8 times a power of ten.
double roundUpNicely(double v) {
  const double decade = std::pow(10.0, std::floor(std::log10(v)));
  for (double m : {1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0, 8.0})
    if (m * decade >= v * (1 - 1e-9)) return m * decade;
  return 10 * decade;
}

}  // namespace

double defaultPressureScale(const cardiac::Scenario& scenario) {
  const double g = std::max(double(scenario.simulation.gravity.norm()), 1e-6);
  return roundUpNicely(4 * double(scenario.blood.restDensity) * g * fallHeight(scenario) / cardiac::kPascalPerMmHg);
}

Vec3f originColour(cardiac::FlowRegion origin) {
  switch (origin) {
    case cardiac::FlowRegion::InflowVessel: return Vec3f(0.15f, 0.35f, 0.95f);
    case cardiac::FlowRegion::Ventricle: return Vec3f(0.75f, 0.35f, 0.95f);
    case cardiac::FlowRegion::Parked: return Vec3f(0.2f, 0.8f, 0.3f);
    default: return Vec3f(0.6f, 0.6f, 0.65f);
  }
}

Vec3f componentColour(cardiac::FlowComponent component) {
  switch (component) {
    case cardiac::FlowComponent::Direct: return Vec3f(0.1f, 0.72f, 0.2f);
    case cardiac::FlowComponent::RetainedInflow: return Vec3f(0.15f, 0.35f, 0.95f);
    case cardiac::FlowComponent::DelayedEjection: return Vec3f(0.98f, 0.85f, 0.1f);
    case cardiac::FlowComponent::Residual: return Vec3f(0.85f, 0.08f, 0.08f);
    case cardiac::FlowComponent::None: break;
  }
  return Vec3f(0.78f, 0.78f, 0.8f);
}

Vec3f stayColour(cardiac::Stay stay) {
  switch (stay) {
    case cardiac::Stay::OverThreeBeats: return Vec3f(0.7f, 0.05f, 0.1f);
    case cardiac::Stay::UpToThreeBeats: return Vec3f(0.55f, 0.75f, 0.98f);
    case cardiac::Stay::Outside: break;
  }
  return Vec3f(0.78f, 0.78f, 0.8f);
}

double defaultSpeedScale(const cardiac::Scenario& scenario) {
  const double g = std::max(double(scenario.simulation.gravity.norm()), 1e-6);
  return roundUpNicely(std::sqrt(2 * g * fallHeight(scenario)));
}

double colourScaleMax(const SceneOptions& options, const cardiac::Scenario& scenario) {
  switch (options.bloodColour) {
    case BloodColour::Speed: return options.speedMax > 0 ? options.speedMax : defaultSpeedScale(scenario);
    case BloodColour::Pressure: return options.pressureMax > 0 ? options.pressureMax : defaultPressureScale(scenario);
    case BloodColour::Origin:
    case BloodColour::Components:
    case BloodColour::Stay: return 0;
  }
  return 0;
}

Box sceneBounds(const cardiac::HeartSimulation& sim) {
  const auto& s = sim.scenario();
  Box box{Vec3f::Constant(INFINITY), Vec3f::Constant(-INFINITY)};
  auto add = [&](const pbd::Vec3& p) {
    box.min = box.min.cwiseMin(toVec3f(p));
    box.max = box.max.cwiseMax(toVec3f(p));
  };
  if (sim.hasHeart())
    for (const auto& v : sim.model().mesh.vertices) add(v);
  if (s.container.enabled) {
    add(s.container.min);
    add(s.container.max);
  }
  if (!sim.hasHeart() && !s.container.enabled && sim.hasBlood()) {
    add(s.blood.blockMin);
    add(s.blood.blockMax);
  }
  if (!(box.min.array() <= box.max.array()).all()) box = Box{Vec3f::Constant(-1), Vec3f::Constant(1)};
  return box;
}

Scene buildScene(const cardiac::HeartSimulation& sim, const SceneOptions& options) {
  Scene scene;
  scene.bounds = sceneBounds(sim);
  const auto& s = sim.scenario();
  if (sim.hasHeart()) {
    addWall(sim, options.beating ? *options.beating : chosenBeatingRegion(sim),
            options.markOutOfStep ? outOfStepRegion(sim) : std::vector<std::uint8_t>(), scene.wall);
    scene.wall.opacity = std::clamp(options.wallOpacity, 0.05f, 1.0f);
    if (options.valves) addValveLeaflets(sim, scene.valves);
  }
  if (options.clip) {
    scene.clip.enabled = true;
    scene.clip.normal = Vec3f(0, 0, 1);
    scene.clip.offset = -options.clipZ;
  }
  if (s.container.enabled) scene.lines.points = boxEdges(toVec3f(s.container.min), toVec3f(s.container.max));
  if (sim.hasBlood()) {
    const double scaleMax = colourScaleMax(options, s);
    scene.particles.radius = float(s.blood.radius);
    scene.particles.opacity = std::clamp(options.bloodOpacity, 0.05f, 1.0f);
    scene.particles.look = options.bloodLook;
    scene.particles.liquidDownsample = options.liquidDownsample;
    scene.clip.clipParticles = true;
    // Speed and pressure from the SPH-smoothed field (blood_field.h), not per particle.
    const BloodField field = smoothedBlood(sim);
    scene.particles.centres = field.position;
    const std::size_t blood = sim.particles().size() - sim.firstBloodParticle();
    const bool tagged = options.components && options.components->size() == blood;
    const bool stayed = options.stays && options.stays->size() == blood;
    auto identity = [&](pbd::Index i) { return std::size_t(sim.particles().id[i] - sim.firstBloodParticle()); };
    for (std::size_t k = 0; k < field.particle.size(); ++k) {
      switch (options.bloodColour) {
        case BloodColour::Speed:
          scene.particles.colours.push_back(field.vesselEnd[k] ? kVesselEndColour
                                                               : speedColour(double(field.velocity[k].norm()) / scaleMax));
          break;
        case BloodColour::Pressure:
          scene.particles.colours.push_back(speedColour(double(field.pressure[k]) / cardiac::kPascalPerMmHg / scaleMax));
          break;
        case BloodColour::Origin:
          scene.particles.colours.push_back(originColour(sim.bloodOrigin(field.particle[k])));
          break;
        case BloodColour::Components:
          scene.particles.colours.push_back(componentColour(
              tagged ? (*options.components)[identity(field.particle[k])] : cardiac::FlowComponent::None));
          break;
        case BloodColour::Stay:
          scene.particles.colours.push_back(
              stayColour(stayed ? (*options.stays)[identity(field.particle[k])] : cardiac::Stay::Outside));
          break;
      }
    }
    if (options.flow != FlowView::Off) {
      // The lines carry the speed colours; the blood is a pale backdrop behind them.
      const double speedMax = options.speedMax > 0 ? options.speedMax : defaultSpeedScale(s);
      scene.particles.colours.assign(scene.particles.centres.size(), kFlowBackdropColour);
      scene.particles.opacity = std::min(scene.particles.opacity, kFlowBackdropOpacity);
      if (options.flow == FlowView::Streaks && options.pathlines)
        addStreaks(scene.flow, *options.pathlines, speedMax, options.flowLineWidth);
      if (options.flow == FlowView::Arrows)
        addArrows(scene.flow, field.position, field.velocity, speedMax, options.flowLineWidth);
    }
  }
  return scene;
}

std::vector<std::size_t> drawnBloodIdentities(const cardiac::HeartSimulation& sim) {
  std::vector<std::size_t> identities;
  if (!sim.hasBlood()) return identities;
  // smoothedBlood's order: the active blood particles in storage order.
  for (std::size_t i = sim.firstBloodParticle(); i < sim.particles().size(); ++i)
    if (sim.bloodActive(pbd::Index(i))) identities.push_back(std::size_t(sim.particles().id[i] - sim.firstBloodParticle()));
  return identities;
}

void colourByComponent(Scene& scene, std::span<const std::size_t> identities,
                       std::span<const cardiac::FlowComponent> components) {
  assert(identities.size() == scene.particles.centres.size());
  scene.particles.colours.resize(identities.size());
  for (std::size_t k = 0; k < identities.size(); ++k)
    scene.particles.colours[k] = componentColour(
        identities[k] < components.size() ? components[identities[k]] : cardiac::FlowComponent::None);
}

void applyView(Scene& scene, const SceneOptions& options, View view) {
  const float opacity = std::clamp(options.wallOpacity, 0.05f, 1.0f);
  const bool facing = std::abs(viewDirection(view).dot(scene.clip.normal)) >= 0.5f;
  scene.clip.enabled = options.clip && facing;
  scene.wall.opacity = options.clip && !facing && !scene.particles.centres.empty() ? std::min(opacity, 0.45f) : opacity;
}

const char* bloodColourName(BloodColour colour) {
  switch (colour) {
    case BloodColour::Speed: return "speed";
    case BloodColour::Pressure: return "pressure";
    case BloodColour::Origin: return "origin";
    case BloodColour::Components: return "components";
    case BloodColour::Stay: return "stay";
  }
  return "";
}

std::optional<BloodColour> parseBloodColour(std::string_view name) {
  for (const BloodColour c : {BloodColour::Speed, BloodColour::Pressure, BloodColour::Origin, BloodColour::Components,
                              BloodColour::Stay})
    if (name == bloodColourName(c)) return c;
  return std::nullopt;
}

const char* bloodLookName(BloodLook look) { return look == BloodLook::Liquid ? "liquid" : "spheres"; }

std::optional<BloodLook> parseBloodLook(std::string_view name) {
  for (const BloodLook look : {BloodLook::Liquid, BloodLook::Spheres})
    if (name == bloodLookName(look)) return look;
  return std::nullopt;
}

const char* flowViewName(FlowView flow) {
  switch (flow) {
    case FlowView::Off: return "off";
    case FlowView::Streaks: return "streaks";
    case FlowView::Arrows: return "arrows";
  }
  return "";
}

std::optional<FlowView> parseFlowView(std::string_view name) {
  for (const FlowView flow : {FlowView::Off, FlowView::Streaks, FlowView::Arrows})
    if (name == flowViewName(flow)) return flow;
  return std::nullopt;
}

std::span<const OriginKeyRow> originKey() {
  static constexpr OriginKeyRow kRows[] = {{cardiac::FlowRegion::InflowVessel, "in the inflow vessel", "blue"},
                                           {cardiac::FlowRegion::Ventricle, "in the ventricle", "violet"},
                                           {cardiac::FlowRegion::Parked, "outside: entered through the loop", "green"}};
  return kRows;
}

std::span<const ComponentKeyRow> componentKey() {
  using cardiac::FlowComponent;
  static constexpr ComponentKeyRow kRows[] = {
      {FlowComponent::Direct, "direct flow: in and out in one beat", "green", "direct flow"},
      {FlowComponent::RetainedInflow, "retained inflow: came in, stays", "blue", "retained inflow"},
      {FlowComponent::DelayedEjection, "delayed ejection: was there, leaves", "yellow", "delayed ejection"},
      {FlowComponent::Residual, "residual: was there, stays", "red", "residual volume"},
      {FlowComponent::None, "not in the ventricle at end-diastole", "grey", "not in at end-diastole"}};
  return kRows;
}

std::span<const StayKeyRow> stayKey() {
  static constexpr StayKeyRow kRows[] = {{cardiac::Stay::OverThreeBeats, "in the ventricle over 3 beats", "dark red"},
                                         {cardiac::Stay::UpToThreeBeats, "in the ventricle up to 3 beats", "pale blue"},
                                         {cardiac::Stay::Outside, "outside the ventricle", "grey"}};
  return kRows;
}

namespace {

// A key's frame in the image's lower right corner, text scaled with the image: a pale box of
// the given content size plus margins, with its title; returns the content's top left.
struct KeyLayout {
  int scale, margin, line, capHalf;
  explicit KeyLayout(const viz::Image& image)
      : scale(std::max(1, std::min(image.width(), image.height()) / 300)),
        margin(8 * scale),
        line(viz::Image::lineHeight(scale)),
        capHalf(viz::Image::capHeight(scale) / 2) {}
};
constexpr viz::Rgb kInk{40, 40, 50};

// The key's box in the lower right corner, its title drawn; `box` is where it is. Returns where
// its content begins.
std::array<int, 2> drawKeyBox(viz::Image& image, const KeyLayout& k, const std::string& title, int contentWidth,
                              int contentHeight, viz::Rect& box) {
  const int boxWidth = std::max(contentWidth, viz::Image::textWidth(title, k.scale)) + 2 * k.margin;
  const int boxHeight = k.line + contentHeight + 2 * k.margin;
  const int x0 = image.width() - boxWidth - k.margin, y0 = image.height() - boxHeight - k.margin;
  box = {x0, y0, boxWidth, boxHeight};
  image.fillRect({x0, y0, boxWidth, boxHeight}, {250, 250, 252});
  image.strokeRect({x0, y0, boxWidth, boxHeight}, {150, 155, 165});
  image.drawText(x0 + k.margin, y0 + k.margin, title, k.scale, kInk);
  return {x0 + k.margin, y0 + k.margin + k.line};
}

// One swatch and label per row, one line each: (colour, label) pairs under a title.
void drawSwatchKey(viz::Image& image, const KeyLayout& k, const std::string& title,
                   const std::vector<std::pair<Vec3f, const char*>>& rows, viz::Rect& box) {
  const int swatch = viz::Image::capHeight(k.scale) + 2 * k.scale, gap = 4 * k.scale;
  int width = 0;
  for (const auto& [colour, label] : rows) width = std::max(width, swatch + gap + viz::Image::textWidth(label, k.scale));
  auto [x, y] = drawKeyBox(image, k, title, width, int(rows.size()) * k.line, box);
  for (const auto& [colour, label] : rows) {
    image.fillRect({x, y + k.capHalf - swatch / 2, swatch, swatch}, toRgb(colour));
    image.drawText(x + swatch + gap, y, label, k.scale, kInk);
    y += k.line;
  }
}

void drawOriginKey(viz::Image& image, const KeyLayout& k, viz::Rect& box) {
  std::vector<std::pair<Vec3f, const char*>> rows;
  for (const OriginKeyRow& row : originKey()) rows.emplace_back(originColour(row.origin), row.label);
  drawSwatchKey(image, k, "blood by where it started", rows, box);
}

// The colour bar from 0 (bottom) to scaleMax (top), labelled at both ends and the middle.
void drawScaleBar(viz::Image& image, const KeyLayout& k, const std::string& title, double scaleMax, viz::Rect& box) {
  const int barWidth = 18 * k.scale, barHeight = std::min(image.height() / 4, 90 * k.scale);
  char top[32], mid[32];
  std::snprintf(top, sizeof top, "%g", scaleMax);
  std::snprintf(mid, sizeof mid, "%g", scaleMax / 2);
  const int labelWidth = viz::Image::textWidth(top, k.scale) + 4 * k.scale;
  const auto [barX, titleEnd] = drawKeyBox(image, k, title, barWidth + labelWidth, barHeight + k.margin, box);
  const int barY = titleEnd + k.margin;
  for (int row = 0; row < barHeight; ++row)
    image.fillRect({barX, barY + row, barWidth, 1}, toRgb(speedColour(1.0 - double(row) / double(barHeight - 1))));
  image.strokeRect({barX, barY, barWidth, barHeight}, {90, 90, 100});
  const int textX = barX + barWidth + 4 * k.scale;
  image.drawText(textX, barY - k.capHalf, top, k.scale, kInk);
  image.drawText(textX, barY + barHeight / 2 - k.capHalf, mid, k.scale, kInk);
  image.drawText(textX, barY + barHeight - 1 - k.capHalf, "0", k.scale, kInk);
}

}  // namespace

viz::Rect drawBloodLegend(viz::Image& image, BloodColour colour, double scaleMax) {
  const KeyLayout k(image);
  viz::Rect box{};
  switch (colour) {
    case BloodColour::Speed: drawScaleBar(image, k, "blood speed (m/s)", scaleMax, box); break;
    case BloodColour::Pressure: drawScaleBar(image, k, "blood pressure (mmHg)", scaleMax, box); break;
    case BloodColour::Origin: drawOriginKey(image, k, box); break;
    case BloodColour::Components: {
      std::vector<std::pair<Vec3f, const char*>> rows;
      for (const ComponentKeyRow& row : componentKey()) rows.emplace_back(componentColour(row.component), row.label);
      drawSwatchKey(image, k, "blood by flow component", rows, box);
      break;
    }
    case BloodColour::Stay: {
      std::vector<std::pair<Vec3f, const char*>> rows;
      for (const StayKeyRow& row : stayKey()) rows.emplace_back(stayColour(row.stay), row.label);
      drawSwatchKey(image, k, "blood by how long it stayed", rows, box);
      break;
    }
  }
  return box;
}

}  // namespace hs::render
