#include "render/fluid_surface.h"

#include <algorithm>
#include <cmath>

#include "render/fluid_shaders.h"
#include "render/gl_program.h"
#include "render/renderer.h"
#include "render/shaders.h"

namespace hs::render {
namespace {

// Filter and shading constants, in particle radii r (the blood's own length scale):
constexpr float kFilterRadii = 3;      // spatial reach of the bilateral filter: 3 r
constexpr float kFalloffRadii = 6;  // range weight's depth scale: 6 r (see the note on terraces below)
// Opacity alpha = 1 - exp(-k T) (Beer-Lambert) from the thickness T summed over the surface's
// spheres: 1.6 r wide and 2 r apart, they add about 4/3 pi (1.6 r)^3 / (2 r)^2 = 4.3 r per layer
// of particles; k = 0.53 / r makes one layer 90% opaque, two 99%, four (a cavity's depth is
// dozens) opaque to a unit of 8-bit colour, so the colour key reads true.
constexpr float kAbsorptionPerRadius = 0.53f;
constexpr int kMaxFilterPixels = 20;   // cap of the filter's half width at full resolution

GLuint makeTexture(GLint internalFormat, GLenum format, GLenum type, int width, int height) {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, internalFormat, width, height, 0, format, type, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return texture;
}

// A framebuffer drawing into the given colour textures (and depth buffer, if any).
GLuint makeFramebuffer(std::initializer_list<GLuint> colours, GLuint depth) {
  GLuint fbo = 0;
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  GLenum buffers[4] = {};
  GLenum attachment = GL_COLOR_ATTACHMENT0;
  for (GLuint texture : colours) {
    glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, texture, 0);
    buffers[attachment - GL_COLOR_ATTACHMENT0] = attachment;
    ++attachment;
  }
  glDrawBuffers(GLsizei(colours.size()), buffers);
  if (depth) glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("OpenGL framebuffer of the liquid surface incomplete");
  return fbo;
}

void setInt(GLuint program, const char* name, int value) { glUniform1i(glGetUniformLocation(program, name), value); }

void setSphereUniforms(GLuint program, float radius, const LiquidFrame& frame) {
  glUseProgram(program);
  setMat4(program, "uView", frame.view);
  setMat4(program, "uProjection", frame.projection);
  setFloat(program, "uRadius", radius);
  glUniform4f(glGetUniformLocation(program, "uClip"), frame.clip.x(), frame.clip.y(), frame.clip.z(), frame.clip.w());
  setInt(program, "uClipOn", frame.clipOn ? 1 : 0);
}

void bindTextures(std::initializer_list<GLuint> textures) {
  GLenum unit = GL_TEXTURE0;
  for (GLuint texture : textures) {
    glActiveTexture(unit++);
    glBindTexture(GL_TEXTURE_2D, texture);
  }
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace

void screenExtent(const std::vector<Vec3f>& centres, float radius, LiquidFrame& frame) {
  const float pixelsPerUnit = float(frame.height) / (2 * frame.tanHalfY);  // at a depth of 1
  const Mat4f toClip = frame.projection * frame.view;
  float x0 = float(frame.width), y0 = float(frame.height), x1 = 0, y1 = 0;
  for (const Vec3f& c : centres) {
    const Vec4f p = toClip * Vec4f(c.x(), c.y(), c.z(), 1);
    if (p.w() <= radius) {  // at or behind the eye's plane: no projection bounds it
      x0 = y0 = 0, x1 = float(frame.width), y1 = float(frame.height);
      break;
    }
    const float reach = radius * pixelsPerUnit / (p.w() - radius) + 2;  // the outline's widest, plus a margin
    const float x = (p.x() / p.w() * 0.5f + 0.5f) * float(frame.width);
    const float y = (p.y() / p.w() * 0.5f + 0.5f) * float(frame.height);
    x0 = std::min(x0, x - reach), x1 = std::max(x1, x + reach);
    y0 = std::min(y0, y - reach), y1 = std::max(y1, y + reach);
  }
  frame.x0 = std::clamp(int(std::floor(x0)), 0, frame.width);
  frame.y0 = std::clamp(int(std::floor(y0)), 0, frame.height);
  frame.x1 = std::clamp(int(std::ceil(x1)), frame.x0, frame.width);
  frame.y1 = std::clamp(int(std::ceil(y1)), frame.y0, frame.height);
}

FluidSurface::FluidSurface() {
  m_depthProgram = linkProgram(shaders::kParticleVs, shaders::kLiquidDepthFs, shaders::kSphereHit, "liquid depth");
  m_thicknessProgram =
      linkProgram(shaders::kParticleVs, shaders::kLiquidThicknessFs, shaders::kSphereHit, "liquid thickness");
  m_blurProgram = linkProgram(shaders::kFullScreenVs, shaders::kLiquidBlurFs, nullptr, "liquid filter");
  m_compositeProgram = linkProgram(shaders::kFullScreenVs, shaders::kLiquidCompositeFs, nullptr, "liquid surface");
}

FluidSurface::~FluidSurface() {
  resize(0, 0);
  for (GLuint p : {m_depthProgram, m_thicknessProgram, m_blurProgram, m_compositeProgram}) glDeleteProgram(p);
}

void FluidSurface::resize(int width, int height) {
  if (width == m_width && height == m_height) return;
  const GLuint fbos[] = {m_sphereFbo, m_thicknessFbo, m_blurFbo};
  const GLuint textures[] = {m_depth[0], m_depth[1], m_colour[0], m_colour[1], m_thickness};
  glDeleteFramebuffers(3, fbos);
  glDeleteTextures(5, textures);
  glDeleteRenderbuffers(1, &m_depthBuffer);
  m_sphereFbo = m_thicknessFbo = m_blurFbo = m_thickness = m_depthBuffer = 0;
  m_depth[0] = m_depth[1] = m_colour[0] = m_colour[1] = 0;
  m_width = width, m_height = height;
  if (width <= 0 || height <= 0) return;
  for (int i = 0; i < 2; ++i) {
    m_depth[i] = makeTexture(GL_R32F, GL_RED, GL_FLOAT, width, height);
    m_colour[i] = makeTexture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width, height);
  }
  m_thickness = makeTexture(GL_R16F, GL_RED, GL_FLOAT, width, height);
  glGenRenderbuffers(1, &m_depthBuffer);
  glBindRenderbuffer(GL_RENDERBUFFER, m_depthBuffer);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  m_sphereFbo = makeFramebuffer({m_depth[0], m_colour[0]}, m_depthBuffer);
  m_thicknessFbo = makeFramebuffer({m_thickness}, 0);
  m_blurFbo = makeFramebuffer({m_depth[1], m_colour[1]}, 0);
}

void FluidSurface::draw(const ParticleCloud& cloud, GLuint centres, GLuint colours, const LiquidFrame& frame) {
  GLint target = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
  const bool scissor = glIsEnabled(GL_SCISSOR_TEST);
  GLint box[4] = {};
  glGetIntegerv(GL_SCISSOR_BOX, box);
  if (!scissor) box[0] = box[1] = 0, box[2] = frame.width, box[3] = frame.height;
  // The blood's extent within the caller's strip: all that any pass needs to cover.
  const int bx0 = std::max(box[0], frame.x0), by0 = std::max(box[1], frame.y0);
  const int bx1 = std::min(box[0] + box[2], frame.x1), by1 = std::min(box[1] + box[3], frame.y1);
  if (bx1 <= bx0 || by1 <= by0) return;
  const int downsample = std::max(1, cloud.liquidDownsample);
  const int width = std::max(1, frame.width / downsample), height = std::max(1, frame.height / downsample);
  resize(width, height);
  glViewport(0, 0, width, height);
  glEnable(GL_SCISSOR_TEST);
  // At this resolution, with the filter's reach around it (the filter reads that far).
  const int reach = kMaxFilterPixels / downsample + 1;
  glScissor(bx0 / downsample - reach, by0 / downsample - reach, (bx1 - bx0) / downsample + 2 * reach + 1,
            (by1 - by0) / downsample + 2 * reach + 1);

  // 1: nearest sphere's depth and colour.
  glBindFramebuffer(GL_FRAMEBUFFER, m_sphereFbo);
  glClearColor(0, 0, 0, 0);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  const auto count = GLsizei(cloud.centres.size());
  attribute(0, centres, 1);
  attribute(1, colours, 1);
  setSphereUniforms(m_depthProgram, kLiquidSurfaceRadii * cloud.radius, frame);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, count);

