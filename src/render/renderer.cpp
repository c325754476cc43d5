// The scene renderer: one draw call per part of the scene, in the order the depth test and
// blending need: background, lines, the wall, then the blood (an opaque wall's depth hides the
// blood behind it; the liquid's see-through edges blend over the wall drawn behind them; over a
// see-through wall, which writes no depth, the blood is drawn whole, so that its colours are
// never mixed with the wall's and read true against the colour key), the valves' leaflets
// (over the liquid, which writes no depth), then the flow lines.
#include "render/renderer.h"

#include <epoxy/gl.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <string>

#include "render/fluid_shaders.h"
#include "render/fluid_surface.h"
#include "render/gl_program.h"
#include "render/shaders.h"

namespace hs::render {

struct Renderer::Gl {
  GLuint background = 0, wall = 0, particles = 0, lines = 0, flow = 0;  // programs
  GLuint vao = 0;
  // wall positions, normals, colours; particle centres, colours; lines; flow from, to, colours,
  // widths
  GLuint buffers[10] = {};
};

Renderer::Renderer() : m_gl(std::make_unique<Gl>()) {
  Gl& g = *m_gl;
  g.background = linkProgram(shaders::kBackgroundVs, shaders::kBackgroundFs, nullptr, "background");
  g.wall = linkProgram(shaders::kWallVs, shaders::kWallFs, shaders::kLighting, "wall");
  const std::string sphereLibrary = std::string(shaders::kLighting) + shaders::kSphereHit;
  g.particles = linkProgram(shaders::kParticleVs, shaders::kParticleFs, sphereLibrary.c_str(), "particles");
  g.lines = linkProgram(shaders::kLineVs, shaders::kLineFs, nullptr, "lines");
  g.flow = linkProgram(shaders::kFlowLineVs, shaders::kFlowLineFs, nullptr, "flow lines");
  glGenVertexArrays(1, &g.vao);
  glGenBuffers(10, g.buffers);
}

Renderer::~Renderer() {
  m_liquid.reset();
  Gl& g = *m_gl;
  glDeleteBuffers(10, g.buffers);
  glDeleteVertexArrays(1, &g.vao);
  for (GLuint p : {g.background, g.wall, g.particles, g.lines, g.flow}) glDeleteProgram(p);
}

namespace {


// Makes `program` current with the camera's matrices.
void useProgram(GLuint program, const CameraMatrices& camera) {
  glUseProgram(program);
  setMat4(program, "uView", camera.view);
  setMat4(program, "uProjection", camera.projection);
}

void setLight(GLuint program, const Light& light) {
  setVec3(program, "uKey", light.key.normalized());
  setVec3(program, "uFill", light.fill.normalized());
  setFloat(program, "uAmbient", light.ambient);
  setFloat(program, "uKeyStrength", light.keyStrength);
  setFloat(program, "uFillStrength", light.fillStrength);
  setFloat(program, "uSpecular", light.specular);
  setFloat(program, "uShininess", light.shininess);
}

// A plane (n, d) transforms with the inverse transpose of the point transform.
Vec4f viewPlane(const ClipPlane& clip, const Mat4f& view) {
  return view.inverse().transpose() * Vec4f(clip.normal.x(), clip.normal.y(), clip.normal.z(), clip.offset);
}

void setClip(GLuint program, const ClipPlane& clip, bool on, const Mat4f& view) {
  const Vec4f plane = viewPlane(clip, view);
  glUniform4f(glGetUniformLocation(program, "uClip"), plane.x(), plane.y(), plane.z(), plane.w());
  glUniform1i(glGetUniformLocation(program, "uClipOn"), on ? 1 : 0);
}

// Clears colour and depth and fills the screen with the vertical gradient; leaves the depth
// test on for what follows.
void drawBackground(GLuint program, const Scene& scene) {
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glDepthMask(GL_TRUE);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
  glUseProgram(program);
  setVec3(program, "uTop", scene.backgroundTop);
  setVec3(program, "uBottom", scene.backgroundBottom);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
}

void drawLines(GLuint program, GLuint buffer, const LineSet& lines, const CameraMatrices& camera) {
  useProgram(program, camera);
  setVec3(program, "uColour", lines.colour);
  upload(buffer, lines.points);
  attribute(0, buffer);
  glDrawArrays(GL_LINES, 0, GLsizei(lines.points.size()));
  glDisableVertexAttribArray(0);
}

void uploadParticles(const GLuint (&buffers)[2], const ParticleCloud& cloud) {
  upload(buffers[0], cloud.centres);
  upload(buffers[1], cloud.colours.size() == cloud.centres.size()
                         ? cloud.colours
                         : std::vector<Vec3f>(cloud.centres.size(), Vec3f(0.2f, 0.4f, 0.9f)));
}

// One instanced camera-facing rectangle per particle (centres and colours one per instance).
void drawParticles(GLuint program, const GLuint (&buffers)[2], const Scene& scene,
                   const CameraMatrices& camera) {
  const ParticleCloud& cloud = scene.particles;
  useProgram(program, camera);
  setFloat(program, "uRadius", cloud.radius);
  setFloat(program, "uOpacity", cloud.opacity);
  setLight(program, scene.light);
  setClip(program, scene.clip, scene.clip.enabled && scene.clip.clipParticles, camera.view);
  uploadParticles(buffers, cloud);
  attribute(0, buffers[0], 1);
  attribute(1, buffers[1], 1);
  const bool seeThrough = cloud.opacity < 1;
  if (seeThrough) {
    // Blended over the opaque wall already drawn, writing no depth, so each sphere lets what
    // is behind it (other blood, the far wall) show through.
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
  }
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(cloud.centres.size()));
  if (seeThrough) {
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
  }
  glVertexAttribDivisor(0, 0);
  glVertexAttribDivisor(1, 0);
  glDisableVertexAttribArray(0);
  glDisableVertexAttribArray(1);
}

// The wall's triangles; buffers: positions, normals, colours.
void drawWall(GLuint program, const GLuint (&buffers)[3], const Scene& scene, const CameraMatrices& camera) {
  const WallMesh& wall = scene.wall;
  useProgram(program, camera);
  setLight(program, scene.light);
  setClip(program, scene.clip, scene.clip.enabled, camera.view);
  setFloat(program, "uOpacity", wall.opacity);
  setVec3(program, "uCutColour", wall.cutColour);
  upload(buffers[0], wall.positions);
  upload(buffers[1], wall.normals);
  upload(buffers[2], wall.colours);
  for (GLuint i = 0; i < 3; ++i) attribute(i, buffers[i]);
  const auto count = GLsizei(wall.positions.size());
  glEnable(GL_CLIP_DISTANCE0);
  if (wall.opacity >= 1) {
    glDrawArrays(GL_TRIANGLES, 0, count);
  } else {
    // See-through: far side first, then near side, blended over what is behind, without
    // hiding the blood from the depth buffer.
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glDrawArrays(GL_TRIANGLES, 0, count);
    glCullFace(GL_BACK);
    glDrawArrays(GL_TRIANGLES, 0, count);
    glDisable(GL_CULL_FACE);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
  }
  glDisable(GL_CLIP_DISTANCE0);
  for (GLuint i = 0; i < 3; ++i) glDisableVertexAttribArray(i);
}


// The flow lines: one instanced ribbon of 4 vertices per segment; buffers: from, to, colours,
// widths. Depth-tested against what is drawn (an opaque wall hides them), writing no depth.
void drawFlow(GLuint program, const GLuint (&buffers)[4], const Scene& scene, const CameraMatrices& camera,
              int width, int height) {
  const FlowLines& flow = scene.flow;
  useProgram(program, camera);
  glUniform2f(glGetUniformLocation(program, "uViewport"), float(width) / 2, float(height) / 2);
  setClip(program, scene.clip, scene.clip.enabled, camera.view);
  upload(buffers[0], flow.from);
  upload(buffers[1], flow.to);
  upload(buffers[2], flow.colours);
  std::vector<float> widths(2 * flow.size());
  for (std::size_t i = 0; i < flow.size(); ++i) widths[2 * i] = flow.widthFrom[i], widths[2 * i + 1] = flow.widthTo[i];
  for (GLuint i = 0; i < 3; ++i) attribute(i, buffers[i], 1);
  glBindBuffer(GL_ARRAY_BUFFER, buffers[3]);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(widths.size() * sizeof(float)), widths.data(), GL_STREAM_DRAW);
  glEnableVertexAttribArray(3);
  glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
  glVertexAttribDivisor(3, 1);
  glEnable(GL_CLIP_DISTANCE0);
  glDepthMask(GL_FALSE);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(flow.size()));
  glDepthMask(GL_TRUE);
  glDisable(GL_CLIP_DISTANCE0);
  for (GLuint i = 0; i < 4; ++i) {
    glVertexAttribDivisor(i, 0);
    glDisableVertexAttribArray(i);
  }
}

}  // namespace

