#include "render/gl_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace hs::render {
namespace {

bool hasExtension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = std::strstr(list, name); p != nullptr; p = std::strstr(p + n, name)) {
    const bool startOk = p == list || p[-1] == ' ';
    const bool endOk = p[n] == ' ' || p[n] == '\0';
    if (startOk && endOk) return true;
  }
  return false;
}

std::string eglErrorName(EGLint error) {
  switch (error) {
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    default: return "EGL error " + std::to_string(error);
  }
}

// An initialised display: Mesa's surfaceless platform first (no window system, no device
// file needed: it falls back to llvmpipe), then the first EGL device, then the default display.
EGLDisplay openDisplay(std::string& how) {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  EGLint major = 0, minor = 0;
  if (hasExtension(client, "EGL_MESA_platform_surfaceless") && hasExtension(client, "EGL_EXT_platform_base")) {
    EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor)) {
      how = "EGL surfaceless platform";
      return d;
    }
  }
  if (hasExtension(client, "EGL_EXT_platform_device") && hasExtension(client, "EGL_EXT_device_enumeration")) {
    EGLint count = 0;
    EGLDeviceEXT devices[8];
    if (eglQueryDevicesEXT(8, devices, &count)) {
      for (EGLint i = 0; i < count; ++i) {
        EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor)) {
          how = "EGL device " + std::to_string(i);
          return d;
        }
      }
    }
  }
  EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  if (d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor)) {
    how = "EGL default display";
    return d;
  }
  return EGL_NO_DISPLAY;
}

}  // namespace

struct GlContext::State {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  EGLSurface surface = EGL_NO_SURFACE;  // a 1x1 pbuffer, only without EGL_KHR_surfaceless_context
  std::string how;
};

GlContext::GlContext() : m_state(std::make_unique<State>()) {
  State& s = *m_state;
  s.display = openDisplay(s.how);
  if (s.display == EGL_NO_DISPLAY) {
    // No hardware device and no surfaceless platform: ask Mesa for its software rasteriser
    // (llvmpipe) and try once more. Does not override a user's own setting.
    setenv("LIBGL_ALWAYS_SOFTWARE", "1", 0);
    s.display = openDisplay(s.how);
    if (s.display == EGL_NO_DISPLAY)
      throw std::runtime_error("no OpenGL context: EGL found no display (is Mesa's libegl-mesa0 installed?)");
  }
  const auto fail = [&](const std::string& what) {
    const std::string reason = what + " (" + eglErrorName(eglGetError()) + ", " + s.how + ")";
    eglTerminate(s.display);
    s.display = EGL_NO_DISPLAY;
    throw std::runtime_error("no OpenGL context: " + reason);
  };
  if (!eglBindAPI(EGL_OPENGL_API)) fail("EGL cannot bind desktop OpenGL");
  const char* extensions = eglQueryString(s.display, EGL_EXTENSIONS);
  const bool surfaceless = hasExtension(extensions, "EGL_KHR_surfaceless_context");

  const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE,
                                    surfaceless ? 0 : EGL_PBUFFER_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  if (!eglChooseConfig(s.display, configAttributes, &config, 1, &configs) || configs < 1) {
    if (!surfaceless || !hasExtension(extensions, "EGL_KHR_no_config_context")) fail("no EGL config for OpenGL");
    config = EGL_NO_CONFIG_KHR;
  }
  const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                      EGL_NONE};
  s.context = eglCreateContext(s.display, config, EGL_NO_CONTEXT, contextAttributes);
  if (s.context == EGL_NO_CONTEXT) fail("EGL cannot create an OpenGL 3.3 core context");
  if (!surfaceless) {
    const EGLint pbufferAttributes[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
    s.surface = eglCreatePbufferSurface(s.display, config, pbufferAttributes);
    if (s.surface == EGL_NO_SURFACE) fail("EGL cannot create a pbuffer surface");
  }
  makeCurrent();
}

GlContext::~GlContext() {
  if (!m_state || m_state->display == EGL_NO_DISPLAY) return;
  eglMakeCurrent(m_state->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (m_state->surface != EGL_NO_SURFACE) eglDestroySurface(m_state->display, m_state->surface);
  if (m_state->context != EGL_NO_CONTEXT) eglDestroyContext(m_state->display, m_state->context);
  eglTerminate(m_state->display);
}

void GlContext::makeCurrent() {
  if (!eglMakeCurrent(m_state->display, m_state->surface, m_state->surface, m_state->context))
    throw std::runtime_error("no OpenGL context: eglMakeCurrent failed (" + eglErrorName(eglGetError()) + ")");
}

std::string GlContext::description() const {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return std::string(renderer ? renderer : "?") + ", OpenGL " + (version ? version : "?") + ", " + m_state->how;
}

FrameTarget::FrameTarget(int width, int height) : m_width(width), m_height(height) {
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
  if (width < 1 || height < 1 || width > maxSize || height > maxSize)
    throw std::runtime_error("image size " + std::to_string(width) + "x" + std::to_string(height) +
                             " is outside 1.." + std::to_string(maxSize) + " pixels");
  GLint maxSamples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
  m_samples = std::min(4, int(maxSamples));

  glGenFramebuffers(1, &m_drawFbo);
  glBindFramebuffer(GL_FRAMEBUFFER, m_drawFbo);
  glGenRenderbuffers(1, &m_colour);
  glBindRenderbuffer(GL_RENDERBUFFER, m_colour);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, m_samples, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_colour);
  glGenRenderbuffers(1, &m_depth);
  glBindRenderbuffer(GL_RENDERBUFFER, m_depth);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, m_samples, GL_DEPTH_COMPONENT24, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, m_depth);
  const GLenum drawStatus = glCheckFramebufferStatus(GL_FRAMEBUFFER);

  glGenFramebuffers(1, &m_resolveFbo);
  glBindFramebuffer(GL_FRAMEBUFFER, m_resolveFbo);
  glGenRenderbuffers(1, &m_resolveColour);
  glBindRenderbuffer(GL_RENDERBUFFER, m_resolveColour);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_resolveColour);
  const GLenum resolveStatus = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (drawStatus != GL_FRAMEBUFFER_COMPLETE || resolveStatus != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("OpenGL framebuffer incomplete (status " + std::to_string(drawStatus) + ", " +
                             std::to_string(resolveStatus) + ")");
  bind();
}

FrameTarget::~FrameTarget() {
  const GLuint framebuffers[] = {m_drawFbo, m_resolveFbo};
  const GLuint renderbuffers[] = {m_colour, m_depth, m_resolveColour};
  glDeleteFramebuffers(2, framebuffers);
  glDeleteRenderbuffers(3, renderbuffers);
}

void FrameTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, m_drawFbo);
  glViewport(0, 0, m_width, m_height);
}

viz::Image FrameTarget::read() const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, m_drawFbo);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, m_resolveFbo);
  glBlitFramebuffer(0, 0, m_width, m_height, 0, 0, m_width, m_height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, m_resolveFbo);
  std::vector<std::uint8_t> rgba(std::size_t(m_width) * std::size_t(m_height) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, m_width, m_height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) throw std::runtime_error("OpenGL error " + std::to_string(error) + " reading pixels");
  viz::Image image(m_width, m_height);
  for (int y = 0; y < m_height; ++y) {
    const std::uint8_t* row = rgba.data() + std::size_t(m_height - 1 - y) * std::size_t(m_width) * 4;
    for (int x = 0; x < m_width; ++x) image.set(x, y, {row[4 * x], row[4 * x + 1], row[4 * x + 2]});
  }
  bind();
  return image;
}

}  // namespace hs::render
