#pragma once
// The blood's liquid look: screen-space fluid rendering (Green 2010, "Screen Space Fluid
// Rendering for Games"; van der Laan et al. 2009). The particles' spheres go to an offscreen
// depth image (the nearest sphere per pixel, with its colour) and a thickness image (their
// chords added up); the depth and colour are smoothed by a separable bilateral filter; a full
// screen pass rebuilds normals from the smoothed depth, shades the surface and blends it into
// the framebuffer that was bound, depth-tested against what is drawn (the wall), writing no
// depth itself.
// The shaders are in fluid_shaders.h. Needs a current OpenGL 3.3 core context.
#include <epoxy/gl.h>

#include <vector>

#include "render/camera.h"

namespace hs::render {

struct ParticleCloud;

// The liquid's spheres are drawn 1.6 particle radii r wide: the particles sit about 2 r apart,
// so spheres of radius r leave gaps that show as pits (and, on the cut, as holes into the blood
// behind); at 1.6 r neighbours overlap and the filter has one surface to smooth. An opaque
// wall, drawn after, hides what this adds beyond the blood's extent.
inline constexpr float kLiquidSurfaceRadii = 1.6f;

// Where and how the liquid is seen this frame.
struct LiquidFrame {
  Mat4f view, projection;
  float tanHalfX = 1, tanHalfY = 1;  // tan of half the field of view
  int width = 1, height = 1;         // pixels of the framebuffer drawn into
  Vec4f clip = Vec4f::Zero();        // view space; keeps dot(xyz, p) + w <= 0
  bool clipOn = false;
  Vec3f key = Vec3f(0, 0, 1);        // key light, view space, unit
  // The pixels the blood can cover ([x0, x1) x [y0, y1), OpenGL's rows bottom-up): every pass
  // is limited to them, which on a software renderer is most of the time saved.
  int x0 = 0, y0 = 0, x1 = 1, y1 = 1;
};

// The pixels spheres of `radius` around `centres` can cover in a width x height image seen
// through view and projection (tanHalfY: tan of half the vertical field of view), as
// [x0, x1) x [y0, y1), bottom-up; the whole image when a sphere reaches the eye's plane.
void screenExtent(const std::vector<Vec3f>& centres, float radius, LiquidFrame& frame);

class FluidSurface {
 public:
  FluidSurface();
  ~FluidSurface();
  FluidSurface(const FluidSurface&) = delete;
  FluidSurface& operator=(const FluidSurface&) = delete;

  // Draws the cloud whose centres and colours are already in the two buffers (one Vec3f per
  // particle each) into the framebuffer bound now, at 1 / cloud.liquidDownsample of its
  // resolution. Leaves the depth test on, blending off.
  void draw(const ParticleCloud& cloud, GLuint centres, GLuint colours, const LiquidFrame& frame);

 private:
  void resize(int width, int height);

  GLuint m_depthProgram = 0, m_thicknessProgram = 0, m_blurProgram = 0, m_compositeProgram = 0;
  GLuint m_sphereFbo = 0, m_thicknessFbo = 0, m_blurFbo = 0;
  GLuint m_depth[2] = {}, m_colour[2] = {}, m_thickness = 0, m_depthBuffer = 0;
  int m_width = 0, m_height = 0;
};

}  // namespace hs::render
