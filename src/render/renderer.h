#pragma once
// The scene renderer shared by `heartsim render` (offscreen) and the viewer: a lit, optionally
// see-through or cut-open heart wall, the blood as a liquid surface (fluid_surface.h) or as
// shaded spheres, flow lines (streaks or arrows), a wireframe box, over a gradient background. The scene is plain data (scene.h builds it from a simulation), so the
// renderer knows nothing about hearts. Cameras and views: camera.h.
#include <memory>
#include <vector>

#include "render/camera.h"

namespace hs::render {

class FluidSurface;

struct CameraMatrices {
  Mat4f view, projection;
};

// Triangles as consecutive vertex triples (not indexed: creases get their own normals).
// Front faces (counter-clockwise seen from outside) are the wall's outside; back faces are
// only seen where the clipping plane cuts the wall open and are drawn in cutColour.
struct WallMesh {
  std::vector<Vec3f> positions, normals, colours;  // per vertex, colours linear RGB in [0, 1]
  float opacity = 1;                             // < 1: see-through
  Vec3f cutColour = Vec3f(0.55f, 0.16f, 0.18f);
  std::size_t triangleCount() const { return positions.size() / 3; }
};

// How the blood is drawn: a smooth liquid surface over the particles (screen-space fluid
// rendering, fluid_surface.h) or each particle as a shaded sphere.
enum class BloodLook { Liquid, Spheres };

struct ParticleCloud {
  std::vector<Vec3f> centres, colours;
  float radius = 0.01f;
  float opacity = 1;  // < 1: see-through, drawn over the wall without hiding it
  BloodLook look = BloodLook::Spheres;
  int liquidDownsample = 1;  // the liquid look's images at 1/n of the screen's resolution
};

// Flow lines as segments, each a flat-coloured screen-space ribbon from `from` to `to`, widths
// in pixels at each end (a streak tapers toward its tail; an arrow's head is two segments).
struct FlowLines {
  std::vector<Vec3f> from, to, colours;
  std::vector<float> widthFrom, widthTo;  // pixels
  std::size_t size() const { return from.size(); }
};

// Line segments as point pairs.
struct LineSet {
  std::vector<Vec3f> points;
  Vec3f colour = Vec3f(0.35f, 0.4f, 0.5f);
};

// Removes what lies on the side the normal points to: dot(normal, x) + offset > 0.
struct ClipPlane {
  bool enabled = false;
  Vec3f normal = Vec3f(0, 0, 1);
  float offset = 0;
  bool clipParticles = false;  // the wall (and flow lines) always clipped; particles only when asked
};

// Directional lights fixed to the camera (view space, pointing toward the light), so every
// view is lit the same way: a key light from the upper left, a weaker fill from the right.
struct Light {
  Vec3f key = Vec3f(-0.4f, 0.6f, 0.7f);
  Vec3f fill = Vec3f(0.6f, -0.1f, 0.5f);
  float ambient = 0.28f, keyStrength = 0.75f, fillStrength = 0.25f;
  float specular = 0.35f, shininess = 40;
};

struct Scene {
  WallMesh wall;
  // The valves' leaflets (valve_leaflets.h): opaque, drawn after the liquid blood, which
  // writes no depth, so they show inside it; depth-tested against the wall.
  WallMesh valves;
  ParticleCloud particles;
  FlowLines flow;
  LineSet lines;
  ClipPlane clip;
  Light light;
  Vec3f backgroundTop = Vec3f(0.97f, 0.97f, 0.99f), backgroundBottom = Vec3f(0.78f, 0.82f, 0.89f);
  Box bounds;  // what the cameras frame
};

// Draws into the currently bound framebuffer (FrameTarget::bind). Needs a current OpenGL 3.3
// core context (GlContext) for its whole life; throws std::runtime_error when a shader does not
// compile.
class Renderer {
 public:
  Renderer();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  void draw(const Scene& scene, const Camera& camera, int width, int height);
  // Only the pixels x in [x0, x1) are drawn (the rest is left as it was), with the projection
  // of the whole width x height image: the viewer skips what its opaque panels cover, which
  // on a software renderer is time saved.
  void draw(const Scene& scene, const Camera& camera, int width, int height, int x0, int x1);

 private:
  void drawBlood(const Scene& scene, const Camera& camera, const CameraMatrices& matrices, int width, int height);

  struct Gl;
  std::unique_ptr<Gl> m_gl;
  std::unique_ptr<FluidSurface> m_liquid;
};

}  // namespace hs::render
