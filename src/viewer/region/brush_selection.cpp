#include "viewer/region/brush_selection.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace hs::viewer {
namespace {

using render::Vec3f;
using render::Vec4f;

bool clippedAway(const render::ClipPlane& clip, const Vec3f& p) {
  return clip.enabled && clip.normal.dot(p) + clip.offset > 0;
}

// Moeller-Trumbore: the parameter t of the ray o + t d where it crosses triangle (a, b, c),
// or a negative value when it misses.
float rayTriangle(const Vec3f& o, const Vec3f& d, const Vec3f& a, const Vec3f& b, const Vec3f& c) {
  const Vec3f e1 = b - a, e2 = c - a;
  const Vec3f p = d.cross(e2);
  const float det = e1.dot(p);
  if (std::abs(det) < 1e-20f) return -1;  // ray parallel to the triangle
  const float inv = 1.0f / det;
  const Vec3f s = o - a;
  const float u = s.dot(p) * inv;
  if (u < 0 || u > 1) return -1;
  const Vec3f q = s.cross(e1);
  const float v = d.dot(q) * inv;
  if (v < 0 || u + v > 1) return -1;
  return e2.dot(q) * inv;
}

// Whether the surface hides vertex v from the eye: the segment eye -> v crosses a triangle
// that does not touch v, at a point the clipping plane keeps (the cut-away wall hides nothing).
bool occluded(const BrushSurface& surface, const Vec3f& eye, std::uint32_t v, const render::ClipPlane& clip,
              const std::vector<std::uint32_t>& nearTriangles) {
  const auto& x = *surface.positions;
  const Vec3f d = x[v] - eye;
  // Stop short of v itself: a crossing within 1e-4 of the segment's length is v's own surface.
  constexpr float kEnd = 1 - 1e-4f;
  for (const std::uint32_t f : nearTriangles) {
    const auto& t = (*surface.triangles)[f];
    if (t[0] == v || t[1] == v || t[2] == v) continue;
    const float hit = rayTriangle(eye, d, x[t[0]], x[t[1]], x[t[2]]);
    if (hit > 0 && hit < kEnd && !clippedAway(clip, eye + hit * d)) return true;
  }
  return false;
}

}  // namespace

BrushView brushView(const render::Camera& camera, int width, int height) {
  BrushView view;
  width = std::max(width, 1);
  height = std::max(height, 1);
  view.viewProjection = camera.projectionMatrix(float(width) / float(height)) * camera.viewMatrix();
  view.eye = camera.eye;
  view.width = width;
  view.height = height;
  return view;
}

bool projectToScreen(const BrushView& view, const Vec3f& point, float& x, float& y) {
  const Vec4f clip = view.viewProjection * point.homogeneous();
  if (!(clip.w() > 0)) return false;
  const Vec3f ndc = clip.head<3>() / clip.w();
  if (!(ndc.z() >= -1 && ndc.z() <= 1)) return false;
  x = (ndc.x() + 1) / 2 * float(view.width);
  y = (1 - ndc.y()) / 2 * float(view.height);
  return true;
}

std::vector<std::uint32_t> verticesInBrush(const BrushSurface& surface, const BrushQuery& query) {
  std::vector<std::uint32_t> picked;
  if (!surface.positions || !surface.candidate || !(query.radius > 0)) return picked;
  const auto& x = *surface.positions;
  const std::size_t n = std::min(x.size(), surface.candidate->size());
  const float r2 = query.radius * query.radius;
  for (std::size_t v = 0; v < n; ++v) {
    if (!(*surface.candidate)[v] || clippedAway(query.clip, x[v])) continue;
    float sx = 0, sy = 0;
    if (!projectToScreen(query.view, x[v], sx, sy)) continue;
    const float dx = sx - query.centreX, dy = sy - query.centreY;
    if (dx * dx + dy * dy <= r2) picked.push_back(std::uint32_t(v));
  }
  if (picked.empty() || !surface.triangles || surface.triangles->empty()) return picked;

  // Only triangles whose screen box meets the brush's box can hide a vertex under the brush.
  // A triangle with a corner behind the eye has no screen box: kept, the ray test decides.
  const float left = query.centreX - query.radius, right = query.centreX + query.radius;
  const float top = query.centreY - query.radius, bottom = query.centreY + query.radius;
  std::vector<std::uint32_t> nearTriangles;
  for (std::size_t f = 0; f < surface.triangles->size(); ++f) {
    const auto& t = (*surface.triangles)[f];
    if (t[0] >= x.size() || t[1] >= x.size() || t[2] >= x.size()) continue;
    float lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    bool behind = false;
    for (const std::uint32_t v : t) {
      float sx = 0, sy = 0;
      if (!projectToScreen(query.view, x[v], sx, sy)) {
        behind = true;
        break;
      }
      lo[0] = std::min(lo[0], sx), hi[0] = std::max(hi[0], sx);
      lo[1] = std::min(lo[1], sy), hi[1] = std::max(hi[1], sy);
    }
    if (behind || (hi[0] >= left && lo[0] <= right && hi[1] >= top && lo[1] <= bottom))
      nearTriangles.push_back(std::uint32_t(f));
  }
  std::erase_if(picked, [&](std::uint32_t v) {
    return occluded(surface, query.view.eye, v, query.clip, nearTriangles);
  });
  return picked;
}

std::vector<BrushQuery> brushDabsAlong(BrushQuery query, float x0, float y0, float x1, float y1) {
  const float length = std::hypot(x1 - x0, y1 - y0);
  const int steps = std::max(1, int(std::ceil(length / (0.5f * query.radius))));
  std::vector<BrushQuery> dabs;
  for (int i = 1; i <= steps; ++i) {
    const float t = float(i) / float(steps);
    query.centreX = x0 + t * (x1 - x0);
    query.centreY = y0 + t * (y1 - y0);
    dabs.push_back(query);
  }
  return dabs;
}

}  // namespace hs::viewer