void Renderer::drawBlood(const Scene& scene, const Camera& camera, const CameraMatrices& matrices, int width,
                         int height) {
  const Gl& g = *m_gl;
  const ParticleCloud& cloud = scene.particles;
  if (cloud.look == BloodLook::Spheres) {
    drawParticles(g.particles, {g.buffers[3], g.buffers[4]}, scene, matrices);
    return;
  }
  if (!m_liquid) m_liquid = std::make_unique<FluidSurface>();
  uploadParticles({g.buffers[3], g.buffers[4]}, cloud);
  LiquidFrame frame;
  frame.view = matrices.view;
  frame.projection = matrices.projection;
  frame.tanHalfY = std::tan(camera.fovyDegrees * float(M_PI) / 360);
  frame.tanHalfX = frame.tanHalfY * float(width) / float(height);
  frame.width = width, frame.height = height;
  frame.clipOn = scene.clip.enabled && scene.clip.clipParticles;
  frame.clip = viewPlane(scene.clip, matrices.view);
  frame.key = scene.light.key.normalized();
  screenExtent(cloud.centres, kLiquidSurfaceRadii * cloud.radius, frame);
  m_liquid->draw(cloud, g.buffers[3], g.buffers[4], frame);
  glBindVertexArray(g.vao);
}

