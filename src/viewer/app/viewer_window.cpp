#include "viewer/app/viewer_window.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <cstdint>
#include <string>
#include <vector>

#include "viewer/app/viewer_app.h"

namespace hs::viewer {
namespace {

// GLFW reports errors through a callback without a user pointer; the last message is kept
// here for the one-line error of a failed start.
std::string& lastGlfwError() {
  static std::string message;
  return message;
}

void onGlfwError(int /*code*/, const char* description) {
  lastGlfwError() = description ? description : "unknown";
}

// Mesa's CPU renderers name themselves in GL_RENDERER.
bool softwareRenderer() {
  const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (!name) return false;
  const std::string renderer = name;
  for (const char* cpu : {"llvmpipe", "softpipe", "swrast"})
    if (renderer.find(cpu) != std::string::npos) return true;
  return false;
}

}  // namespace

Window::Window(int width, int height, bool softwareAntialias) {
  glfwSetErrorCallback(onGlfwError);
  if (!glfwInit())
    throw DisplayError("`heartsim view` needs a display (" + lastGlfwError() +
                       "); `heartsim render` draws images without one");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  // Hidden until it is known whether the renderer is a GPU: a software one gets a window
  // without multisampling instead (the samples are fixed when the window is made).
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  for (const int samples : {4, 0}) {
    glfwWindowHint(GLFW_SAMPLES, samples);
    handle = glfwCreateWindow(width, height, "heartsim", nullptr, nullptr);
    if (!handle) {
      glfwTerminate();
      throw DisplayError("`heartsim view` cannot open an OpenGL 3.3 window (" + lastGlfwError() +
                         "); `heartsim render` draws images without a display");
    }
    glfwMakeContextCurrent(handle);
    multisampled = samples > 0;
    if (samples == 0 || softwareAntialias || !softwareRenderer()) break;
    glfwDestroyWindow(handle);
    handle = nullptr;
  }
  glfwShowWindow(handle);
  glfwSwapInterval(1);
}

Window::~Window() {
  glfwDestroyWindow(handle);
  glfwTerminate();
}

ImGuiSession::ImGuiSession(GLFWwindow* window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the user's working directory
  ImGui::StyleColorsLight();
  ImGui::GetStyle().WindowRounding = 0;
  ImGui_ImplGlfw_InitForOpenGL(window, true);  // chains to the callbacks installed before
  ImGui_ImplOpenGL3_Init("#version 330 core");
}

ImGuiSession::~ImGuiSession() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

viz::Image readBackBuffer(int width, int height) {
  std::vector<std::uint8_t> rgb(std::size_t(width) * std::size_t(height) * 3);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  viz::Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = (std::size_t(height - 1 - y) * std::size_t(width) + std::size_t(x)) * 3;
      image.set(x, y, {rgb[i], rgb[i + 1], rgb[i + 2]});
    }
  return image;
}

}  // namespace hs::viewer
