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
#include "viewer/region_editor.h"
#include "viewer/ui_panel.h"
#include "viewer/viewer_window.h"

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
  RegionEditor m_region;
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
    m_region.configure(s);
    return s;
  }

  // A new scenario: controls from its settings, the camera framing it.
  void startScenario(const cardiac::Scenario& scenario) {
    m_baseScenario = scenario;
    m_controls.cycleEnabled = scenario.cycle.enabled;
    m_controls.heartRateBpm = float(scenario.cycle.heartRateBpm);
    m_region = RegionEditor();  // a region applied to the last scenario is not this one's
    restart();
    if (!m_sim) return;
    m_region.startScenario(*m_sim, m_controls.region);
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
    RegionControls& region = m_controls.region;
    if (m_dragButton == GLFW_MOUSE_BUTTON_LEFT && region.paintMode)
      paintStroke(float(m_lastX), float(m_lastY), float(x), float(y), w, h, io.KeyShift);
    else if (m_dragButton == GLFW_MOUSE_BUTTON_LEFT)
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
    if (pressed(GLFW_KEY_B) && m_region.available()) region.paintMode = !region.paintMode;
    // Each press scales the brush by 1.25, so the range is crossed in a dozen presses.
    if (ImGui::IsKeyPressed(GLFW_KEY_LEFT_BRACKET, true)) region.brushRadiusPx /= 1.25f;
    if (ImGui::IsKeyPressed(GLFW_KEY_RIGHT_BRACKET, true)) region.brushRadiusPx *= 1.25f;
    region.brushRadiusPx =
        std::clamp(region.brushRadiusPx, RegionControls::kMinBrushPx, RegionControls::kMaxBrushPx);
    if (pressed(GLFW_KEY_ENTER) || pressed(GLFW_KEY_KP_ENTER)) region.applyRequested = true;
    if (pressed(GLFW_KEY_ESCAPE)) glfwSetWindowShouldClose(m_window.handle, GLFW_TRUE);
  }

  void applyRequests() {
    ViewerControls& c = m_controls;
    const bool regionApplied = m_region.handleRequests(c.region);
    if (c.scenarioChanged && c.scenarioIndex >= 0) {
      const std::string& name = m_scenarios[std::size_t(c.scenarioIndex)];
      try {
        startScenario(io::loadScenario(name));
      } catch (const std::exception& e) {
        m_status.message = "cannot load " + name + ": " + e.what();
      }
    } else if (regionApplied || c.resetRequested || c.cycleChanged) {
      restart();
      if (regionApplied && m_status.message.empty())
        m_status.message = "beating region applied: " + std::to_string(m_region.selection().count()) +
                           " vertices; restarted from t = 0";
    }
    if (c.viewRequested) resetCamera(*c.viewRequested);
    if (c.resetCameraRequested) resetCamera(render::View::Front);
    c.scenarioChanged = c.resetRequested = c.cycleChanged = c.resetCameraRequested = false;
    c.viewRequested.reset();
  }

  // Paints along the cursor's path since the last frame (window pixels), every half brush
  // radius, so a fast stroke leaves no gaps.
  void paintStroke(float x0, float y0, float x1, float y1, int width, int height, bool erase) {
    if (!m_sim->hasHeart()) return;
    BrushQuery query;
    query.view = brushView(m_camera->camera(), width, height);
    query.radius = m_controls.region.brushRadiusPx;
    // The scene's cut (render::buildScene): what it removes cannot be painted.
    query.clip.enabled = m_controls.clip;
    query.clip.normal = render::Vec3f(0, 0, 1);
    query.clip.offset = -m_controls.clipZ;
    const float length = std::hypot(x1 - x0, y1 - y0);
    const int steps = std::max(1, int(std::ceil(length / (0.5f * query.radius))));
    for (int i = 1; i <= steps; ++i) {
      const float t = float(i) / float(steps);
      query.centreX = x0 + t * (x1 - x0);
      query.centreY = y0 + t * (y1 - y0);
      m_region.paint(*m_sim, query, erase, m_controls.region);
    }
  }

  // The brush's outline at the cursor while painting: orange adds, blue removes (Shift).
  void drawBrushOutline() const {
    const ImGuiIO& io = ImGui::GetIO();
    if (!m_controls.region.paintMode || io.WantCaptureMouse || !m_sim->hasHeart()) return;
    const float r = m_controls.region.brushRadiusPx;
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    draw->AddCircle(io.MousePos, r, IM_COL32(30, 30, 30, 200), 48, 3.0f);
    draw->AddCircle(io.MousePos, r, io.KeyShift ? IM_COL32(90, 170, 255, 255) : IM_COL32(255, 170, 40, 255),
                    48, 1.5f);
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
    m_region.fillStatus(m_status.region, sim.scenario().cycle.enabled);
    int w = 0, h = 0;
    glfwGetWindowSize(m_window.handle, &w, &h);
    // The length of a pixel at the camera's target, where the heart is.
    const double pixel = 2 * double(m_camera->distance()) *
                         std::tan(double(m_camera->camera().fovyDegrees) * M_PI / 360) /
                         double(std::max(h, 1));
    m_status.region.brushWorldRadius = pixel * double(m_controls.region.brushRadiusPx);
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
    drawBrushOutline();
    ImGui::Render();

    if (fbw > 0 && fbh > 0) {
      render::SceneOptions options;
      options.clip = m_controls.clip && m_sim->hasHeart();
      options.clipZ = m_controls.clipZ;
      options.wallOpacity = m_controls.wallOpacity;
      options.beating = m_region.highlight(m_controls.region);
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
