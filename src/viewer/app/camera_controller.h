#pragma once
// The viewer's mouse camera: an orbit camera around a target point, described by the distance
// to the target and two angles, so that orbiting can never change the distance and the four
// named views of `heartsim render` are exact positions of it. Pure maths (no GL, no GLFW), so
// it is unit-tested on its own.
//
// Angles (model coordinates, docs/rendering.md): the unit vector from the target toward the
// eye is d(yaw, pitch) = (cos p sin y, sin p, cos p cos y). yaw = 0, pitch = 0 is the front
// view (eye at +z); yaw = -90 deg the left view (eye at -x); yaw = +90 deg the right view; pitch
// = +90 deg the top view. Up is the derivative of d along the pitch, dd/dp = (-sin p sin y,
// cos p, -sin p cos y): +y at pitch 0 and -z at the top (anterior at the bottom of the image,
// as in the top view of `heartsim render`), so there is no singularity at the poles.
#include "render/renderer.h"

namespace hs::viewer {

class CameraController {
 public:
  static constexpr float kMaxPitchDegrees = 90;
  static constexpr float kMinDistanceFraction = 0.02f;  // of the framing distance
  static constexpr float kMaxDistanceFraction = 20;

  // bounds: what to frame (render::sceneBounds); aspect: width / height of the window.
  CameraController(const render::Box& bounds, float aspect);

  // One of the four named views, framing the bounds exactly as render::viewCamera does.
  void setView(render::View view);
  // The front view, framing the bounds for the current aspect.
  void reset() { setView(render::View::Front); }
  void setAspect(float aspect) { m_aspect = aspect; }
  void setBounds(const render::Box& bounds) { m_bounds = bounds; }

  // Turns the camera about the target: dx, dy in pixels of mouse motion (right, down);
  // a drag across the window's height turns it by about 180 degrees. The distance stays.
  void orbit(float dx, float dy, int viewportHeight);
  // Moves the target (and the eye with it) in the view plane so the point under the cursor
  // follows the cursor at the target's depth; dx, dy in pixels (right, down).
  void pan(float dx, float dy, int viewportHeight);
  // Scales the distance to the target by 0.9^steps (steps > 0 zooms in; wheel notches),
  // within [kMinDistanceFraction, kMaxDistanceFraction] x the framing distance.
  void zoom(float steps);

  [[nodiscard]] render::Camera camera() const;
  [[nodiscard]] const render::Vec3f& target() const { return m_target; }
  [[nodiscard]] float distance() const { return m_distance; }
  [[nodiscard]] float yawDegrees() const { return m_yaw; }
  [[nodiscard]] float pitchDegrees() const { return m_pitch; }
  // Unit vectors of the current view: toward the eye, up and right on the screen.
  [[nodiscard]] render::Vec3f towardEye() const;
  [[nodiscard]] render::Vec3f up() const;
  [[nodiscard]] render::Vec3f right() const;

 private:
  render::Box m_bounds;
  float m_aspect = 1;
  render::Vec3f m_target = render::Vec3f::Zero();
  float m_distance = 1;
  float m_framingDistance = 1;  // of the last named view: sets the clip planes and zoom limits
  float m_boundsRadius = 1;
  float m_yaw = 0, m_pitch = 0;  // degrees
};

}  // namespace hs::viewer
