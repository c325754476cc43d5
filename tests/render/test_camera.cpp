// The four named views look from the sides their names say: known world points land on the
// expected side of the image (the mitral side, -x, on the viewer's left in the front view).
#include <gtest/gtest.h>

#include "render/renderer.h"

namespace {

using hs::render::Box;
using hs::render::Camera;
using hs::render::Vec3f;
using hs::render::View;

constexpr int kW = 800, kH = 600;
const Box kBox{Vec3f(-1, -2, -1), Vec3f(1, 1, 1)};

Vec3f pixel(View view, const Vec3f& p) {
  return hs::render::viewCamera(view, kBox, float(kW) / float(kH)).project(p, kW, kH);
}

TEST(Camera, FrontLooksAlongMinusZWithMinusXOnTheLeftAndYUp) {
  const Vec3f c = kBox.centre();
  EXPECT_LT(pixel(View::Front, c + Vec3f(-0.5f, 0, 0)).x(), kW / 2.0f);
  EXPECT_GT(pixel(View::Front, c + Vec3f(0.5f, 0, 0)).x(), kW / 2.0f);
  EXPECT_LT(pixel(View::Front, c + Vec3f(0, 0.5f, 0)).y(), kH / 2.0f);  // +y up: smaller row
  // +z is nearer the camera: smaller depth.
  EXPECT_LT(pixel(View::Front, c + Vec3f(0, 0, 0.5f)).z(), pixel(View::Front, c + Vec3f(0, 0, -0.5f)).z());
  const Camera cam = hs::render::viewCamera(View::Front, kBox, 4.0f / 3.0f);
  EXPECT_GT(cam.eye.z(), kBox.max.z());
  EXPECT_NEAR(cam.eye.x(), 0.0f, 1e-5f);
}

TEST(Camera, LeftLooksFromMinusXWithAnteriorOnTheRight) {
  const Vec3f c = kBox.centre();
  EXPECT_GT(pixel(View::Left, c + Vec3f(0, 0, 0.5f)).x(), kW / 2.0f);
  EXPECT_LT(pixel(View::Left, c + Vec3f(0, 0.5f, 0)).y(), kH / 2.0f);
  EXPECT_LT(pixel(View::Left, c + Vec3f(-0.5f, 0, 0)).z(), pixel(View::Left, c + Vec3f(0.5f, 0, 0)).z());
  EXPECT_LT(hs::render::viewCamera(View::Left, kBox, 1).eye.x(), kBox.min.x());
}

TEST(Camera, RightLooksFromPlusXWithAnteriorOnTheLeft) {
  const Vec3f c = kBox.centre();
  EXPECT_LT(pixel(View::Right, c + Vec3f(0, 0, 0.5f)).x(), kW / 2.0f);
  EXPECT_LT(pixel(View::Right, c + Vec3f(0, 0.5f, 0)).y(), kH / 2.0f);
  EXPECT_LT(pixel(View::Right, c + Vec3f(0.5f, 0, 0)).z(), pixel(View::Right, c + Vec3f(-0.5f, 0, 0)).z());
  EXPECT_GT(hs::render::viewCamera(View::Right, kBox, 1).eye.x(), kBox.max.x());
}

TEST(Camera, TopLooksDownWithMinusXLeftAndAnteriorAtTheBottom) {
  const Vec3f c = kBox.centre();
  EXPECT_LT(pixel(View::Top, c + Vec3f(-0.5f, 0, 0)).x(), kW / 2.0f);
  EXPECT_GT(pixel(View::Top, c + Vec3f(0, 0, 0.5f)).y(), kH / 2.0f);
  EXPECT_LT(pixel(View::Top, c + Vec3f(0, 0.5f, 0)).z(), pixel(View::Top, c + Vec3f(0, -0.5f, 0)).z());
  EXPECT_GT(hs::render::viewCamera(View::Top, kBox, 1).eye.y(), kBox.max.y());
}

TEST(Camera, EveryViewFramesTheWholeBox) {
  for (View view : hs::render::kAllViews) {
    for (int corner = 0; corner < 8; ++corner) {
      const Vec3f p((corner & 1) ? kBox.max.x() : kBox.min.x(), (corner & 2) ? kBox.max.y() : kBox.min.y(),
                    (corner & 4) ? kBox.max.z() : kBox.min.z());
      const Vec3f q = pixel(view, p);
      EXPECT_GE(q.x(), 0) << hs::render::viewName(view);
      EXPECT_LE(q.x(), kW) << hs::render::viewName(view);
      EXPECT_GE(q.y(), 0) << hs::render::viewName(view);
      EXPECT_LE(q.y(), kH) << hs::render::viewName(view);
      EXPECT_GT(q.z(), 0) << hs::render::viewName(view);
      EXPECT_LT(q.z(), 1) << hs::render::viewName(view);
    }
  }
}

TEST(Camera, ViewNamesRoundTripAndUnknownNamesAreRejected) {
  for (View view : hs::render::kAllViews) EXPECT_EQ(hs::render::parseView(hs::render::viewName(view)), view);
  EXPECT_FALSE(hs::render::parseView("back").has_value());
  EXPECT_FALSE(hs::render::parseView("Front ").has_value());
  EXPECT_EQ(hs::render::viewNames(), "front, left, right, top");
}

}  // namespace
