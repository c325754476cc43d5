#pragma once
// Which wall vertices lie under the viewer's round paint brush: the selection code behind
// painting the beating region (thesis 4.3.3, "selectedBeatingParticles"). Pure geometry (no
// GL, no window), so it is tested against a brute-force projection.
//
// A vertex is picked when it is a candidate (myocardium, not pinned: the caller's mask), lies
// in front of the camera and inside the clip volume, is not removed by the clipping plane, its
// projection is within the brush radius of the brush centre, and (with the surface given)
// nothing of the surface lies between the eye and it: painting marks what the student sees,
// not the hidden wall behind it.
#include <array>
#include <cstdint>
#include <vector>

#include "render/renderer.h"

namespace hs::viewer {

// The camera as the screen sees it: pixels x to the right, y downwards, of a width x height
// viewport (the window's, in the same units as the cursor).
struct BrushView {
  render::Mat4f viewProjection = render::Mat4f::Identity();
  render::Vec3f eye = render::Vec3f::Zero();
  int width = 1, height = 1;
};

BrushView brushView(const render::Camera& camera, int width, int height);

// Where a point lands on the screen (pixels, y down); false when it lies behind the eye or
// outside the near/far range.
bool projectToScreen(const BrushView& view, const render::Vec3f& point, float& x, float& y);

struct BrushQuery {
  BrushView view;
  float centreX = 0, centreY = 0;  // brush centre, pixels (the cursor)
  float radius = 20;               // pixels
  // What the renderer cuts away: points with dot(normal, p) + offset > 0 (render::ClipPlane).
  render::ClipPlane clip;
};

struct BrushSurface {
  const std::vector<render::Vec3f>* positions = nullptr;  // per vertex, current
  const std::vector<std::uint8_t>* candidate = nullptr;   // per vertex: nonzero = may be picked
  // Outward boundary triangles (vertex ids) that hide what lies behind them; null or empty:
  // no occlusion test, every candidate under the brush is picked.
  const std::vector<std::array<std::uint32_t, 3>>* triangles = nullptr;
};

// The brush's dabs along a stroke from (x0, y0) to (x1, y1) (pixels, the cursor's path since the
// last frame): `query` centred every half radius, ending at (x1, y1), so a fast stroke leaves
// no gaps.
std::vector<BrushQuery> brushDabsAlong(BrushQuery query, float x0, float y0, float x1, float y1);

// The vertex ids under the brush, ascending. Cost: one projection per vertex, then one ray per
// vertex under the brush against the triangles whose screen boxes meet the brush's box.
std::vector<std::uint32_t> verticesInBrush(const BrushSurface& surface, const BrushQuery& query);

}  // namespace hs::viewer
