#pragma once
// The viewer's window-system owners: the GLFW window with its OpenGL 3.3 core context, the
// Dear ImGui session on it, and reading the drawn frame back for screenshots. Each owner
// releases what it made on every exit path, including the error paths of a failed start.
#include "viz/image.h"

struct GLFWwindow;

namespace hs::viewer {

// GLFW's window and library as one owner. Throws DisplayError (viewer_app.h) when there is no
// display or no OpenGL 3.3 context on it. The window is antialiased (4x multisampling) unless
// the OpenGL implementation draws on the CPU (Mesa llvmpipe, softpipe, swrast: no GPU, e.g.
// under Xvfb) and `softwareAntialias` is false: there multisampling costs about 40% of the
// frame time.
struct Window {
  GLFWwindow* handle = nullptr;
  bool multisampled = false;
  Window(int width, int height, bool softwareAntialias);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;
};

// ImGui with its GLFW and OpenGL3 backends on the window; installs the backends' callbacks
// after (and chained to) those set before.
struct ImGuiSession {
  explicit ImGuiSession(GLFWwindow* window);
  ~ImGuiSession();
  ImGuiSession(const ImGuiSession&) = delete;
  ImGuiSession& operator=(const ImGuiSession&) = delete;
};

// The back buffer as drawn so far (before the swap), top row first.
viz::Image readBackBuffer(int width, int height);

}  // namespace hs::viewer
