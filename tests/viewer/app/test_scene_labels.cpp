// The anatomy's names on the scene: one for each place a student asks about, anchored where
// that place is now (the orifices' rings, the vessels' ends, the apex), with arrows the way
// blood flows forward, and projected where the front view shows them (inflow on the left).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "cardiac/heart_simulation.h"
#include "io/scenario/scenario_file.h"
#include "normal_geometry.h"
#include "render/scene.h"
#include "viewer/app/camera_controller.h"
#include "viewer/app/scene_labels.h"

namespace hs::viewer {
namespace {

using render::Vec3f;

const SceneLabel& named(const std::vector<SceneLabel>& labels, const std::string& prefix) {
  const auto found = std::find_if(labels.begin(), labels.end(),
                                  [&](const SceneLabel& l) { return l.text.starts_with(prefix); });
  if (found == labels.end()) throw std::runtime_error("no label " + prefix);
  return *found;
}

TEST(SceneLabels, NameTheInflowTheValvesTheAortaAndTheApexWhereTheyAre) {
  const cardiac::Scenario scenario;  // the thesis-scale heart
  const cardiac::HeartSimulation sim(scenario, 1);
  const std::vector<SceneLabel> labels = anatomyLabels(sim);
  ASSERT_EQ(labels.size(), 7u);
  const cardiac::FlowPath& path = sim.model().flowPath;
  const SceneLabel& mitral = named(labels, "mitral");
  const SceneLabel& aortic = named(labels, "aortic");
  EXPECT_LT((mitral.anchor - path.mitral.centre.cast<float>()).norm(), 0.05f * float(path.mitral.radius));
  EXPECT_LT((aortic.anchor - path.aortic.centre.cast<float>()).norm(), 0.05f * float(path.aortic.radius));
  // The inflow's arrow points down its vessel into the heart, the aorta's up and out.
  const SceneLabel& inflow = named(labels, "from the left atrium");
  const SceneLabel& aorta = named(labels, "to the aorta");
  EXPECT_TRUE(inflow.flowsIn);
  EXPECT_LT(inflow.flow.y(), 0);
  EXPECT_FALSE(aorta.flowsIn);
  EXPECT_GT(aorta.flow.y(), 0);
  EXPECT_LT(inflow.anchor.x(), 0) << "the inflow vessel is on the mitral side, -x";
  EXPECT_GT(aorta.anchor.x(), 0);
  EXPECT_GT(inflow.anchor.y(), mitral.anchor.y()) << "up its vessel, above the valve";
  // The apex is the wall's lowest point.
  const SceneLabel& apex = named(labels, "apex");
  for (const auto& x : sim.particles().position) EXPECT_GE(x.y(), apex.anchor.y() - 1e-5);
}

// An anatomical heart's atrium and aortic root get their own names, inside their bulges, the
// atrium over the mitral valve and the root over the aortic one; straight vessels get none.
TEST(SceneLabels, AnAtriumAndAnAorticRootAreNamedInTheirBulges) {
  const cardiac::HeartSimulation sim(io::loadScenario("normal"), 1);
  const std::vector<SceneLabel> labels = anatomyLabels(sim);
  ASSERT_EQ(labels.size(), 9u);
  const cardiac::FlowPath& path = sim.model().flowPath;
  const SceneLabel& atrium = named(labels, "left atrium");
  const SceneLabel& root = named(labels, "aortic root");
  const cardiac::Orifice atriumSection = path.inflowSection(atrium.anchor.y());
  const cardiac::Orifice rootSection = path.outflowSection(root.anchor.y());
  EXPECT_LT(atriumSection.radial(atrium.anchor.cast<pbd::Real>()), atriumSection.radius) << "inside the atrium";
  EXPECT_LT(rootSection.radial(root.anchor.cast<pbd::Real>()), rootSection.radius) << "inside the root";
  EXPECT_GT(atrium.anchor.y(), path.mitral.centre.y());
  EXPECT_GT(root.anchor.y(), path.aortic.centre.y());
  EXPECT_LT(atrium.anchor.x(), root.anchor.x()) << "the atrium on the inflow's side";
  cardiac::Scenario straight = io::loadScenario("normal");
  straight.geometry = cardiac::testing::withStraightVessels(straight.geometry);
  EXPECT_EQ(anatomyLabels(cardiac::HeartSimulation(straight, 1)).size(), 7u);
}

TEST(SceneLabels, NoHeartNoLabels) {
  const cardiac::Scenario scenario = io::loadScenario("dam-break");
  ASSERT_FALSE(scenario.heart);
  EXPECT_TRUE(anatomyLabels(cardiac::HeartSimulation(scenario, 1)).empty());
}

TEST(SceneLabels, TheFrontViewShowsTheInflowOnTheLeftAndNothingBehindTheEye) {
  const cardiac::Scenario scenario;
  const cardiac::HeartSimulation sim(scenario, 1);
  const std::vector<SceneLabel> labels = anatomyLabels(sim);
  render::Box bounds;
  bounds.min = Vec3f(-3, -5, -3), bounds.max = Vec3f(3, 3, 3);
  CameraController controller(bounds, 1);
  controller.setView(render::View::Front);
  const render::Camera& camera = controller.camera();
  const ProjectedLabel mitral = projectLabel(named(labels, "mitral"), camera, 1280, 800);
  const ProjectedLabel aortic = projectLabel(named(labels, "aortic"), camera, 1280, 800);
  const ProjectedLabel inflow = projectLabel(named(labels, "from the left atrium"), camera, 1280, 800);
  ASSERT_TRUE(mitral.onScreen && aortic.onScreen && inflow.onScreen);
  EXPECT_LT(mitral.x, aortic.x);
  // The inflow's arrow points down the screen (y grows downwards), ending at its anchor.
  ASSERT_TRUE(inflow.hasArrow);
  EXPECT_GT(inflow.arrowToY, inflow.arrowFromY);
  EXPECT_NEAR(inflow.arrowToX, inflow.x, 1e-3f);
  // A point behind the eye is not drawn.
  SceneLabel behind = named(labels, "apex");
  behind.anchor = camera.eye + (camera.eye - camera.target);
  EXPECT_FALSE(projectLabel(behind, camera, 1280, 800).onScreen);
}

}  // namespace
}  // namespace hs::viewer

