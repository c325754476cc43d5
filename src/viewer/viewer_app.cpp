#include "viewer/viewer_app.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cardiac/heart_simulation.h"
#include "io/scenario_file.h"
#include "render/renderer.h"
#include "render/scene.h"
#include "viewer/camera_controller.h"
#include "viewer/ui_panel.h"
#include "viz/image.h"

namespace hs::viewer {

long Pacing::owe(double wallSeconds, double speed, double dt) {
  debt += std::max(wallSeconds, 0.0) * std::max(speed, 0.0);
  return static_cast<long>(std::floor(debt / dt + 1e-9));
}

bool Pacing::settle(long owed, long taken, double dt) {
  debt -= double(taken) * dt;
  if (taken >= owed) return false;
  debt = std::min(debt, dt);  // what could not be done is dropped, not carried
  return true;
}

namespace {

using Clock = std::chrono::steady_clock;

// GLFW reports errors through a callback without a user pointer; the last message is kept
// here for the one-line error of a failed start.
std::string& lastGlfwError() {
  static std::string message;
  return message;
}

void onGlfwError(int /*code*/, const char* description) {
  lastGlfwError() = description ? description : "unknown";
}

// GLFW's window and library as one owner, so every exit path releases them.
struct Window {
  GLFWwindow* handle = nullptr;
  Window(int width, int height) {
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit())
      throw DisplayError("`heartsim view` needs a display (" + lastGlfwError() +
                         "); `heartsim render` draws images without one");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SAMPLES, 4);
    handle = glfwCreateWindow(width, height, "heartsim", nullptr, nullptr);
    if (!handle) {
      glfwTerminate();
      throw DisplayError("`heartsim view` cannot open an OpenGL 3.3 window (" + lastGlfwError() +
                         "); `heartsim render` draws images without a display");
    }
    glfwMakeContextCurrent(handle);
    glfwSwapInterval(1);
  }
  ~Window() {
    glfwDestroyWindow(handle);
    glfwTerminate();
  }
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;
};

struct ImGuiSession {
  explicit ImGuiSession(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the user's working directory
    ImGui::StyleColorsLight();
    ImGui::GetStyle().WindowRounding = 0;
    ImGui_ImplGlfw_InitForOpenGL(window, true);  // chains to the callbacks installed before
    ImGui_ImplOpenGL3_Init("#version 330 core");
  }
  ~ImGuiSession() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  ImGuiSession(const ImGuiSession&) = delete;
  ImGuiSession& operator=(const ImGuiSession&) = delete;
};

// The back buffer as drawn so far (before the swap), top row first.
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

class ViewerApp {
 public:
  explicit ViewerApp(const ViewerOptions& options)
      : m_options(options),
        m_baseScenario(options.scenario),
        m_scenarios(io::builtinScenarioNames()),
        m_window(options.width, options.height) {
    glfwSetWindowUserPointer(m_window.handle, this);
    glfwSetScrollCallback(m_window.handle, [](GLFWwindow* w, double, double dy) {
      static_cast<ViewerApp*>(glfwGetWindowUserPointer(w))->m_scroll += dy;
    });
    m_imgui = std::make_unique<ImGuiSession>(m_window.handle);
    m_renderer = std::make_unique<render::Renderer>();
    const auto found = std::find(m_scenarios.begin(), m_scenarios.end(), options.builtinName);
    m_controls.scenarioIndex = found == m_scenarios.end() ? -1 : int(found - m_scenarios.begin());
    startScenario(m_baseScenario);
  }

  void run() {
    m_lastFrame = Clock::now();
    for (int frame = 0; !glfwWindowShouldClose(m_window.handle); ++frame) {
      const bool last = m_options.frames > 0 && frame + 1 >= m_options.frames;
      drawFrame(last && !m_options.screenshot.empty() ? m_options.screenshot : std::string());
      if (last) return;
    }
    // Closed by the user: the last frame once more, for the screenshot.
    if (!m_options.screenshot.empty()) drawFrame(m_options.screenshot);
  }

 private:
  ViewerOptions m_options;
  cardiac::Scenario m_baseScenario;  // as loaded, before the panel's cycle settings
  std::vector<std::string> m_scenarios;
  Window m_window;
  std::unique_ptr<ImGuiSession> m_imgui;
  std::unique_ptr<render::Renderer> m_renderer;
  std::unique_ptr<cardiac::HeartSimulation> m_sim;
  std::unique_ptr<CameraController> m_camera;
  ViewerControls m_controls;
  ViewerStatus m_status;
  Pacing m_pacing;
  Clock::time_point m_lastFrame;
  double m_scroll = 0;
  int m_dragButton = -1;  // GLFW mouse button of a drag that began over the scene
  double m_lastX = 0, m_lastY = 0;
  int m_screenshotCount = 0;

