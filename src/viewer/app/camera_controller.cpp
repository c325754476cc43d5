#include "viewer/app/camera_controller.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace hs::viewer {
namespace {

constexpr float kDegrees = 180.0f / float(M_PI);

float radians(float degrees) { return degrees / kDegrees; }

}  // namespace

CameraController::CameraController(const render::Box& bounds, float aspect)
    : m_bounds(bounds), m_aspect(aspect) {
  reset();
}

void CameraController::setView(render::View view) {
  const render::Camera framed = render::viewCamera(view, m_bounds, m_aspect);
  m_target = framed.target;
  m_distance = (framed.eye - framed.target).norm();
  m_framingDistance = m_distance;
  m_boundsRadius = std::max((m_bounds.max - m_bounds.min).norm() / 2, 1e-6f);
  switch (view) {
    case render::View::Front:
      m_yaw = 0, m_pitch = 0;
      break;
    case render::View::Left:
      m_yaw = -90, m_pitch = 0;
      break;
    case render::View::Right:
      m_yaw = 90, m_pitch = 0;
      break;
    case render::View::Top:
      m_yaw = 0, m_pitch = 90;
      break;
  }
}

render::Vec3f CameraController::towardEye() const {
  const float y = radians(m_yaw), p = radians(m_pitch);
  return {std::cos(p) * std::sin(y), std::sin(p), std::cos(p) * std::cos(y)};
}

render::Vec3f CameraController::up() const {
  const float y = radians(m_yaw), p = radians(m_pitch);
  return {-std::sin(p) * std::sin(y), std::cos(p), -std::sin(p) * std::cos(y)};
}

// Seen from the eye looking at the target (along -towardEye), with `up` up.
render::Vec3f CameraController::right() const { return (-towardEye()).cross(up()); }

void CameraController::orbit(float dx, float dy, int viewportHeight) {
  const float degreesPerPixel = 180.0f / float(std::max(viewportHeight, 1));
  // Dragging right turns the scene with the cursor, so the eye moves to the left (yaw falls);
  // dragging down tips the near side down, so the eye rises (pitch grows).
  m_yaw -= dx * degreesPerPixel;
  m_yaw = std::remainder(m_yaw, 360.0f);
  m_pitch = std::clamp(m_pitch + dy * degreesPerPixel, -kMaxPitchDegrees, kMaxPitchDegrees);
}

void CameraController::pan(float dx, float dy, int viewportHeight) {
  // World size of one pixel at the target's depth.
  const float tanHalf = std::tan(radians(render::Camera{}.fovyDegrees) / 2);
  const float metresPerPixel = 2 * m_distance * tanHalf / float(std::max(viewportHeight, 1));
  // The scene follows the cursor: the target moves against the drag.
  m_target += (-dx * right() + dy * up()) * metresPerPixel;
}

void CameraController::zoom(float steps) {
  m_distance = std::clamp(m_distance * std::pow(0.9f, steps), kMinDistanceFraction * m_framingDistance,
                          kMaxDistanceFraction * m_framingDistance);
}

render::Camera CameraController::camera() const {
  render::Camera c;
  c.target = m_target;
  c.eye = m_target + towardEye() * m_distance;
  c.up = up();
  // The bounds' far side stays inside the far plane; the near plane keeps depth precision
  // but never cuts into the scene (or what is in front of the eye when zoomed in).
  c.nearPlane = std::max(0.5f * (m_distance - 2 * m_boundsRadius), 2e-3f * m_distance);
  c.nearPlane = std::min(c.nearPlane, 0.5f * m_distance);
  c.farPlane = m_distance + 4 * m_boundsRadius + (m_target - m_bounds.centre()).norm();
  return c;
}

}  // namespace hs::viewer