namespace hs::viewer {
namespace {

// The two names the pictures issue added: the left ventricle inside the cavity, the septum on
// the side the model's AHA septal segments are (its data, not a fixed side), and none at all
// for the label set "off".
TEST(SceneLabels, TheVentricleAndTheSeptumComeFromTheModelsSegments) {
  const cardiac::Scenario scenario;
  const cardiac::HeartSimulation sim(scenario, 1);
  const std::vector<SceneLabel> labels = anatomyLabels(sim);
  const SceneLabel& ventricle = named(labels, "left ventricle");
  const SceneLabel& septum = named(labels, "septum");
  const cardiac::LvModel& model = sim.model();
  double septalX = 0;
  int count = 0;
  for (std::size_t v = 0; v < model.segment.size(); ++v)
    if (model.segment[v] == 2 || model.segment[v] == 3 || model.segment[v] == 8 || model.segment[v] == 9 ||
        model.segment[v] == 14)
      septalX += double(sim.particles().position[v].x()), ++count;
  ASSERT_GT(count, 0);
  EXPECT_EQ(septum.anchor.x() < ventricle.anchor.x(), septalX / count < double(ventricle.anchor.x()));
  EXPECT_EQ(model.flowPath.classify(ventricle.anchor.cast<pbd::Real>(), 0, 0), cardiac::FlowRegion::Ventricle);
  EXPECT_TRUE(render::anatomyLabels(sim, render::LabelSet::Off).empty());
  EXPECT_EQ(render::parseLabelSet("anatomy"), render::LabelSet::Anatomy);
  EXPECT_FALSE(render::parseLabelSet("all"));
}

// Drawn into an image, every label leaves ink near its anchor's projection.
TEST(SceneLabels, RenderDrawsThemIntoTheImage) {
  const cardiac::Scenario scenario;
  const cardiac::HeartSimulation sim(scenario, 1);
  const std::vector<SceneLabel> labels = anatomyLabels(sim);
  const render::Camera camera = render::viewCamera(render::View::Front, render::sceneBounds(sim), 4.0f / 3);
  viz::Image image(400, 300);
  image.fill({200, 200, 200});
  render::drawLabels(image, labels, camera);
  for (const SceneLabel& label : labels) {
    const ProjectedLabel p = projectLabel(label, camera, 400, 300);
    ASSERT_TRUE(p.onScreen) << label.text;
    const viz::Rgb at = image.at(std::clamp(int(p.x), 0, 399), std::clamp(int(p.y), 0, 299));
    EXPECT_LT(int(at.r) + at.g + at.b, 3 * 150) << label.text << ": the anchor's dot";
  }
}

// The colour key in the lower right corner: no name's box is drawn over it, and the same names
// drawn without the key do cover it. The heart's own names, and one more named at the scene's
// lower right corner, where the key is: it must move.
TEST(SceneLabels, NoNameCoversTheColourKey) {
  const cardiac::HeartSimulation sim(io::loadScenario("normal"), 1);
  std::vector<SceneLabel> labels = anatomyLabels(sim);
  const render::Box bounds = render::sceneBounds(sim);
  SceneLabel corner;
  corner.text = "lower right";
  corner.anchor = Vec3f(bounds.max.x(), bounds.min.y(), bounds.centre().z());
  corner.side = LabelSide::Right;
  labels.push_back(corner);
  const render::Camera camera = render::viewCamera(render::View::Front, bounds, 4.0f / 3);
  viz::Image scratch(800, 600);
  const viz::Rect key = render::drawBloodLegend(scratch, render::BloodColour::Speed, 2.0);
  ASSERT_GT(key.width * key.height, 100 * 100);
  auto paperIn = [&](const viz::Image& image) {  // the names' boxes are pure white, the rest grey
    int n = 0;
    for (int y = key.y; y < key.y + key.height; ++y)
      for (int x = key.x; x < key.x + key.width; ++x) n += image.at(x, y) == viz::Rgb{255, 255, 255};
    return n;
  };
  viz::Image avoided(800, 600), covered(800, 600);
  avoided.fill({200, 200, 200});
  covered.fill({200, 200, 200});
  render::drawLabels(avoided, labels, camera, {key});
  render::drawLabels(covered, labels, camera);
  EXPECT_GT(paperIn(covered), 100) << "the test must put a name where the key is";
  EXPECT_EQ(paperIn(avoided), 0);
}

// Seen from the side the atrium and the aortic root lie one behind the other, on the heart's
// column: their names split to its two sides by the side they have seen from the front (the
// inflow's on one, the outflow's on the other) instead of stacking in one column whose leader
// lines cross.
TEST(SceneLabels, ASideViewSplitsTheNamesToBothSidesOfTheHeart) {
  const cardiac::HeartSimulation sim(io::loadScenario("normal"), 1);
  const std::vector<SceneLabel> labels = anatomyLabels(sim);
  const render::Camera camera = render::viewCamera(render::View::Left, render::sceneBounds(sim), 4.0f / 3);
  viz::Image image(800, 600);
  image.fill({200, 200, 200});
  render::drawLabels(image, labels, camera);
  float column = 0;
  for (const SceneLabel& label : labels) column += projectLabel(label, camera, 800, 600).x;
  column /= float(labels.size());
  int left = 0, right = 0;  // the names' pure white paper either side of the column
  for (int y = 0; y < 600; ++y)
    for (int x = 0; x < 800; ++x)
      if (image.at(x, y) == viz::Rgb{255, 255, 255}) (float(x) < column ? left : right) += 1;
  std::printf("paper left of the heart %d px, right %d px\n", left, right);
  EXPECT_GT(left, right / 3);
  EXPECT_GT(right, left / 3);
}

}  // namespace
}  // namespace hs::viewer
