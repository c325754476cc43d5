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
#include <vector>

#include "cardiac/heart_simulation.h"
#include "io/output_paths.h"
#include "io/scenario_file.h"
#include "render/renderer.h"
#include "render/scene.h"
#include "viewer/camera_controller.h"
#include "viewer/pacing.h"
#include "viewer/plot_history.h"
#include "viewer/region_editor.h"
#include "viewer/simulation_runner.h"
#include "viewer/ui_panel.h"
#include "viewer/viewer_window.h"

namespace hs::viewer {

namespace {

using Clock = std::chrono::steady_clock;

// A brush dab to apply to the simulation's wall at the next access.
struct BrushDab {
  BrushQuery query;
  bool erase = false;
};

class ViewerApp {
 public:
  explicit ViewerApp(const ViewerOptions& options)
      : m_options(options),
        m_baseScenario(options.scenario),
        m_scenarios(builtinScenarioChoices()),
        m_window(options.width, options.height, !options.screenshot.empty()),
        m_runner(options.threads) {
    glfwSetWindowUserPointer(m_window.handle, this);
    glfwSetScrollCallback(m_window.handle, [](GLFWwindow* w, double, double dy) {
      static_cast<ViewerApp*>(glfwGetWindowUserPointer(w))->m_scroll += dy;
    });
    m_imgui = std::make_unique<ImGuiSession>(m_window.handle);
    m_renderer = std::make_unique<render::Renderer>();
    m_controls.scenarioIndex = scenarioIndex(options.builtinName);
    startScenario(m_baseScenario);
  }

  void run() {
    m_lastFrame = Clock::now();
    std::vector<double> frameSeconds;
    for (int frame = 0; !glfwWindowShouldClose(m_window.handle); ++frame) {
      const bool last = m_options.frames > 0 && frame + 1 >= m_options.frames;
      const auto start = Clock::now();
      drawFrame(last && !m_options.screenshot.empty() ? m_options.screenshot : std::string());
      if (m_options.frames > 0) frameSeconds.push_back(std::chrono::duration<double>(Clock::now() - start).count());
      if (last) {
        reportFrameTimes(frameSeconds);
        return;
      }
    }
    // Closed by the user: the last frame once more, for the screenshot.
    if (!m_options.screenshot.empty()) drawFrame(m_options.screenshot);
  }

 private:
  ViewerOptions m_options;
  cardiac::Scenario m_baseScenario;  // as loaded, before the panel's cycle and blood settings
  std::vector<ScenarioChoice> m_scenarios;
  Window m_window;
  std::unique_ptr<ImGuiSession> m_imgui;
  std::unique_ptr<render::Renderer> m_renderer;
  std::unique_ptr<CameraController> m_camera;
  ViewerControls m_controls;
  ViewerStatus m_status;
  RegionEditor m_region;
  PlotHistory m_history;
  std::vector<BrushDab> m_dabs;  // painted this frame, applied at the frame's access
  bool m_sentPlaying = true;     // what the simulation thread was last told
  bool m_started = false;        // a simulation is running (a failed restart keeps it)
  BloodControls m_runningBlood;  // the blood settings of the simulation running
  Clock::time_point m_lastFrame;
  double m_scroll = 0;
  int m_dragButton = -1;  // GLFW mouse button of a drag that began over the scene
  double m_lastX = 0, m_lastY = 0;
  int m_screenshotCount = 0;
  SimulationRunner m_runner;  // last, so destroyed first: its thread stops before the app goes

  // The position of a built-in scenario in the preset list; -1 for any other name.
  int scenarioIndex(const std::string& name) const {
    const auto found = std::find_if(m_scenarios.begin(), m_scenarios.end(),
                                    [&](const ScenarioChoice& c) { return c.name == name; });
    return found == m_scenarios.end() ? -1 : int(found - m_scenarios.begin());
  }

