#include "render/renderer.h"

#include <epoxy/gl.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hs::render {

// ---- camera ---------------------------------------------------------------------------------

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

const char* viewName(View view) {
  switch (view) {
    case View::Front: return "front";
    case View::Left: return "left";
    case View::Right: return "right";
    case View::Top: return "top";
  }
  return "?";
}

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

Vec3f viewDirection(View view) {
  switch (view) {
    case View::Front: return {0, 0, 1};
    case View::Left: return {-1, 0, 0};
    case View::Right: return {1, 0, 0};
    case View::Top: return {0, 1, 0};
  }
  return {0, 0, 1};
}

Camera viewCamera(View view, const Box& bounds, float aspect) {
  const Vec3f towardEye = viewDirection(view);
  // Top: tilted up over the base from the front view, so x keeps its direction (-x on the
  // left) and anterior (+z) comes to the bottom of the image.
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

// ---- shaders --------------------------------------------------------------------------------
namespace {

constexpr const char* kLighting = R"(
uniform vec3 uKey, uFill;
uniform float uAmbient, uKeyStrength, uFillStrength, uSpecular, uShininess;
// Blinn-Phong with two directional lights in view space; v points from the surface to the eye.
vec3 shade(vec3 base, vec3 n, vec3 v) {
  float diffuse = uAmbient + uKeyStrength * max(dot(n, uKey), 0.0) + uFillStrength * max(dot(n, uFill), 0.0);
  float spec = uSpecular * pow(max(dot(n, normalize(uKey + v)), 0.0), uShininess);
  return base * diffuse + vec3(spec);
}
)";

constexpr const char* kBackgroundVs = R"(#version 330 core
out float vHeight;
void main() {
  // One triangle covering the screen.
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2) * 2.0 - 1.0;
  vHeight = p.y * 0.5 + 0.5;
  gl_Position = vec4(p, 0.0, 1.0);
}
)";
constexpr const char* kBackgroundFs = R"(#version 330 core
in float vHeight;
uniform vec3 uTop, uBottom;
out vec4 colour;
void main() { colour = vec4(mix(uBottom, uTop, vHeight), 1.0); }
)";

constexpr const char* kWallVs = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColour;
uniform mat4 uView, uProjection;
uniform vec4 uClip;  // view space; the cut keeps dot(xyz, p) + w <= 0
uniform bool uClipOn;
out vec3 vViewPos, vNormal, vColour;
void main() {
  vec4 p = uView * vec4(aPosition, 1.0);
  vViewPos = p.xyz;
  vNormal = mat3(uView) * aNormal;
  vColour = aColour;
  // The cut as a clip distance: the rasteriser clips the triangles, so the fragment shader
  // has no discard and a software rasteriser can test depth before shading (several wall
  // layers overlap on screen; only the front one is shaded).
  gl_ClipDistance[0] = uClipOn ? -(dot(uClip.xyz, p.xyz) + uClip.w) : 1.0;
  gl_Position = uProjection * p;
}
)";
constexpr const char* kWallFs = R"(#version 330 core
in vec3 vViewPos, vNormal, vColour;
uniform float uOpacity;
uniform vec3 uCutColour;
out vec4 colour;
vec3 shade(vec3 base, vec3 n, vec3 v);
void main() {
  vec3 v = normalize(-vViewPos);
  if (gl_FrontFacing) {
    colour = vec4(shade(vColour, normalize(vNormal), v), uOpacity);
  } else {
    // Inside the wall's material: the cut face, lit as if it faced the viewer.
    colour = vec4(uCutColour * (0.75 + 0.25 * abs(dot(normalize(vNormal), v))), uOpacity);
  }
}
)";

