// Offscreen rendering through EGL with no display (run with DISPLAY unset): the expected
// colours appear at the expected pixels.
#include <gtest/gtest.h>

#include <cstdlib>

#include "render/gl_context.h"
#include "render/renderer.h"
#include "render/scene.h"

namespace {

using hs::render::Vec3f;
using hs::viz::Rgb;

class Offscreen : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { unsetenv("DISPLAY"); }
  hs::render::GlContext gl;
  hs::render::FrameTarget target{160, 120};
  hs::render::Renderer renderer;

  hs::viz::Image draw(const hs::render::Scene& scene, hs::render::View view) {
    target.bind();
    renderer.draw(scene, hs::render::viewCamera(view, scene.bounds, 160.0f / 120.0f), 160, 120);
    return target.read();
  }
};

hs::render::Scene emptyScene() {
  hs::render::Scene scene;
  scene.bounds = {Vec3f(-1, -1, -1), Vec3f(1, 1, 1)};
  scene.backgroundTop = scene.backgroundBottom = Vec3f(1, 1, 1);
  return scene;
}

// A large triangle facing +z at z = 0, in one colour.
void addTriangle(hs::render::Scene& scene, const Vec3f& colour) {
  for (const Vec3f& p : {Vec3f(-1, -1, 0), Vec3f(1, -1, 0), Vec3f(0, 1, 0)}) {
    scene.wall.positions.push_back(p);
    scene.wall.normals.push_back(Vec3f(0, 0, 1));
    scene.wall.colours.push_back(colour);
  }
}

TEST_F(Offscreen, ContextIsCreatedWithoutADisplay) {
  EXPECT_FALSE(gl.description().empty());
  EXPECT_EQ(std::getenv("DISPLAY"), nullptr);
}

TEST_F(Offscreen, BackgroundGradientRunsFromTopToBottom) {
  hs::render::Scene scene = emptyScene();
  scene.backgroundTop = Vec3f(1, 0, 0);
  scene.backgroundBottom = Vec3f(0, 0, 1);
  const hs::viz::Image image = draw(scene, hs::render::View::Front);
  EXPECT_GT(image.at(80, 1).r, 240);
  EXPECT_LT(image.at(80, 1).b, 15);
  EXPECT_GT(image.at(80, 118).b, 240);
}

TEST_F(Offscreen, LitTriangleAppearsInItsColourAtTheCentre) {
  hs::render::Scene scene = emptyScene();
  addTriangle(scene, Vec3f(0.9f, 0.1f, 0.1f));
  const hs::viz::Image image = draw(scene, hs::render::View::Front);
  const Rgb centre = image.at(80, 70);
  EXPECT_GT(centre.r, 150);
  EXPECT_LT(centre.g, 100);
  EXPECT_EQ(image.at(2, 2), (Rgb{255, 255, 255}));  // background in the corner
  // Seen from behind (no front faces toward the camera), the triangle shows the cut colour.
  hs::render::Scene back = scene;
  back.wall.cutColour = Vec3f(0, 0.8f, 0);
  std::swap(back.wall.positions[0], back.wall.positions[1]);
  const Rgb cut = draw(back, hs::render::View::Front).at(80, 70);
  EXPECT_GT(cut.g, 150);
  EXPECT_LT(cut.r, 60);
}

TEST_F(Offscreen, ClippingPlaneRemovesTheCutAwaySide) {
  hs::render::Scene scene = emptyScene();
  addTriangle(scene, Vec3f(0.9f, 0.1f, 0.1f));
  scene.clip.enabled = true;
  scene.clip.normal = Vec3f(1, 0, 0);  // removes x > 0.1: the right part of the front view
  scene.clip.offset = -0.1f;
  const hs::viz::Image image = draw(scene, hs::render::View::Front);
  EXPECT_GT(image.at(70, 80).r, 150);
  EXPECT_LT(image.at(70, 80).g, 100);
  EXPECT_EQ(image.at(95, 80), (Rgb{255, 255, 255}));
}

TEST_F(Offscreen, ParticlesAreShadedSpheresThatHideWhatIsBehind) {
  hs::render::Scene scene = emptyScene();
  addTriangle(scene, Vec3f(0.9f, 0.1f, 0.1f));
  scene.particles.radius = 0.3f;
  scene.particles.centres = {Vec3f(0, 0, 0.5f)};  // in front of the triangle
  scene.particles.colours = {Vec3f(0.1f, 0.2f, 0.9f)};
  const hs::viz::Image image = draw(scene, hs::render::View::Front);
  const Vec3f p = hs::render::viewCamera(hs::render::View::Front, scene.bounds, 160.0f / 120.0f)
                      .project(Vec3f(0, 0, 0.5f), 160, 120);
  const Rgb centre = image.at(int(p.x()), int(p.y()));
  EXPECT_GT(centre.b, 150);
  EXPECT_LT(centre.r, 100);
  // Shaded: the lit upper-left of the sphere is brighter than its lower-right edge.
  const Rgb upperLeft = image.at(int(p.x()) - 8, int(p.y()) - 8);
  const Rgb lowerRight = image.at(int(p.x()) + 10, int(p.y()) + 10);
  EXPECT_GT(int(upperLeft.b), int(lowerRight.b) + 20);
  // A sphere behind the triangle is hidden by it (correct depth, not drawn on top).
  scene.particles.centres = {Vec3f(0, 0, -0.6f)};
  EXPECT_GT(draw(scene, hs::render::View::Front).at(80, 70).r, 150);
}

TEST_F(Offscreen, SeeThroughWallShowsTheBloodBehindIt) {
  hs::render::Scene scene = emptyScene();
  addTriangle(scene, Vec3f(0.9f, 0.1f, 0.1f));
  scene.wall.opacity = 0.4f;
  scene.particles.radius = 0.3f;
  scene.particles.centres = {Vec3f(0, 0, -0.6f)};
  scene.particles.colours = {Vec3f(0.1f, 0.2f, 0.9f)};
  const Rgb mixed = draw(scene, hs::render::View::Front).at(80, 72);
  EXPECT_GT(mixed.b, 60);
  EXPECT_GT(mixed.r, 60);
}

TEST_F(Offscreen, ImpossibleTargetSizeGivesAClearError) {
  EXPECT_THROW(hs::render::FrameTarget(0, 10), std::runtime_error);
}

}  // namespace