  // A new scenario: controls from its settings, the camera framing it. When it cannot start,
  // the one running stays, with its controls.
  void startScenario(const cardiac::Scenario& scenario) {
    const cardiac::Scenario previousBase = m_baseScenario;
    const ViewerControls previousControls = m_controls;
    const RegionEditor previousRegion = m_region;
    m_baseScenario = scenario;
    setControls(scenario, m_controls);
    m_region = RegionEditor();  // a region applied to the last scenario is not this one's
    if (!restart()) {
      m_baseScenario = previousBase, m_controls = previousControls, m_region = previousRegion;
      // The list shows the scenario that still runs (or its name, when it came from a file).
      m_controls.scenarioIndex = scenarioIndex(m_status.scenarioName);
      return;
    }
    render::Box bounds;
    m_runner.access([&](SimulationState& s) {
      const cardiac::HeartSimulation& sim = *s.sim;
      m_region.startScenario(sim, m_controls.region);
      bounds = render::sceneBounds(sim);
      m_status.hasHeart = sim.hasHeart();
      m_status.pump.scale = volumeScaleFor(s.monitor->last().cavity);
      const int blood = sim.hasBlood() ? int(sim.particles().size() - sim.firstBloodParticle()) : 0;
      m_controls.blood = bloodControlsFrom(scenario, blood);
    });
    m_controls.clip = m_status.hasHeart;
    m_status.clipMin = bounds.min.z();
    m_status.clipMax = bounds.max.z();
    m_controls.clipZ = std::clamp(0.0f, m_status.clipMin, m_status.clipMax);
    m_camera = std::make_unique<CameraController>(bounds, 1.0f);
    resetCamera(render::View::Front);
  }

  // From t = 0 with the configured scenario; false (and a message) when it is rejected and a
  // simulation already runs, which then goes on.
  bool restart() {
    try {
      m_runner.start(configuredScenario(m_baseScenario, m_controls, m_region));
    } catch (const std::invalid_argument& e) {
      if (!m_started) throw;
      m_status.message = std::string("cannot restart: ") + e.what();
      return false;
    }
    m_started = true;
    m_runningBlood = m_controls.blood;
    m_status.message.clear();
    m_history.clear();
    return true;
  }

  // The pump panel's width, when it is shown (with a heart).
  float rightPanelWidth() const { return m_status.hasHeart ? kPumpPanelWidth : 0; }

  // Frames the bounds in the part of the window between the panels.
  void resetCamera(render::View view) {
    int w = 0, h = 0;
    glfwGetWindowSize(m_window.handle, &w, &h);
    h = std::max(h, 1);
    const float free = std::max(float(w) - kPanelWidth - rightPanelWidth(), float(w) * 0.3f);
    m_camera->setAspect(free / float(h));
    m_camera->setView(view);
    m_camera->pan((kPanelWidth - rightPanelWidth()) / 2, 0, h);
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
      const std::string& name = m_scenarios[std::size_t(c.scenarioIndex)].name;
      try {
        startScenario(io::loadScenario(name));
      } catch (const std::exception& e) {
        m_status.message = "cannot load " + name + ": " + e.what();
      }
    } else if (regionApplied || c.resetRequested || c.cycleChanged || c.blood.changed) {
      if (!restart() && c.blood.changed) {
        // Back to what runs, so that Reset restarts what is shown.
        c.blood = m_runningBlood;
        m_status.message += " (blood settings put back)";
      }
      if (regionApplied && m_status.message.empty())
        m_status.message = "beating region applied: " + std::to_string(m_region.selection().count()) +
                           " vertices; restarted from t = 0";
    }
    if (c.viewRequested) resetCamera(*c.viewRequested);
    if (c.resetCameraRequested) resetCamera(render::View::Front);
    c.scenarioChanged = c.resetRequested = c.cycleChanged = c.resetCameraRequested = c.blood.changed = false;
    c.viewRequested.reset();
  }

  // Paints along the cursor's path since the last frame (window pixels), every half brush
  // radius, so a fast stroke leaves no gaps.
  void paintStroke(float x0, float y0, float x1, float y1, int width, int height, bool erase) {
    if (!m_status.hasHeart) return;
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
      m_dabs.push_back({query, erase});
    }
  }

  // The brush's outline at the cursor while painting: orange adds, blue removes (Shift).
  void drawBrushOutline() const {
    const ImGuiIO& io = ImGui::GetIO();
    if (!m_controls.region.paintMode || io.WantCaptureMouse || !m_status.hasHeart) return;
    const float r = m_controls.region.brushRadiusPx;
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    draw->AddCircle(io.MousePos, r, IM_COL32(30, 30, 30, 200), 48, 3.0f);
    draw->AddCircle(io.MousePos, r, io.KeyShift ? IM_COL32(90, 170, 255, 255) : IM_COL32(255, 170, 40, 255),
                    48, 1.5f);
  }