constexpr const char* kParticleVs = R"(#version 330 core
layout(location = 0) in vec3 aCentre;
layout(location = 1) in vec3 aColour;
uniform mat4 uView, uProjection;
uniform float uRadius;
out vec3 vViewPos, vCentre, vColour;
void main() {
  // A camera-facing rectangle at the centre's depth that just holds the sphere's perspective
  // outline, so few fragments miss the sphere (each one that does still costs a ray test).
  // Screen x is x / -z: its extremes over the sphere lie on the planes x = k (-z) through the
  // eye tangent to it, i.e. the tangents from the origin to the circle of radius r around
  // (c.x, -c.z) in the xz plane; the same for y. With the eye in or at the sphere a generous
  // square stands in.
  vec2 corner = vec2(gl_VertexID & 1, (gl_VertexID >> 1) & 1) * 2.0 - 1.0;
  vec3 c = (uView * vec4(aCentre, 1.0)).xyz;
  float depth = -c.z;
  vec2 offset = corner * uRadius * 1.5;
  if (depth > uRadius * 1.01) {
    for (int a = 0; a < 2; ++a) {
      float spread = asin(uRadius / length(vec2(c[a], depth)));
      float angle = clamp(atan(c[a], depth) + corner[a] * spread, -1.5, 1.5);
      offset[a] = depth * tan(angle) - c[a];
    }
  }
  vec3 p = c + vec3(offset, 0.0);
  vViewPos = p;
  vCentre = c;
  vColour = aColour;
  gl_Position = uProjection * vec4(p, 1.0);
}
)";
constexpr const char* kParticleFs = R"(#version 330 core
in vec3 vViewPos, vCentre, vColour;
uniform mat4 uProjection;
uniform float uRadius;
uniform vec4 uClip;
uniform bool uClipOn;
out vec4 colour;
vec3 shade(vec3 base, vec3 n, vec3 v);
void main() {
  // Ray from the eye through this fragment against the sphere: the nearest hit.
  vec3 d = normalize(vViewPos);
  float b = dot(d, vCentre);
  float disc = b * b - dot(vCentre, vCentre) + uRadius * uRadius;
  if (disc < 0.0) discard;
  vec3 hit = d * (b - sqrt(disc));
  if (uClipOn && dot(uClip.xyz, hit) + uClip.w > 0.0) discard;
  vec4 clipPos = uProjection * vec4(hit, 1.0);
  gl_FragDepth = clipPos.z / clipPos.w * 0.5 + 0.5;
  colour = vec4(shade(vColour, (hit - vCentre) / uRadius, -d), 1.0);
}
)";

constexpr const char* kLineVs = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
uniform mat4 uView, uProjection;
void main() { gl_Position = uProjection * uView * vec4(aPosition, 1.0); }
)";
constexpr const char* kLineFs = R"(#version 330 core
uniform vec3 uColour;
out vec4 colour;
void main() { colour = vec4(uColour, 1.0); }
)";

GLuint compile(GLenum type, const std::vector<const char*>& sources, const char* name) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, GLsizei(sources.size()), sources.data(), nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[1024] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    glDeleteShader(shader);
    throw std::runtime_error(std::string("OpenGL shader '") + name + "' does not compile: " + log);
  }
  return shader;
}

// A program from a vertex and a fragment shader; lit fragment shaders get the shade() function
// as a second shader object.
GLuint link(const char* vs, const char* fs, bool lit, const char* name) {
  const GLuint program = glCreateProgram();
  std::vector<GLuint> shaders = {compile(GL_VERTEX_SHADER, {vs}, name), compile(GL_FRAGMENT_SHADER, {fs}, name)};
  if (lit) shaders.push_back(compile(GL_FRAGMENT_SHADER, {"#version 330 core\n", kLighting}, name));
  for (GLuint s : shaders) glAttachShader(program, s);
  glLinkProgram(program);
  for (GLuint s : shaders) glDeleteShader(s);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[1024] = {};
    glGetProgramInfoLog(program, sizeof log, nullptr, log);
    glDeleteProgram(program);
    throw std::runtime_error(std::string("OpenGL program '") + name + "' does not link: " + log);
  }
  return program;
}

void setVec3(GLuint program, const char* name, const Vec3f& v) {
  glUniform3f(glGetUniformLocation(program, name), v.x(), v.y(), v.z());
}
void setMat4(GLuint program, const char* name, const Mat4f& m) {
  glUniformMatrix4fv(glGetUniformLocation(program, name), 1, GL_FALSE, m.data());
}

void upload(GLuint buffer, const std::vector<Vec3f>& data) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(data.size() * sizeof(Vec3f)), data.data(), GL_STREAM_DRAW);
}

void attribute(GLuint index, GLuint buffer, GLuint divisor = 0) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glEnableVertexAttribArray(index);
  glVertexAttribPointer(index, 3, GL_FLOAT, GL_FALSE, sizeof(Vec3f), nullptr);
  glVertexAttribDivisor(index, divisor);
}

}  // namespace

struct Renderer::Gl {
  GLuint background = 0, wall = 0, particles = 0, lines = 0;  // programs
  GLuint vao = 0;
  GLuint buffers[6] = {};  // wall positions, normals, colours; particle centres, colours; lines
};

Renderer::Renderer() : m_gl(std::make_unique<Gl>()) {
  Gl& g = *m_gl;
  g.background = link(kBackgroundVs, kBackgroundFs, false, "background");
  g.wall = link(kWallVs, kWallFs, true, "wall");
  g.particles = link(kParticleVs, kParticleFs, true, "particles");
  g.lines = link(kLineVs, kLineFs, false, "lines");
  glGenVertexArrays(1, &g.vao);
  glGenBuffers(6, g.buffers);
}

Renderer::~Renderer() {
  Gl& g = *m_gl;
  glDeleteBuffers(6, g.buffers);
  glDeleteVertexArrays(1, &g.vao);
  for (GLuint p : {g.background, g.wall, g.particles, g.lines}) glDeleteProgram(p);
}

