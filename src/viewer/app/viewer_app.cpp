#include "viewer/app/viewer_app.h"

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

#include "viewer/app/viewer_app_internal.h"

namespace hs::viewer {
namespace detail {

ViewerApp::ViewerApp(const ViewerOptions& options)
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
  m_controls.bloodLook = int(options.bloodLook);
  m_controls.flowView = int(options.flow);
  m_controls.showLabels = options.labels;
  if (options.lesson) m_lesson = std::make_unique<LessonPlayer>(*options.lesson, options.frames > 0);
  m_controls.blood.resolution = options.resolution.value_or(kScenarioResolution);
  m_status.resolution.fixedBy = options.bloodFixedBy;
  startScenario(m_baseScenario);
  startResolutionProbe();
}

void ViewerApp::run() {
  m_lastFrame = Clock::now();
  std::vector<double> frameSeconds;
  for (int frame = 0; !glfwWindowShouldClose(m_window.handle); ++frame) {
    // A scripted lesson ends with its last step: one more frame, the final screenshot.
    const bool lessonDone = m_lesson && m_lesson->scripted() && m_lesson->finished();
    const bool last = m_options.frames > 0 && (frame + 1 >= m_options.frames || lessonDone);
    if (last && m_lesson && !lessonDone)
      std::fprintf(stderr, "heartsim: the lesson stopped at step %d of %d when the %d frames ran out\n",
                   m_lesson->stepIndex() + 1, m_lesson->stepCount(), m_options.frames);
    const auto start = Clock::now();
    followProbe();
    drawFrame(last && !m_options.screenshot.empty() ? m_options.screenshot : std::string());
    if (m_options.frames > 0) frameSeconds.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    if (last) {
      reportScriptedRun(frameSeconds);
      return;
    }
  }
  // Closed by the user: the last frame once more, for the screenshot.
  if (!m_options.screenshot.empty()) drawFrame(m_options.screenshot);
}

int ViewerApp::scenarioIndex(const std::string& name) const {
  const auto found = std::find_if(m_scenarios.begin(), m_scenarios.end(),
                                  [&](const ScenarioChoice& c) { return c.name == name; });
  return found == m_scenarios.end() ? -1 : int(found - m_scenarios.begin());
}

void ViewerApp::startScenario(const cardiac::Scenario& scenario) {
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
  });
  m_controls.clip = m_status.hasHeart;
  m_status.clipMin = bounds.min.z();
  m_status.clipMax = bounds.max.z();
  m_controls.clipZ = std::clamp(0.0f, m_status.clipMin, m_status.clipMax);
  m_camera = std::make_unique<CameraController>(bounds, 1.0f);
  resetCamera(render::View::Front);
}

bool ViewerApp::restart(const std::string& change) {
  try {
    if (m_options.resume && !m_started) {
      // heartsim view --resume: the first run is the checkpoint's scenario, from its state.
      m_runner.start(m_baseScenario, [&](cardiac::HeartSimulation& sim) {
        io::restoreSimulation(*m_options.resume, sim, m_options.resumeSource);
      });
    } else {
      m_runner.start(configuredScenario(m_baseScenario, m_controls, m_region));
    }
  } catch (const std::invalid_argument& e) {
    if (!m_started) throw;
    m_status.message = std::string("cannot restart: ") + e.what();
    return false;
  }
  m_started = true;
  m_runner.access([&](SimulationState& s) {  // the count the run made (blood.particles = 0 fills)
    const cardiac::HeartSimulation& sim = *s.sim;
    if (sim.hasBlood()) m_controls.blood.particles = int(sim.particles().size() - sim.firstBloodParticle());
  });
  m_status.resolution.level = m_controls.blood.resolution;
  m_status.resolution.measuredPace = m_measuredPace[std::size_t(m_controls.blood.resolution)];
  m_runningBlood = m_controls.blood;
  m_runningCirculation = m_controls.circulation;
  m_status.message.clear();
  m_runs.restart(m_baseScenario.name + (change.empty() ? "" : ", " + change), m_history, m_circulation);
  m_axesFresh = true;
  m_history.clear();
  m_circulation.clear();
  return true;
}

float ViewerApp::rightPanelWidth() const {
  int w = 0, h = 0;
  glfwGetWindowSize(m_window.handle, &w, &h);
  const bool room = float(w) - kPanelWidth - kPumpPanelWidth >= kMinSceneWidth;
  return m_status.hasHeart && room ? kPumpPanelWidth : 0;
}

float ViewerApp::stripHeight(int windowHeight) const {
  return m_status.circulation.lumped && m_controls.showCirculation ? circulationPanelHeight(windowHeight) : 0;
}

void ViewerApp::resetCamera(render::View view) {
  int w = 0, h = 0;
  glfwGetWindowSize(m_window.handle, &w, &h);
  m_framedStrip = stripHeight(h);
  frameView(*m_camera, view, {kPanelWidth, float(w) - rightPanelWidth(), m_framedStrip}, w, h);
}

void ViewerApp::followStrip(int windowHeight) {
  const float strip = stripHeight(windowHeight);
  refitForStrip(*m_camera, m_framedStrip, strip, windowHeight);
  m_framedStrip = strip;
}

void ViewerApp::handleInput() {
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

void ViewerApp::applyRequests() {
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
  if (c.saveStateRequested) saveState();
  c.saveStateRequested = false;
  if (c.viewRequested) resetCamera(*c.viewRequested);
  if (c.resetCameraRequested) resetCamera(render::View::Front);
  c.scenarioChanged = c.resetRequested = c.cycleChanged = c.resetCameraRequested = c.blood.changed = false;
  c.circulation.changed = c.circulation.defaultsRequested = false;
  c.viewRequested.reset();
}

// The simulation as it is, as a checkpoint in the working directory (io/output/checkpoint.h), which
// heartsim view --resume or heartsim run --resume continues.
void ViewerApp::saveState() {
  const io::Checkpoint checkpoint =
      m_runner.access([](SimulationState& s) { return io::captureCheckpoint(*s.sim, nullptr); });
  const std::string name = io::checkpointFileName(checkpoint.time);
  try {
    io::writeCheckpointFile(name, checkpoint);
    m_status.message = "state saved: " + name + " (heartsim view --resume " + name + ")";
  } catch (const io::CheckpointError& e) {
    m_status.message = std::string("saving the state failed: ") + e.what();
  }
}

void ViewerApp::paintStroke(float x0, float y0, float x1, float y1, int width, int height, bool erase) {
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

}  // namespace detail

void runViewer(const ViewerOptions& options) {
  detail::ViewerApp app(options);
  app.run();
}

}  // namespace hs::viewer