  // The scenario with the panel's cycle settings applied.
  cardiac::Scenario configured() const {
    cardiac::Scenario s = m_baseScenario;
    s.cycle.enabled = m_controls.cycleEnabled;
    if (m_controls.heartRateBpm != float(s.cycle.heartRateBpm)) {
      s.cycle.mode = cardiac::TimingMode::Physiological;
      s.cycle.heartRateBpm = cardiac::Real(m_controls.heartRateBpm);
    }
    return s;
  }

  // A new scenario: controls from its settings, the camera framing it.
  void startScenario(const cardiac::Scenario& scenario) {
    m_baseScenario = scenario;
    m_controls.cycleEnabled = scenario.cycle.enabled;
    m_controls.heartRateBpm = float(scenario.cycle.heartRateBpm);
    restart();
    if (!m_sim) return;
    m_controls.clip = m_sim->hasHeart();
    const render::Box bounds = render::sceneBounds(*m_sim);
    m_status.clipMin = bounds.min.z();
    m_status.clipMax = bounds.max.z();
    m_controls.clipZ = std::clamp(0.0f, m_status.clipMin, m_status.clipMax);
    m_camera = std::make_unique<CameraController>(bounds, 1.0f);
    resetCamera(render::View::Front);
  }

  void restart() {
    try {
      m_sim = std::make_unique<cardiac::HeartSimulation>(configured(), m_options.threads);
      m_status.message.clear();
    } catch (const std::invalid_argument& e) {
      if (!m_sim) throw;
      m_status.message = std::string("cannot restart: ") + e.what();
    }
    m_pacing = {};
  }

  // Frames the bounds in the part of the window right of the panel.
  void resetCamera(render::View view) {
    int w = 0, h = 0;
    glfwGetWindowSize(m_window.handle, &w, &h);
    h = std::max(h, 1);
    const float free = std::max(float(w) - kPanelWidth, float(w) * 0.3f);
    m_camera->setAspect(free / float(h));
    m_camera->setView(view);
    m_camera->pan((float(w) - free) / 2, 0, h);
  }

  void handleInput() {
    const ImGuiIO& io = ImGui::GetIO();
    double x = 0, y = 0;
    glfwGetCursorPos(m_window.handle, &x, &y);
    int w = 0, h = 0;
    glfwGetWindowSize(m_window.handle, &w, &h);
    constexpr std::array kButtons = {GLFW_MOUSE_BUTTON_LEFT, GLFW_MOUSE_BUTTON_RIGHT,
                                     GLFW_MOUSE_BUTTON_MIDDLE};
    if (m_dragButton >= 0 && glfwGetMouseButton(m_window.handle, m_dragButton) != GLFW_PRESS)
      m_dragButton = -1;
    if (m_dragButton < 0 && !io.WantCaptureMouse)
      for (const int button : kButtons)
        if (glfwGetMouseButton(m_window.handle, button) == GLFW_PRESS) m_dragButton = button;
    const auto dx = float(x - m_lastX), dy = float(y - m_lastY);
    if (m_dragButton == GLFW_MOUSE_BUTTON_LEFT)
      m_camera->orbit(dx, dy, h);
    else if (m_dragButton >= 0)
      m_camera->pan(dx, dy, h);
    m_lastX = x, m_lastY = y;
    if (!io.WantCaptureMouse && m_scroll != 0) m_camera->zoom(float(m_scroll));
    m_scroll = 0;

    if (io.WantCaptureKeyboard) return;
    const auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
    if (pressed(GLFW_KEY_1) || pressed(GLFW_KEY_F)) m_controls.viewRequested = render::View::Front;
    if (pressed(GLFW_KEY_2) || pressed(GLFW_KEY_L)) m_controls.viewRequested = render::View::Left;
    if (pressed(GLFW_KEY_3)) m_controls.viewRequested = render::View::Right;
    if (pressed(GLFW_KEY_4) || pressed(GLFW_KEY_T)) m_controls.viewRequested = render::View::Top;
    if (pressed(GLFW_KEY_R)) m_controls.resetCameraRequested = true;
    if (pressed(GLFW_KEY_SPACE)) m_controls.playing = !m_controls.playing;
    if (ImGui::IsKeyPressed(GLFW_KEY_S, true)) m_controls.stepRequested = true;
    if (pressed(GLFW_KEY_BACKSPACE)) m_controls.resetRequested = true;
    if (pressed(GLFW_KEY_P)) m_controls.screenshotRequested = true;
    if (pressed(GLFW_KEY_H) || pressed(GLFW_KEY_F1)) m_controls.showHelp = !m_controls.showHelp;
    if (pressed(GLFW_KEY_ESCAPE)) glfwSetWindowShouldClose(m_window.handle, GLFW_TRUE);
  }

  void applyRequests() {
    ViewerControls& c = m_controls;
    if (c.scenarioChanged && c.scenarioIndex >= 0) {
      const std::string& name = m_scenarios[std::size_t(c.scenarioIndex)];
      try {
        startScenario(io::loadScenario(name));
      } catch (const std::exception& e) {
        m_status.message = "cannot load " + name + ": " + e.what();
      }
    } else if (c.resetRequested || c.cycleChanged) {
      restart();
    }
    if (c.viewRequested) resetCamera(*c.viewRequested);
    if (c.resetCameraRequested) resetCamera(render::View::Front);
    c.scenarioChanged = c.resetRequested = c.cycleChanged = c.resetCameraRequested = false;
    c.viewRequested.reset();
  }

