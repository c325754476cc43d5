// The look-at camera's matrices and the four named views' cameras framing a box.
#include "render/camera.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace hs::render {

Mat4f Camera::viewMatrix() const {
  const Vec3f f = (target - eye).normalized();
  const Vec3f r = f.cross(up).normalized();
  const Vec3f u = r.cross(f);
  Mat4f m = Mat4f::Identity();
  m.block<1, 3>(0, 0) = r.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -r.dot(eye);
  m(1, 3) = -u.dot(eye);
  m(2, 3) = f.dot(eye);
  return m;
}

// gluPerspective.
Mat4f Camera::projectionMatrix(float aspect) const {
  const float t = 1.0f / std::tan(fovyDegrees * float(M_PI) / 360.0f);
  Mat4f m = Mat4f::Zero();
  m(0, 0) = t / aspect;
  m(1, 1) = t;
  m(2, 2) = (farPlane + nearPlane) / (nearPlane - farPlane);
  m(2, 3) = 2 * farPlane * nearPlane / (nearPlane - farPlane);
  m(3, 2) = -1;
  return m;
}

Vec3f Camera::project(const Vec3f& world, int width, int height) const {
  const Vec4f clip = projectionMatrix(float(width) / float(height)) * viewMatrix() * world.homogeneous();
  const Vec3f ndc = clip.head<3>() / clip.w();
  return {(ndc.x() + 1) / 2 * float(width), (1 - ndc.y()) / 2 * float(height), (ndc.z() + 1) / 2};
}

namespace {

// What each view is: its name and the unit vector from the scene toward its eye.
struct ViewFacts {
  const char* name;
  Vec3f towardEye;
};

ViewFacts viewFacts(View view) {
  switch (view) {
    case View::Front: return {"front", Vec3f(0, 0, 1)};
    case View::Left: return {"left", Vec3f(-1, 0, 0)};
    case View::Right: return {"right", Vec3f(1, 0, 0)};
    case View::Top: return {"top", Vec3f(0, 1, 0)};
  }
  return {"?", Vec3f(0, 0, 1)};
}

}  // namespace

const char* viewName(View view) { return viewFacts(view).name; }

std::optional<View> parseView(std::string_view name) {
  for (View v : kAllViews)
    if (name == viewName(v)) return v;
  return std::nullopt;
}

std::string viewNames() {
  std::string names;
  for (View v : kAllViews) names += (names.empty() ? "" : ", ") + std::string(viewName(v));
  return names;
}

Vec3f viewDirection(View view) { return viewFacts(view).towardEye; }

Camera viewCamera(View view, const Box& bounds, float aspect) {
  const Vec3f towardEye = viewDirection(view);
  // Top: tilted up over the base from the front view, so x keeps its direction (-x on the
  // left) and +z, the front view's side, comes to the bottom of the image.
  const Vec3f up = view == View::Top ? Vec3f(0, 0, -1) : Vec3f(0, 1, 0);
  const Vec3f right = (-towardEye).cross(up);
  const Vec3f centre = bounds.centre();
  float halfW = 0, halfH = 0, halfD = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3f c((corner & 1) ? bounds.max.x() : bounds.min.x(), (corner & 2) ? bounds.max.y() : bounds.min.y(),
                  (corner & 4) ? bounds.max.z() : bounds.min.z());
    const Vec3f d = c - centre;
    halfW = std::max(halfW, std::abs(d.dot(right)));
    halfH = std::max(halfH, std::abs(d.dot(up)));
    halfD = std::max(halfD, std::abs(d.dot(towardEye)));
  }
  Camera camera;
  const float tanY = std::tan(camera.fovyDegrees * float(M_PI) / 360.0f);
  const float tanX = tanY * aspect;
  constexpr float kMargin = 1.08f;
  // The box's near face must fit: distance from the eye to that face, plus half the depth.
  const float size = std::max({halfW / tanX, halfH / tanY, 1e-6f});
  const float distance = halfD + kMargin * size;
  camera.target = centre;
  camera.eye = centre + towardEye * distance;
  camera.up = up;
  camera.nearPlane = std::max(0.5f * (distance - 2 * halfD), 1e-3f * distance);
  camera.farPlane = distance + 3 * halfD + size;
  return camera;
}

}  // namespace hs::render
