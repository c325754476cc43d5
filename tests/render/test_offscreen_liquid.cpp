// The blood's liquid look (render/fluid_surface.h) read back pixel by pixel: a surface facing
// the eye has exactly the colour of the key (no lighting or wall mixed in, also behind a
// see-through wall), the clipping plane cuts the blood flat, and the surface is smoother than
// the spheres it is made of.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "render/gl_context.h"
#include "render/renderer.h"
#include "render/scene.h"

namespace {

using hs::render::BloodLook;
using hs::render::Vec3f;
using hs::viz::Rgb;

constexpr int kWidth = 200, kHeight = 150;

class OffscreenLiquid : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { unsetenv("DISPLAY"); }
  hs::render::GlContext gl;
  hs::render::FrameTarget target{kWidth, kHeight};
  hs::render::Renderer renderer;

  hs::viz::Image draw(const hs::render::Scene& scene) {
    target.bind();
    renderer.draw(scene, hs::render::viewCamera(hs::render::View::Front, scene.bounds, float(kWidth) / kHeight), kWidth,
                  kHeight);
    return target.read();
  }
};

// A block of blood particles about 2 r apart filling [-0.6, 0.6] x [-0.45, 0.45] x [-0.3, 0.3],
// seen from the front, on a white background, in one colour. Each is moved by up to r/2 at
// random (a fixed sequence), as blood's particles are: on a lattice lined up with the eye's
// rays, rays between the columns would meet no particle at all.
hs::render::Scene bloodBlock(BloodLook look, const Vec3f& colour) {
  std::uint32_t state = 12345;
  auto jitter = [&] {
    state = state * 1664525u + 1013904223u;
    return (float(state >> 8) / float(1 << 24) - 0.5f) * 0.05f;
  };
  hs::render::Scene scene;
  scene.bounds = {Vec3f(-0.7f, -0.55f, -0.4f), Vec3f(0.7f, 0.55f, 0.4f)};
  scene.backgroundTop = scene.backgroundBottom = Vec3f(1, 1, 1);
  scene.particles.radius = 0.05f;
  scene.particles.look = look;
  for (float x = -0.6f; x <= 0.6f; x += 0.1f)
    for (float y = -0.45f; y <= 0.45f; y += 0.1f)
      for (float z = -0.3f; z <= 0.3f; z += 0.1f) {
        scene.particles.centres.emplace_back(x + jitter(), y + jitter(), z + jitter());
        scene.particles.colours.push_back(colour);
      }
  return scene;
}

void cutAtZero(hs::render::Scene& scene) {
  scene.clip.enabled = true;
  scene.clip.clipParticles = true;
  scene.clip.normal = Vec3f(0, 0, 1);
  scene.clip.offset = 0;
}

