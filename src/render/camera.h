#pragma once
// The camera of the scene renderer: a perspective look-at camera, and the four named views
// (front, left, right, top) that frame a box the way the thesis's figures show the heart.
//
// World coordinates are the model's (metres): y is the long axis (apex at -y, vessels at +y),
// anterior is +z, the mitral orifice at -x.
#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace hs::render {

using Vec3f = Eigen::Vector3f;
using Vec4f = Eigen::Vector4f;
using Mat4f = Eigen::Matrix4f;

struct Box {
  Vec3f min = Vec3f::Zero(), max = Vec3f::Zero();
  Vec3f centre() const { return (min + max) / 2; }
};

// A perspective look-at camera.
struct Camera {
  Vec3f eye = Vec3f(0, 0, 1), target = Vec3f::Zero(), up = Vec3f(0, 1, 0);
  float fovyDegrees = 30;
  float nearPlane = 0.01f, farPlane = 100;

  Mat4f viewMatrix() const;
  Mat4f projectionMatrix(float aspect) const;
  // Where a world point lands in a width x height image: x to the right, y downwards
  // (pixels, continuous), z the depth in [0, 1] (OpenGL's window depth).
  Vec3f project(const Vec3f& world, int width, int height) const;
};

// front: onto the three-chamber plane, looking along -z (the mitral side, -x, on the viewer's
// left, the outflow tract and the septum on the right; cardiac/anatomy/aha_segments.h); left / right:
// from -x (lateral) / +x (septal) looking along +x / -x; top: from +y down onto the base, -x on
// the viewer's left and +z (the front view's side) at the bottom of the image. Up is +y except
// for top.
enum class View { Front, Left, Right, Top };
inline constexpr std::array<View, 4> kAllViews = {View::Front, View::Left, View::Right, View::Top};
const char* viewName(View view);
std::optional<View> parseView(std::string_view name);
// "front, left, right, top"
std::string viewNames();

// Unit vector from the scene toward the eye of a view: front +z, left -x, right +x, top +y.
Vec3f viewDirection(View view);

// The camera looking at `bounds` from the named side, far enough that the whole box fits an
// image of the given aspect ratio (width / height) with a small margin.
Camera viewCamera(View view, const Box& bounds, float aspect);

}  // namespace hs::render