  // The frame's one visit to the simulation thread's state (the worker waits meanwhile, so it
  // is kept short): controls in; brush dabs applied; status, plot samples and the scene out.
  render::Scene exchange(double frameSeconds, const render::SceneOptions& options) {
    render::Scene scene;
    m_runner.access([&](SimulationState& s) {
      ViewerControls& c = m_controls;
      // Play / pause from the panel goes to the thread; a pause from the thread (after Step, or
      // an invalid simulation) comes back to the panel.
      if (c.playing != m_sentPlaying) s.playing = c.playing;
      if (c.stepRequested) s.stepRequested = true, s.playing = false;
      c.stepRequested = false;
      c.playing = m_sentPlaying = s.playing;
      s.speed = double(c.speed);
      const cardiac::HeartSimulation& sim = *s.sim;
      for (const BrushDab& dab : m_dabs) m_region.paint(sim, dab.query, dab.erase, c.region);
      for (const PumpSample& sample : s.newSamples) m_history.push(sample);
      s.newSamples.clear();
      if (!s.message.empty()) m_status.message = s.message, s.message.clear();
      m_status.realTimeFactor = s.paceFactor;
      m_status.behind = s.behind && s.playing;
      readStatus(s, m_status);
      m_status.bloodColour = c.bloodColour;
      m_region.fillStatus(m_status.region, sim.scenario().cycle.enabled);
      scene = render::buildScene(sim, options);
    });
    m_dabs.clear();
    m_status.frameMs += 0.1 * (frameSeconds * 1000 - m_status.frameMs);
    m_history.setWindow(double(m_controls.pump.plotWindowSeconds));
    int w = 0, h = 0;
    glfwGetWindowSize(m_window.handle, &w, &h);
    // The length of a pixel at the camera's target, where the heart is.
    const double pixel = 2 * double(m_camera->distance()) *
                         std::tan(double(m_camera->camera().fovyDegrees) * M_PI / 360) /
                         double(std::max(h, 1));
    m_status.region.brushWorldRadius = pixel * double(m_controls.region.brushRadiusPx);
    return scene;
  }

  void saveScreenshot(const std::string& path, int width, int height) {
    readBackBuffer(width, height).savePng(path);
    m_status.message = "saved " + path;
  }

  std::string nextScreenshotName() {
    std::string name;
    do {
      char text[96];
      std::snprintf(text, sizeof text, "heartsim_%s_%03d.png", io::safeFileStem(m_status.scenarioName).c_str(),
                    ++m_screenshotCount);
      name = text;
    } while (std::filesystem::exists(name));
    return name;
  }

  // A scripted run's frame rate, for benchmarks (docs/performance.md): the first 10 frames
  // (shader compilation, the first steps) are left out.
  static void reportFrameTimes(const std::vector<double>& seconds) {
    const FrameTimeSummary s = summariseFrameTimes(seconds, 10);
    std::fprintf(stderr, "heartsim: %d frames: %.1f ms mean, %.1f fps, 95%% within %.1f ms\n", s.frames, s.meanMs,
                 s.fps, s.p95Ms);
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
    // The panel's display settings of the last frame: the panels are drawn below, from the
    // status this exchange brings.
    render::SceneOptions options;
    options.clip = m_controls.clip && m_status.hasHeart;
    options.clipZ = m_controls.clipZ;
    options.wallOpacity = m_controls.wallOpacity;
    options.beating = m_region.highlight(m_controls.region);
    options.bloodColour = render::BloodColour(std::clamp(m_controls.bloodColour, 0, 2));
    const render::Scene scene = exchange(wallSeconds, options);

    int w = 0, h = 0, fbw = 0, fbh = 0;
    glfwGetWindowSize(m_window.handle, &w, &h);
    glfwGetFramebufferSize(m_window.handle, &fbw, &fbh);
    drawControlPanel(m_controls, m_status, m_scenarios, h);
    drawPumpPanel(m_controls.pump, m_status.pump, m_history, w, h);
    drawStatusOverlay(m_status, float(w) - rightPanelWidth());
    drawColourKey(m_status, kPanelWidth, h);
    drawHelpWindow(m_controls.showHelp, w, h);
    drawBrushOutline();
    ImGui::Render();

    if (fbw > 0 && fbh > 0) {
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      // The panels are opaque: the scene is drawn only between them.
      const double pixels = double(fbw) / double(std::max(w, 1));
      m_renderer->draw(scene, m_camera->camera(), fbw, fbh, int(std::floor(kPanelWidth * pixels)),
                       int(std::ceil((double(w) - rightPanelWidth()) * pixels)));
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
