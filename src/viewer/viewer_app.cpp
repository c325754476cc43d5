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
#include "viewer/circulation_history.h"
#include "viewer/compare_window.h"
#include "viewer/help_window.h"
#include "viewer/pacing.h"
#include "viewer/plot_axes.h"
#include "viewer/plot_history.h"
#include "viewer/region_editor.h"
#include "viewer/run_comparison.h"
#include "viewer/scene_framing.h"
#include "viewer/scene_labels.h"
#include "viewer/scene_overlays.h"
#include "viewer/simulation_runner.h"
#include "viewer/ui_panel.h"
#include "viewer/toasts.h"
#include "viewer/viewer_keys.h"
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
    // Keys as events, so a tap between two frames is not lost (viewer_keys.h); ImGui's own
    // callback, installed next, chains to this one.
    glfwSetKeyCallback(m_window.handle, [](GLFWwindow* w, int key, int, int action, int mods) {
      static_cast<ViewerApp*>(glfwGetWindowUserPointer(w))->m_keys.push(key, action, mods);
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
  CirculationHistory m_circulation;  // the lumped circulation's last beats (circulation panel)
  RunComparison m_runs;              // this run and the one before the last restart
  PlotAxes m_axes;                   // the pump plots' fixed axes, set anew for each run
  bool m_axesFresh = true;           // a run started: its first samples set m_axes
  float m_framedStrip = 0;           // the circulation panel's height the camera is framed for
  std::vector<BrushDab> m_dabs;  // painted this frame, applied at the frame's access
  bool m_sentPlaying = true;     // what the simulation thread was last told
  bool m_started = false;        // a simulation is running (a failed restart keeps it)
  BloodControls m_runningBlood;  // the blood settings of the simulation running
  CirculationControls m_runningCirculation;  // and its circulation settings
  Clock::time_point m_lastFrame;
  double m_scroll = 0;
  int m_dragButton = -1;  // GLFW mouse button of a drag that began over the scene
  double m_lastX = 0, m_lastY = 0;
  int m_screenshotCount = 0;
  KeyEvents m_keys;                // pressed since the last frame
  Toasts m_toasts;                 // messages shown in the scene
  std::vector<SceneLabel> m_labels;  // the anatomy's names, where they are this frame
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
      m_status.circulation.lumped = sim.lumped() != nullptr;
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
  // `change`: what this restart changed ("region applied"), for the "before" label; "" for a
  // new scenario.
  bool restart(const std::string& change = "") {
    try {
      m_runner.start(configuredScenario(m_baseScenario, m_controls, m_region));
    } catch (const std::invalid_argument& e) {
      if (!m_started) throw;
      m_status.message = std::string("cannot restart: ") + e.what();
      return false;
    }
    m_started = true;
    m_runningBlood = m_controls.blood;
    m_runningCirculation = m_controls.circulation;
    m_status.message.clear();
    m_runs.restart(m_baseScenario.name + (change.empty() ? "" : ", " + change), m_history, m_circulation);
    m_axesFresh = true;
    m_history.clear();
    m_circulation.clear();
    return true;
  }

  // The pump panel's width, when it is shown (with a heart).
  float rightPanelWidth() const { return m_status.hasHeart ? kPumpPanelWidth : 0; }

  // The circulation panel's height when it is shown (the lumped circulation, not hidden by C).
  float stripHeight(int windowHeight) const {
    return m_status.circulation.lumped && m_controls.showCirculation ? circulationPanelHeight(windowHeight) : 0;
  }

  // Frames the bounds in the part of the window between the panels, above the circulation panel.
  void resetCamera(render::View view) {
    int w = 0, h = 0;
    glfwGetWindowSize(m_window.handle, &w, &h);
    m_framedStrip = stripHeight(h);
    frameView(*m_camera, view, {kPanelWidth, float(w) - rightPanelWidth(), m_framedStrip}, w, h);
  }

  // The circulation panel shown, hidden or resized: the heart moves into the space left,
  // keeping the user's view.
  void followStrip(int windowHeight) {
    const float strip = stripHeight(windowHeight);
    refitForStrip(*m_camera, m_framedStrip, strip, windowHeight);
    m_framedStrip = strip;
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

    const std::vector<KeyPress> presses = m_keys.take();
    // Typed into a field of the panel, or meant for an open list (Esc closing the scenario list
    // must not quit).
    if (io.WantCaptureKeyboard || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) return;
    if (applyKeys(presses, m_controls, m_region.available())) glfwSetWindowShouldClose(m_window.handle, GLFW_TRUE);
  }

  void applyRequests() {
    ViewerControls& c = m_controls;
    const bool regionApplied = m_region.handleRequests(c.region);
    if (c.circulation.defaultsRequested) {
      c.circulation = circulationControlsFrom(m_baseScenario);
      c.heartRateBpm = float(m_baseScenario.cycle.heartRateBpm);
      c.circulation.changed = true;
    }
    if (c.scenarioChanged && c.scenarioIndex >= 0) {
      const std::string& name = m_scenarios[std::size_t(c.scenarioIndex)].name;
      try {
        startScenario(io::loadScenario(name));
      } catch (const std::exception& e) {
        m_status.message = "cannot load " + name + ": " + e.what();
      }
    } else if (regionApplied || c.resetRequested || c.cycleChanged || c.blood.changed || c.circulation.changed) {
      // A rejected setting goes back to what runs, so that Reset restarts what is shown.
      std::string change;
      const auto add = [&](const char* what) { change += (change.empty() ? "" : ", ") + std::string(what); };
      if (regionApplied) add("region applied");
      if (c.cycleChanged) add(c.cycleEnabled ? "cycle settings changed" : "cycle off");
      if (c.blood.changed) add("blood settings changed");
      if (c.circulation.changed) add("circulation settings changed");
      if (c.resetRequested && change.empty()) add("Reset");
      const bool restarted = restart(change);
      if (!restarted && c.blood.changed) c.blood = m_runningBlood, m_status.message += " (blood settings put back)";
      if (!restarted && c.circulation.changed)
        c.circulation = m_runningCirculation, m_status.message += " (circulation settings put back)";
      if (regionApplied && m_status.message.empty())
        m_status.message = "applied: " + std::to_string(m_region.selection().count()) + " of " +
                           std::to_string(m_region.selection().selectableCount()) +
                           " wall points beat; restarted from t = 0";
    }
    if (c.viewRequested) resetCamera(*c.viewRequested);
    if (c.resetCameraRequested) resetCamera(render::View::Front);
    c.scenarioChanged = c.resetRequested = c.cycleChanged = c.resetCameraRequested = c.blood.changed = false;
    c.circulation.changed = c.circulation.defaultsRequested = false;
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
    for (const BrushQuery& dab : brushDabsAlong(query, x0, y0, x1, y1)) m_dabs.push_back({dab, erase});
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
      if (m_axesFresh && !s.newSamples.empty())  // a new run: its own axes, room for the grey curve
        m_axes = PlotAxes(m_status.pump.scale, s.newSamples.front().cavity, m_runs.previousCurve()),
        m_axesFresh = false;
      holdNewSamples(m_axes, m_history, s.newSamples.size());
      s.newSamples.clear();
      if (!s.message.empty()) m_status.message = s.message, s.message.clear();
      m_status.realTimeFactor = s.paceFactor;
      m_status.behind = s.behind && s.playing;
      readStatus(s, m_status);
      if (const cardiac::CirculationRecorder* recorder = s.monitor->circulation())
        m_circulation.update(recorder->samples(), recorder->beatStarts());
      m_runs.update(m_status.pump.beats.recent, m_status.pump.scale, m_status.circulation.lumped);
      m_status.pump.lumped = m_status.circulation.lumped;
      m_status.pump.axes = m_axes;
      m_status.bloodColour = c.bloodColour;
      m_region.fillStatus(m_status.region, sim.scenario().cycle.enabled);
      const std::vector<std::uint8_t> outOfStep = render::outOfStepRegion(sim);
      m_status.region.outOfStep.fill(false);
      for (std::size_t v = 0; v < outOfStep.size(); ++v)
        if (outOfStep[v]) m_status.region.outOfStep[sim.model().segment[v]] = true;
      m_labels = m_controls.showLabels ? anatomyLabels(sim) : std::vector<SceneLabel>();
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
    std::error_code error;
    const std::filesystem::path full = std::filesystem::absolute(path, error);
    m_status.message = "picture saved: " + (error ? path : full.string());
  }

  // The status's pending message becomes a toast; a refusal or a stop is a warning.
  void postMessage() {
    if (m_status.message.empty()) return;
    const std::string& text = m_status.message;
    const bool warning = text.starts_with("cannot") || text.find("stopped") != std::string::npos ||
                         text.find("failed") != std::string::npos || text.find("invalid") != std::string::npos;
    m_toasts.push(text, warning ? ToastKind::Warning : ToastKind::Info, glfwGetTime());
    m_status.message.clear();
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
    // While a region is chosen or painted, the blood lets it show through.
    if (m_controls.region.paintMode || m_controls.region.showRegion) options.bloodOpacity = 0.3f;
    options.bloodColour = render::BloodColour(std::clamp(m_controls.bloodColour, 0, 2));
    const render::Scene scene = exchange(wallSeconds, options);

    int w = 0, h = 0, fbw = 0, fbh = 0;
    glfwGetWindowSize(m_window.handle, &w, &h);
    glfwGetFramebufferSize(m_window.handle, &fbw, &fbh);
    drawControlPanel(m_controls, m_status, m_scenarios, h);
    drawPumpPanel(m_controls.pump, m_status.pump, m_history, m_runs, w, h);
    followStrip(h);
    drawStatusOverlay(m_status, float(w) - rightPanelWidth(), float(h) - stripHeight(h));
    drawColourKey(m_status, kPanelWidth, float(h) - stripHeight(h));
    if (m_controls.showCirculation)
      drawCirculationPanel(m_status.circulation, m_circulation, kPanelWidth, float(w) - rightPanelWidth(), h,
                           m_runs.previousLoop());
    drawCompareWindow(m_controls.pump.showCompare, m_runs, m_history, m_circulation, m_status.pump.axes);
    const SceneArea area{kPanelWidth, float(w) - rightPanelWidth(), stripHeight(h)};
    drawSceneLabels(m_labels, m_camera->camera(), w, h, area);
    postMessage();
    drawToasts(m_toasts.visible(glfwGetTime()), area);
    drawHelpWindow(m_controls.showHelp, w, h);
    if (m_status.hasHeart) drawBrushOutline(m_controls.region);
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