namespace {

void setLight(GLuint program, const Light& light) {
  setVec3(program, "uKey", light.key.normalized());
  setVec3(program, "uFill", light.fill.normalized());
  glUniform1f(glGetUniformLocation(program, "uAmbient"), light.ambient);
  glUniform1f(glGetUniformLocation(program, "uKeyStrength"), light.keyStrength);
  glUniform1f(glGetUniformLocation(program, "uFillStrength"), light.fillStrength);
  glUniform1f(glGetUniformLocation(program, "uSpecular"), light.specular);
  glUniform1f(glGetUniformLocation(program, "uShininess"), light.shininess);
}

void setClip(GLuint program, const ClipPlane& clip, bool on, const Mat4f& view) {
  // A plane (n, d) transforms with the inverse transpose of the point transform.
  const Vec4f plane = view.inverse().transpose() * Vec4f(clip.normal.x(), clip.normal.y(), clip.normal.z(), clip.offset);
  glUniform4f(glGetUniformLocation(program, "uClip"), plane.x(), plane.y(), plane.z(), plane.w());
  glUniform1i(glGetUniformLocation(program, "uClipOn"), on ? 1 : 0);
}

}  // namespace

void Renderer::draw(const Scene& scene, const Camera& camera, int width, int height) {
  draw(scene, camera, width, height, 0, width);
}

void Renderer::draw(const Scene& scene, const Camera& camera, int width, int height, int x0, int x1) {
  Gl& g = *m_gl;
  x0 = std::clamp(x0, 0, width);
  x1 = std::clamp(x1, x0, width);
  const bool strip = x0 > 0 || x1 < width;
  if (strip) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(x0, 0, x1 - x0, height);
  }
  const Mat4f view = camera.viewMatrix();
  const Mat4f projection = camera.projectionMatrix(float(width) / float(height));
  glViewport(0, 0, width, height);
  glBindVertexArray(g.vao);
  for (GLuint i = 0; i < 3; ++i) glDisableVertexAttribArray(i);

  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glDepthMask(GL_TRUE);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
  glUseProgram(g.background);
  setVec3(g.background, "uTop", scene.backgroundTop);
  setVec3(g.background, "uBottom", scene.backgroundBottom);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);

  if (!scene.lines.points.empty()) {
    glUseProgram(g.lines);
    setMat4(g.lines, "uView", view);
    setMat4(g.lines, "uProjection", projection);
    setVec3(g.lines, "uColour", scene.lines.colour);
    upload(g.buffers[5], scene.lines.points);
    attribute(0, g.buffers[5]);
    glDrawArrays(GL_LINES, 0, GLsizei(scene.lines.points.size()));
    glDisableVertexAttribArray(0);
  }

  const ParticleCloud& cloud = scene.particles;
  if (!cloud.centres.empty()) {
    glUseProgram(g.particles);
    setMat4(g.particles, "uView", view);
    setMat4(g.particles, "uProjection", projection);
    glUniform1f(glGetUniformLocation(g.particles, "uRadius"), cloud.radius);
    setLight(g.particles, scene.light);
    setClip(g.particles, scene.clip, scene.clip.enabled && scene.clip.clipParticles, view);
    upload(g.buffers[3], cloud.centres);
    upload(g.buffers[4], cloud.colours.size() == cloud.centres.size()
                             ? cloud.colours
                             : std::vector<Vec3f>(cloud.centres.size(), Vec3f(0.2f, 0.4f, 0.9f)));
    attribute(0, g.buffers[3], 1);
    attribute(1, g.buffers[4], 1);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(cloud.centres.size()));
    glVertexAttribDivisor(0, 0);
    glVertexAttribDivisor(1, 0);
    glDisableVertexAttribArray(0);
    glDisableVertexAttribArray(1);
  }

  const WallMesh& wall = scene.wall;
  if (!wall.positions.empty()) {
    glUseProgram(g.wall);
    setMat4(g.wall, "uView", view);
    setMat4(g.wall, "uProjection", projection);
    setLight(g.wall, scene.light);
    setClip(g.wall, scene.clip, scene.clip.enabled, view);
    glUniform1f(glGetUniformLocation(g.wall, "uOpacity"), wall.opacity);
    setVec3(g.wall, "uCutColour", wall.cutColour);
    upload(g.buffers[0], wall.positions);
    upload(g.buffers[1], wall.normals);
    upload(g.buffers[2], wall.colours);
    attribute(0, g.buffers[0]);
    attribute(1, g.buffers[1]);
    attribute(2, g.buffers[2]);
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
  glBindVertexArray(0);
  glUseProgram(0);
  if (strip) glDisable(GL_SCISSOR_TEST);
}

}  // namespace hs::render
