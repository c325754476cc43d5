// Framing the heart above the circulation panel: the bounds' centre lands in the middle of the
// area between the side panels and above the strip, the bounds fit its height, and showing then
// hiding the strip gives the camera back.
#include <gtest/gtest.h>

#include <algorithm>

#include "render/renderer.h"
#include "viewer/app/scene_framing.h"
#include "viewer/region/brush_selection.h"

namespace hs::viewer {
namespace {

using render::Vec3f;

render::Box testBounds() {
  render::Box box;
  box.min = Vec3f(-0.03f, -0.08f, -0.03f);
  box.max = Vec3f(0.03f, 0.04f, 0.03f);
  return box;
}

TEST(SceneFraming, TheHeartSitsInTheMiddleOfTheAreaAboveTheStrip) {
  constexpr int kWidth = 1280, kHeight = 800;
  for (const float strip : {0.0f, 320.0f}) {
    CameraController camera(testBounds(), 1);
    const SceneArea area{300, kWidth - 340.0f, strip};
    frameView(camera, render::View::Front, area, kWidth, kHeight);
    const BrushView view = brushView(camera.camera(), kWidth, kHeight);
    float x = 0, y = 0;
    ASSERT_TRUE(projectToScreen(view, testBounds().centre(), x, y));
    EXPECT_NEAR(x, (area.left + area.right) / 2, 1.0f) << "strip " << strip;
    EXPECT_NEAR(y, (kHeight - strip) / 2, 1.0f) << "strip " << strip;
    // Every corner of the bounds inside the area.
    for (int corner = 0; corner < 8; ++corner) {
      const render::Box b = testBounds();
      const Vec3f c((corner & 1) ? b.max.x() : b.min.x(), (corner & 2) ? b.max.y() : b.min.y(),
                    (corner & 4) ? b.max.z() : b.min.z());
      ASSERT_TRUE(projectToScreen(view, c, x, y));
      EXPECT_GE(x, area.left);
      EXPECT_LE(x, area.right);
      EXPECT_GE(y, 0);
      EXPECT_LE(y, kHeight - strip) << "corner " << corner << ", strip " << strip;
    }
  }
}

TEST(SceneFraming, ShowingThenHidingTheStripGivesTheCameraBack) {
  CameraController camera(testBounds(), 1.2f);
  camera.setView(render::View::Left);
  camera.orbit(40, -25, 800);
  camera.zoom(2);
  const render::Camera before = camera.camera();
  refitForStrip(camera, 0, 320, 800);
  EXPECT_GT((camera.camera().eye - before.eye).norm(), 1e-4f);
  refitForStrip(camera, 320, 0, 800);
  EXPECT_LT((camera.camera().eye - before.eye).norm(), 1e-5f);
  EXPECT_LT((camera.camera().target - before.target).norm(), 1e-5f);
}

TEST(BrushDabs, AStrokeIsCoveredEveryHalfRadiusUpToTheCursor) {
  BrushQuery query;
  query.radius = 10;
  const std::vector<BrushQuery> dabs = brushDabsAlong(query, 0, 0, 30, 40);  // 50 px long
  ASSERT_EQ(dabs.size(), 10u);
  EXPECT_FLOAT_EQ(dabs.back().centreX, 30);
  EXPECT_FLOAT_EQ(dabs.back().centreY, 40);
  EXPECT_FLOAT_EQ(dabs.front().centreX, 3);
  EXPECT_EQ(brushDabsAlong(query, 5, 5, 5, 5).size(), 1u);  // a click paints once
}

}  // namespace
}  // namespace hs::viewer