  // Steps toward wall time within the frame's budget; the achieved pace goes to the status.
  void advance(double wallSeconds) {
    const double dt = double(m_sim->scenario().simulation.dt);
    long owed = 0;
    if (m_controls.stepRequested) {
      m_controls.playing = false;
      owed = 1;
    } else if (m_controls.playing) {
      owed = m_pacing.owe(std::min(wallSeconds, 0.1), m_controls.speed, dt);
    }
    m_controls.stepRequested = false;
    long taken = 0;
    const auto start = Clock::now();
    while (taken < owed) {
      m_sim->step();
      ++taken;
      if (std::chrono::duration<double>(Clock::now() - start).count() > kStepBudgetSeconds) break;
    }
    const bool behind = m_controls.playing && m_pacing.settle(owed, taken, dt);
    if (m_controls.playing && wallSeconds > 0) {
      const double factor = double(taken) * dt / std::min(wallSeconds, 0.1);
      m_status.realTimeFactor += 0.1 * (factor - m_status.realTimeFactor);
    }
    // Behind when the budget cut the steps short and the pace is clearly below the request.
    m_status.behind = behind && m_status.realTimeFactor < 0.95 * double(m_controls.speed);
    if (taken > 0) {
      const cardiac::TissueStats tissue = m_sim->tissueStats();
      if (!tissue.finite) {
        m_controls.playing = false;
        char text[160];
        std::snprintf(text, sizeof text,
                      "simulation became invalid at t = %.3f s (particle %lld not finite); Reset",
                      m_sim->time(), static_cast<long long>(tissue.firstNonFinite));
        m_status.message = text;
      }
    }
  }

  void updateStatus(double frameSeconds) {
    const cardiac::HeartSimulation& sim = *m_sim;
    m_status.scenarioName = sim.scenario().name;
    m_status.time = sim.time();
    m_status.dt = double(sim.scenario().simulation.dt);
    m_status.hasHeart = sim.hasHeart();
    m_status.hasBlood = sim.hasBlood();
    m_status.physiological = sim.scenario().cycle.mode == cardiac::TimingMode::Physiological;
    m_status.phase =
        sim.hasHeart() && sim.scenario().cycle.enabled ? cardiac::phaseName(sim.lastPhase()) : "";
    m_status.cavityMl = sim.hasHeart() ? double(sim.cavityVolume()) * 1e6 : -1;
    m_status.speedMax = render::defaultSpeedScale(sim.scenario());
    m_status.frameMs += 0.1 * (frameSeconds * 1000 - m_status.frameMs);
  }

  void saveScreenshot(const std::string& path, int width, int height) {
    readBackBuffer(width, height).savePng(path);
    m_status.message = "saved " + path;
  }

  std::string nextScreenshotName() {
    std::string name;
    do {
      char text[96];
      std::snprintf(text, sizeof text, "heartsim_%s_%03d.png", m_sim->scenario().name.c_str(),
                    ++m_screenshotCount);
      name = text;
    } while (std::filesystem::exists(name));
    return name;
  }

  void drawFrame(const std::string& captureTo) {
    const auto now = Clock::now();
    const double wallSeconds = std::chrono::duration<double>(now - m_lastFrame).count();
    m_lastFrame = now;
    glfwPollEvents();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    handleInput();
    applyRequests();
    advance(wallSeconds);
    updateStatus(wallSeconds);

    int w = 0, h = 0, fbw = 0, fbh = 0;
    glfwGetWindowSize(m_window.handle, &w, &h);
    glfwGetFramebufferSize(m_window.handle, &fbw, &fbh);
    drawControlPanel(m_controls, m_status, m_scenarios, h);
    drawStatusOverlay(m_status, w);
    drawHelpWindow(m_controls.showHelp, w, h);
    ImGui::Render();

    if (fbw > 0 && fbh > 0) {
      render::SceneOptions options;
      options.clip = m_controls.clip && m_sim->hasHeart();
      options.clipZ = m_controls.clipZ;
      options.wallOpacity = m_controls.wallOpacity;
      render::Scene scene = render::buildScene(*m_sim, options);
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      m_renderer->draw(scene, m_camera->camera(), fbw, fbh);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      if (!captureTo.empty()) saveScreenshot(captureTo, fbw, fbh);
      if (m_controls.screenshotRequested) {
        try {
          saveScreenshot(nextScreenshotName(), fbw, fbh);
        } catch (const std::runtime_error& e) {
          m_status.message = std::string("screenshot failed: ") + e.what();
        }
      }
    }
    m_controls.screenshotRequested = false;
    glfwSwapBuffers(m_window.handle);
  }
};

}  // namespace

void runViewer(const ViewerOptions& options) {
  ViewerApp app(options);
  app.run();
}

}  // namespace hs::viewer
