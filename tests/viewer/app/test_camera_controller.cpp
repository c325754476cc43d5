// The viewer's mouse camera: orbit keeps the distance to the target, pan moves the target in
// the view plane, zoom scales the distance, and the view keys give the named views of
// `heartsim render` (render::viewCamera).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "render/renderer.h"
#include "viewer/app/camera_controller.h"
#include "viewer/app/viewer_app.h"

namespace hs::viewer {
namespace {

using render::Vec3f;

render::Box testBounds() {
  render::Box box;
  box.min = Vec3f(-0.3f, -0.8f, -0.25f);
  box.max = Vec3f(0.35f, 0.4f, 0.3f);
  return box;
}

void expectNear(const Vec3f& a, const Vec3f& b, float tolerance) {
  EXPECT_LT((a - b).norm(), tolerance) << "got (" << a.transpose() << "), expected (" << b.transpose() << ")";
}

TEST(CameraController, NamedViewsMatchTheOffscreenRenderersCameras) {
  for (const render::View view : render::kAllViews) {
    CameraController controller(testBounds(), 1.5f);
    controller.setView(view);
    const render::Camera got = controller.camera();
    const render::Camera want = render::viewCamera(view, testBounds(), 1.5f);
    SCOPED_TRACE(render::viewName(view));
    expectNear(got.eye, want.eye, 1e-4f);
    expectNear(got.target, want.target, 1e-5f);
    expectNear(got.up.normalized(), want.up.normalized(), 1e-5f);
    expectNear(controller.towardEye(), render::viewDirection(view), 1e-6f);
  }
}

TEST(CameraController, ResetGivesTheFrontView) {
  CameraController controller(testBounds(), 1.0f);
  controller.orbit(123, -45, 600);
  controller.pan(30, 20, 600);
  controller.zoom(3);
  controller.reset();
  const render::Camera want = render::viewCamera(render::View::Front, testBounds(), 1.0f);
  expectNear(controller.camera().eye, want.eye, 1e-4f);
  expectNear(controller.camera().target, want.target, 1e-5f);
}

TEST(CameraController, OrbitKeepsTheDistanceToTheTarget) {
  CameraController controller(testBounds(), 1.0f);
  const float distance = controller.distance();
  const Vec3f target = controller.target();
  for (const auto& [dx, dy] :
       {std::pair{40.0f, 0.0f}, {0.0f, 75.0f}, {-300.0f, 420.0f}, {1000.0f, -2000.0f}}) {
    controller.orbit(dx, dy, 600);
    const render::Camera c = controller.camera();
    EXPECT_NEAR((c.eye - c.target).norm(), distance, 1e-5f * distance);
    expectNear(c.target, target, 1e-6f);
    // The up vector stays a unit vector perpendicular to the line of sight.
    EXPECT_NEAR(c.up.norm(), 1.0f, 1e-5f);
    EXPECT_NEAR(c.up.dot((c.eye - c.target).normalized()), 0.0f, 1e-5f);
  }
}

TEST(CameraController, OrbitTurnsAboutTheVerticalAndTilts) {
  CameraController controller(testBounds(), 1.0f);
  // A drag across the window height turns by 180 degrees; half of it to the right by 90:
  // the eye moves from the front (+z) to the left side (-x).
  controller.orbit(300, 0, 600);
  expectNear(controller.towardEye(), render::viewDirection(render::View::Left), 1e-5f);
  controller.reset();
  controller.orbit(0, 300, 600);  // dragging down by half the height: looking from the top
  expectNear(controller.towardEye(), render::viewDirection(render::View::Top), 1e-5f);
  controller.orbit(0, 300, 600);  // no further than straight down
  EXPECT_FLOAT_EQ(controller.pitchDegrees(), CameraController::kMaxPitchDegrees);
}

TEST(CameraController, PanMovesTheTargetInTheViewPlane) {
  for (const render::View view : render::kAllViews) {
    SCOPED_TRACE(render::viewName(view));
    CameraController controller(testBounds(), 1.0f);
    controller.setView(view);
    controller.orbit(57, -33, 600);  // any orientation
    const render::Camera before = controller.camera();
    const Vec3f line = (before.eye - before.target).normalized();
    controller.pan(80, -25, 600);
    const render::Camera after = controller.camera();
    const Vec3f moved = after.target - before.target;
    EXPECT_GT(moved.norm(), 0.0f);
    EXPECT_NEAR(moved.dot(line), 0.0f, 1e-5f);                                // in the view plane
    expectNear(after.eye - after.target, before.eye - before.target, 1e-5f);  // same orientation, distance
    // Dragging right moves the scene right: the target moves to the left on the screen.
    EXPECT_LT(moved.dot(controller.right()), 0.0f);
    // Dragging up (dy < 0) moves the scene up: the target moves down.
    EXPECT_LT(moved.dot(controller.up()), 0.0f);
  }
}

TEST(CameraController, PanFollowsTheCursorAtTheTargetsDepth) {
  CameraController controller(testBounds(), 1.0f);
  const Vec3f point = controller.target();
  const render::Vec3f before = controller.camera().project(point, 600, 600);
  controller.pan(50, 20, 600);
  const render::Vec3f after = controller.camera().project(point, 600, 600);
  EXPECT_NEAR(after.x() - before.x(), 50.0f, 0.05f);
  EXPECT_NEAR(after.y() - before.y(), 20.0f, 0.05f);
}

TEST(CameraController, ZoomScalesTheDistance) {
  CameraController controller(testBounds(), 1.0f);
  const float distance = controller.distance();
  const Vec3f target = controller.target();
  controller.zoom(1);
  EXPECT_NEAR(controller.distance(), 0.9f * distance, 1e-6f * distance);
  controller.zoom(-2);
  EXPECT_NEAR(controller.distance(), distance / 0.9f, 1e-5f * distance);
  expectNear(controller.target(), target, 1e-7f);
  controller.zoom(1000);
  EXPECT_NEAR(controller.distance(), CameraController::kMinDistanceFraction * distance, 1e-5f * distance);
  controller.zoom(-10000);
  EXPECT_NEAR(controller.distance(), CameraController::kMaxDistanceFraction * distance, 1e-3f * distance);
}

TEST(CameraController, ClipPlanesKeepTheSceneInView) {
  CameraController controller(testBounds(), 1.0f);
  for (const float steps : {0.0f, 5.0f, 20.0f, -20.0f}) {
    controller.zoom(steps);
    const render::Camera c = controller.camera();
    EXPECT_GT(c.nearPlane, 0.0f);
    EXPECT_LT(c.nearPlane, c.farPlane);
    const float d = (c.eye - testBounds().centre()).norm();
    const float radius = (testBounds().max - testBounds().min).norm() / 2;
    EXPECT_GE(c.farPlane, d + radius);
  }
}

}  // namespace
}  // namespace hs::viewer