int channelDistance(Rgb a, Rgb b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

// Sum of the absolute differences between horizontally adjacent pixels over the image's middle
// third: how bumpy the blood looks.
long bumpiness(const hs::viz::Image& image) {
  long sum = 0;
  for (int y = kHeight / 3; y < 2 * kHeight / 3; ++y)
    for (int x = kWidth / 3; x < 2 * kWidth / 3; ++x) {
      const Rgb a = image.at(x, y), b = image.at(x + 1, y);
      sum += std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
    }
  return sum;
}

TEST_F(OffscreenLiquid, TheCutFaceHasExactlyTheKeysColour) {
  const Vec3f colour = hs::render::speedColour(0.4);
  hs::render::Scene scene = bloodBlock(BloodLook::Liquid, colour);
  cutAtZero(scene);
  const hs::viz::Image image = draw(scene);
  const Rgb expected = hs::render::toRgb(colour);
  int exact = 0, checked = 0;
  for (int y = kHeight / 3; y < 2 * kHeight / 3; y += 3)
    for (int x = kWidth / 3; x < 2 * kWidth / 3; x += 3, ++checked) {
      exact += channelDistance(image.at(x, y), expected) <= 2;
    }
  EXPECT_EQ(exact, checked) << "centre " << int(image.at(kWidth / 2, kHeight / 2).r) << ","
                            << int(image.at(kWidth / 2, kHeight / 2).g) << "," << int(image.at(kWidth / 2, kHeight / 2).b);
}

TEST_F(OffscreenLiquid, ASeeThroughWallInFrontDoesNotTintTheBlood) {
  hs::render::Scene scene = bloodBlock(BloodLook::Liquid, hs::render::speedColour(0.8));
  scene.particles.centres.erase(
      std::remove_if(scene.particles.centres.begin(), scene.particles.centres.end(), [](const Vec3f& c) { return c.z() > 0; }),
      scene.particles.centres.end());
  scene.particles.colours.resize(scene.particles.centres.size());
  const hs::viz::Image alone = draw(scene);
  // A red see-through wall in front of the blood (z = 0.35, facing the eye).
  for (const Vec3f& p : {Vec3f(-2, -2, 0.35f), Vec3f(2, -2, 0.35f), Vec3f(0, 2, 0.35f)}) {
    scene.wall.positions.push_back(p);
    scene.wall.normals.emplace_back(0, 0, 1);
    scene.wall.colours.emplace_back(0.8f, 0.27f, 0.3f);
  }
  scene.wall.opacity = 0.45f;
  const hs::viz::Image image = draw(scene);
  int tinted = 0, blood = 0;
  for (int y = kHeight / 3; y < 2 * kHeight / 3; ++y)
    for (int x = kWidth / 3; x < 2 * kWidth / 3; ++x, ++blood) tinted += channelDistance(image.at(x, y), alone.at(x, y)) > 1;
  // Only where the liquid is thin (Beer-Lambert: alpha < 1 by design) may what lies behind it
  // show; the blood's own colour is never mixed with the wall in front of it.
  EXPECT_LT(tinted * 100, blood) << tinted << " of " << blood << " blood pixels";
  // The wall is there: it tints the background around the blood.
  EXPECT_GT(channelDistance(image.at(3, kHeight / 2), Rgb{255, 255, 255}), 40);
}

TEST_F(OffscreenLiquid, TheClippingPlaneRemovesBloodInFrontOfIt) {
  for (const BloodLook look : {BloodLook::Liquid, BloodLook::Spheres}) {
    SCOPED_TRACE(hs::render::bloodLookName(look));
    hs::render::Scene scene = bloodBlock(look, Vec3f(0.2f, 0.3f, 0.9f));
    // Only blood in front of the plane z = 0.
    scene.particles.centres.erase(std::remove_if(scene.particles.centres.begin(), scene.particles.centres.end(),
                                                 [](const Vec3f& c) { return c.z() < 0.15f; }),
                                  scene.particles.centres.end());
    scene.particles.colours.resize(scene.particles.centres.size(), Vec3f(0.2f, 0.3f, 0.9f));
    EXPECT_NE(draw(scene).at(kWidth / 2, kHeight / 2), (Rgb{255, 255, 255}));
    cutAtZero(scene);
    const hs::viz::Image cut = draw(scene);
    int coloured = 0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) coloured += cut.at(x, y) != Rgb{255, 255, 255};
    EXPECT_EQ(coloured, 0);
  }
}

TEST_F(OffscreenLiquid, TheSurfaceIsSmootherThanItsSpheres) {
  // Uncut, so the front of the block is the particles' own outer layer.
  const Vec3f colour = hs::render::speedColour(0.2);
  const long spheres = bumpiness(draw(bloodBlock(BloodLook::Spheres, colour)));
  const long liquid = bumpiness(draw(bloodBlock(BloodLook::Liquid, colour)));
  EXPECT_LT(liquid * 2, spheres) << "liquid " << liquid << ", spheres " << spheres;
}

TEST_F(OffscreenLiquid, DrawnAtAThirdOfTheResolutionItStillCoversTheBlood) {
  hs::render::Scene scene = bloodBlock(BloodLook::Liquid, hs::render::speedColour(0.4));
  cutAtZero(scene);
  const hs::viz::Image full = draw(scene);
  scene.particles.liquidDownsample = 3;
  const hs::viz::Image third = draw(scene);
  int differ = 0, covered = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      covered += full.at(x, y) != Rgb{255, 255, 255};
      differ += channelDistance(full.at(x, y), third.at(x, y)) > 30;
    }
  EXPECT_GT(covered, kWidth * kHeight / 3);
  EXPECT_LT(differ, covered / 10) << "only the outline may move";
}

}  // namespace
