#pragma once
// An offscreen OpenGL 3.3 core context made through EGL without any display or window system
// (Mesa's surfaceless platform, or an EGL device), and a framebuffer object to draw into.
// Works on a machine with no X server and no GPU: Mesa then renders with llvmpipe.
//
// Only one thread may use a context; create it, then make the FrameTarget and the Renderer
// while it is current (the constructor makes it current).
#include <memory>
#include <string>

#include "viz/image.h"

namespace hs::render {

class GlContext {
 public:
  // Throws std::runtime_error with a one-line reason when no context can be created.
  GlContext();
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  void makeCurrent();
  // "llvmpipe (LLVM 15.0.6, 256 bits)" or the GPU's name, and how the display was obtained.
  [[nodiscard]] std::string description() const;

 private:
  struct State;
  std::unique_ptr<State> m_state;
};

// A width x height colour + depth render target (4x multisampled when the driver allows,
// resolved on read). Needs a current GlContext.
class FrameTarget {
 public:
  // Throws std::runtime_error for sizes outside [1, GL_MAX_RENDERBUFFER_SIZE] or an
  // incomplete framebuffer.
  FrameTarget(int width, int height);
  ~FrameTarget();
  FrameTarget(const FrameTarget&) = delete;
  FrameTarget& operator=(const FrameTarget&) = delete;

  int width() const { return m_width; }
  int height() const { return m_height; }
  int samples() const { return m_samples; }
  // Binds the target for drawing and sets the viewport to the whole target.
  void bind() const;
  // The pixels drawn since bind(), top row first (OpenGL's rows run bottom-up).
  [[nodiscard]] viz::Image read() const;

 private:
  int m_width = 0, m_height = 0, m_samples = 0;
  unsigned m_drawFbo = 0, m_colour = 0, m_depth = 0;
  unsigned m_resolveFbo = 0, m_resolveColour = 0;
};

}  // namespace hs::render