  // 2: thickness, every sphere's chord added (the surface's spheres: those of the particles' own
  // radius leave rays that pass between them, which would show as see-through holes).
  glBindFramebuffer(GL_FRAMEBUFFER, m_thicknessFbo);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  setSphereUniforms(m_thicknessProgram, kLiquidSurfaceRadii * cloud.radius, frame);
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, count);
  glDisable(GL_BLEND);
  glVertexAttribDivisor(0, 0);
  glVertexAttribDivisor(1, 0);
  glDisableVertexAttribArray(0);
  glDisableVertexAttribArray(1);

  // 3: the bilateral filter along x (0 -> 1), then along y (1 -> 0).
  glUseProgram(m_blurProgram);
  setFloat(m_blurProgram, "uWorldRadius", kFilterRadii * cloud.radius);
  setFloat(m_blurProgram, "uPixelsPerUnit", float(height) / (2 * frame.tanHalfY));
  setFloat(m_blurProgram, "uFalloff", kFalloffRadii * cloud.radius);
  setInt(m_blurProgram, "uMaxRadius", std::max(1, kMaxFilterPixels / downsample));
  setInt(m_blurProgram, "uDepth", 0);
  setInt(m_blurProgram, "uColour", 1);
  for (int pass = 0; pass < 2; ++pass) {
    glBindFramebuffer(GL_FRAMEBUFFER, pass == 0 ? m_blurFbo : m_sphereFbo);
    bindTextures({m_depth[pass], m_colour[pass]});
    glUniform2i(glGetUniformLocation(m_blurProgram, "uStep"), pass == 0 ? 1 : 0, pass == 0 ? 0 : 1);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }

  // 4: the surface, blended into the caller's framebuffer with its depth.
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(target));
  glViewport(0, 0, frame.width, frame.height);
  glScissor(bx0, by0, bx1 - bx0, by1 - by0);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  // No depth written: the wall is already drawn (the depth test hides the liquid behind it), and
  // the valves' leaflets and flow lines drawn next are to show inside the blood.
  glDepthMask(GL_FALSE);
  glUseProgram(m_compositeProgram);
  bindTextures({m_depth[0], m_colour[0], m_thickness});
  setInt(m_compositeProgram, "uDepth", 0);
  setInt(m_compositeProgram, "uColour", 1);
  setInt(m_compositeProgram, "uThickness", 2);
  setMat4(m_compositeProgram, "uProjection", frame.projection);
  glUniform2f(glGetUniformLocation(m_compositeProgram, "uTanHalf"), frame.tanHalfX, frame.tanHalfY);
  setFloat(m_compositeProgram, "uScale", 1.0f / float(downsample));
  setFloat(m_compositeProgram, "uOpacity", cloud.opacity);
  setFloat(m_compositeProgram, "uAbsorption", kAbsorptionPerRadius / cloud.radius);
  setVec3(m_compositeProgram, "uKey", frame.key);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  bindTextures({0, 0, 0});
  glScissor(box[0], box[1], box[2], box[3]);
  if (!scissor) glDisable(GL_SCISSOR_TEST);
}

}  // namespace hs::render