void Renderer::draw(const Scene& scene, const Camera& camera, int width, int height) {
  draw(scene, camera, width, height, 0, width);
}

void Renderer::draw(const Scene& scene, const Camera& camera, int width, int height, int x0, int x1) {
  const Gl& g = *m_gl;
  x0 = std::clamp(x0, 0, width);
  x1 = std::clamp(x1, x0, width);
  const bool strip = x0 > 0 || x1 < width;
  if (strip) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(x0, 0, x1 - x0, height);
  }
  const CameraMatrices matrices{camera.viewMatrix(), camera.projectionMatrix(float(width) / float(height))};
  glViewport(0, 0, width, height);
  glBindVertexArray(g.vao);
  for (GLuint i = 0; i < 3; ++i) glDisableVertexAttribArray(i);
  drawBackground(g.background, scene);
  if (!scene.lines.points.empty()) drawLines(g.lines, g.buffers[5], scene.lines, matrices);
  if (!scene.wall.positions.empty())
    drawWall(g.wall, {g.buffers[0], g.buffers[1], g.buffers[2]}, scene, matrices);
  if (!scene.particles.centres.empty()) drawBlood(scene, camera, matrices, width, height);
  if (!scene.valves.positions.empty()) {
    Scene leaflets;  // drawWall draws a scene's wall: the leaflets as one, opaque, cut alike
    leaflets.wall = scene.valves;
    leaflets.wall.opacity = 1;
    leaflets.clip = scene.clip;
    leaflets.light = scene.light;
    drawWall(g.wall, {g.buffers[0], g.buffers[1], g.buffers[2]}, leaflets, matrices);
  }
  if (scene.flow.size() > 0)
    drawFlow(g.flow, {g.buffers[6], g.buffers[7], g.buffers[8], g.buffers[9]}, scene, matrices, width, height);
  glBindVertexArray(0);
  glUseProgram(0);
  if (strip) glDisable(GL_SCISSOR_TEST);
}

}  // namespace hs::render
