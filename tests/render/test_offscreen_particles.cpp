// The particle impostors against a ray-cast reference: each sphere's rectangle must hold its
// whole perspective outline, off-axis near the image's corner and close to the eye, where the
// outline is widest; and drawing a strip of the image leaves the rest as it was (the viewer
// skips what its panels cover).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdlib>

#include "render/gl_context.h"
#include "render/renderer.h"

namespace {

using hs::render::Vec3f;
using hs::viz::Rgb;

constexpr int kWidth = 200, kHeight = 150;

class OffscreenParticles : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { unsetenv("DISPLAY"); }
  hs::render::GlContext gl;
  hs::render::FrameTarget target{kWidth, kHeight};
  hs::render::Renderer renderer;
};

hs::render::Scene whiteScene() {
  hs::render::Scene scene;
  scene.bounds = {Vec3f(-1, -1, -1), Vec3f(1, 1, 1)};
  scene.backgroundTop = scene.backgroundBottom = Vec3f(1, 1, 1);
  return scene;
}

// A wide-angle camera, so perspective stretches the outlines toward the corners.
hs::render::Camera wideCamera() {
  hs::render::Camera camera;
  camera.eye = Vec3f(0, 0, 3);
  camera.fovyDegrees = 70;
  camera.nearPlane = 0.05f;
  camera.farPlane = 20;
  return camera;
}

// Whether the ray through the centre of pixel (x, y) hits the sphere.
bool rayHits(const hs::render::Camera& camera, int x, int y, const Vec3f& centre, float radius) {
  const float aspect = float(kWidth) / float(kHeight);
  const float t = std::tan(camera.fovyDegrees * float(M_PI) / 360);
  const Vec3f direction =
      Vec3f((2 * (float(x) + 0.5f) / kWidth - 1) * t * aspect, (1 - 2 * (float(y) + 0.5f) / kHeight) * t, -1)
          .normalized();
  const Vec3f c = (camera.viewMatrix() * centre.homogeneous()).head<3>();
  const float b = direction.dot(c);
  return b > 0 && b * b - c.squaredNorm() + radius * radius > 0;
}

TEST_F(OffscreenParticles, EverySphereIsDrawnWholeOffAxisAndCloseToTheEye) {
  const hs::render::Camera camera = wideCamera();
  struct Case {
    Vec3f centre;
    float radius;
  };
  // Near the upper-right corner of the view; close to the eye and off-axis.
  for (const Case& c : {Case{Vec3f(2.4f, 1.6f, 0), 0.35f}, Case{Vec3f(0.5f, -0.3f, 2.2f), 0.4f},
                        Case{Vec3f(0, 0, 0), 0.5f}}) {
    hs::render::Scene scene = whiteScene();
    scene.particles.radius = c.radius;
    scene.particles.centres = {c.centre};
    scene.particles.colours = {Vec3f(0.1f, 0.2f, 0.9f)};
    target.bind();
    renderer.draw(scene, camera, kWidth, kHeight);
    const hs::viz::Image image = target.read();
    int expected = 0, missing = 0, extra = 0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        const bool hit = rayHits(camera, x, y, c.centre, c.radius);
        const bool drawn = image.at(x, y) != Rgb{255, 255, 255};
        expected += hit ? 1 : 0;
        missing += hit && !drawn ? 1 : 0;
        extra += drawn && !hit ? 1 : 0;
      }
    ASSERT_GT(expected, 100) << "the sphere must be in view";
    // Rasterisation and the ray test may differ on the outline's pixels, not more.
    const double outline = 2 * std::sqrt(M_PI * expected);
    EXPECT_LT(missing, outline * 0.5)
        << "sphere at " << c.centre.transpose() << ": " << missing << " of " << expected << " pixels missing";
    EXPECT_LT(extra, outline * 0.5) << "sphere at " << c.centre.transpose();
  }
}

TEST_F(OffscreenParticles, DrawingAStripLeavesTheRestAsItWas) {
  hs::render::Scene red = whiteScene();
  red.backgroundTop = red.backgroundBottom = Vec3f(1, 0, 0);
  hs::render::Scene blue = whiteScene();
  blue.backgroundTop = blue.backgroundBottom = Vec3f(0, 0, 1);
  target.bind();
  renderer.draw(red, wideCamera(), kWidth, kHeight);
  renderer.draw(blue, wideCamera(), kWidth, kHeight, 50, 120);
  const hs::viz::Image image = target.read();
  // Two pixels from the strip's edges: a multisampled target (llvmpipe) may blend the columns
  // right at them.
  EXPECT_EQ(image.at(47, 75), (Rgb{255, 0, 0}));
  EXPECT_EQ(image.at(52, 75), (Rgb{0, 0, 255}));
  EXPECT_EQ(image.at(117, 10), (Rgb{0, 0, 255}));
  EXPECT_EQ(image.at(122, 140), (Rgb{255, 0, 0}));
  // The whole image again afterwards: the strip does not stay in force.
  renderer.draw(blue, wideCamera(), kWidth, kHeight);
  EXPECT_EQ(target.read().at(5, 5), (Rgb{0, 0, 255}));
}

}  // namespace
