// One frame of the viewer (viewer_app_internal.h).
#include <cfloat>
#include <epoxy/gl.h>  // before GLFW
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

namespace hs::viewer::detail {

render::Scene ViewerApp::exchange(double frameSeconds, const render::SceneOptions& options) {
  render::Scene scene;
  m_runner.access([&](SimulationState& s) {
    ViewerControls& c = m_controls;
    // Play / pause from the panel goes to the thread; a pause from the thread (after Step, or
    // an invalid simulation) comes back to the panel.
    // While the blood's levels are measured at start-up, the simulation waits (m_sentPlaying is
    // false then, so the panel's Play reaches it afterwards).
    const bool held = m_probe != nullptr;
    if (held)
      s.playing = false;
    else if (c.playing != m_sentPlaying)
      s.playing = c.playing;
    if (c.stepRequested && !held) s.stepRequested = true, s.playing = false;
    c.stepRequested = false;
    if (!held) c.playing = m_sentPlaying = s.playing;
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
    m_runs.update(m_status.pump.beats.recent, m_status.pump.scale, m_status.circulation.lumped,
                  m_status.pump.flowComponents);
    m_status.pump.lumped = m_status.circulation.lumped;
    m_status.pump.axes = m_axes;
    m_status.bloodColour = c.bloodColour;
    m_status.flowView = c.flowView;
    m_region.fillStatus(m_status.region, sim.scenario().cycle.enabled);
    const std::vector<std::uint8_t> outOfStep = render::outOfStepRegion(sim);
    m_status.region.outOfStep.fill(false);
    for (std::size_t v = 0; v < outOfStep.size(); ++v)
      if (outOfStep[v]) m_status.region.outOfStep[sim.model().segment[v]] = true;
    m_labels = m_controls.showLabels ? anatomyLabels(sim) : std::vector<SceneLabel>();
    if (options.flow == render::FlowView::Streaks)
      m_pathlines.record(sim);
    else
      m_pathlines.clear();
    // The blood's flow components and stays, from the monitor's bookkeeping, when shown.
    render::SceneOptions drawn = options;
    std::vector<cardiac::FlowComponent> components;
    std::vector<cardiac::Stay> stays;
    if (const cardiac::VentricleBlood* blood = s.monitor->ventricleBlood()) {
      if (options.bloodColour == render::BloodColour::Components) components = blood->components();
      if (options.bloodColour == render::BloodColour::Stay) stays = blood->stays();
    }
    drawn.components = &components;
    drawn.stays = &stays;
    scene = render::buildScene(sim, drawn);
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

void ViewerApp::saveScreenshot(const std::string& path, int width, int height, bool announce) {
  readBackBuffer(width, height).savePng(path);
  if (!announce) return;
  std::error_code error;
  const std::filesystem::path full = std::filesystem::absolute(path, error);
  m_status.message = "picture saved: " + (error ? path : full.string());
}

void ViewerApp::postMessage() {
  if (m_status.message.empty()) return;
  const std::string& text = m_status.message;
  const bool warning = text.starts_with("cannot") || text.find("stopped") != std::string::npos ||
                       text.find("failed") != std::string::npos || text.find("invalid") != std::string::npos;
  m_toasts.push(text, warning ? ToastKind::Warning : ToastKind::Info, glfwGetTime());
  m_status.message.clear();
}

std::string ViewerApp::nextScreenshotName() {
  std::string name;
  do {
    char text[96];
    std::snprintf(text, sizeof text, "heartsim_%s_%03d.png", io::safeFileStem(m_status.scenarioName).c_str(),
                  ++m_screenshotCount);
    name = text;
  } while (std::filesystem::exists(name));
  return name;
}

void ViewerApp::drawFrame(const std::string& captureTo) {
  const auto now = Clock::now();
  const double wallSeconds = std::chrono::duration<double>(now - m_lastFrame).count();
  m_lastFrame = now;
  glfwPollEvents();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  // A scripted run for a picture has no user: the pointer Xvfb leaves in the window's middle
  // would open the tooltip under it in every screenshot.
  if (!m_options.screenshot.empty()) ImGui::GetIO().MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
  ImGui::NewFrame();
  handleInput();
  // The lesson's next action goes into the controls as the panel's would, for applyRequests.
  if (m_lesson) m_lesson->frame(m_lessonRequests, m_status, m_scenarios, m_controls);
  applyRequests();
  // The panel's display settings of the last frame: the panels are drawn below, from the
  // status this exchange brings.
  render::SceneOptions options;
  options.clip = m_controls.clip && m_status.hasHeart;
  options.clipZ = m_controls.clipZ;
  options.wallOpacity = m_controls.wallOpacity;
  options.beating = m_region.highlight(m_controls.region);
  options.bloodColour = render::BloodColour(std::clamp(m_controls.bloodColour, 0, 4));
  // While a region is chosen or painted, the blood lets it show through; but where the blood's
  // colours are the picture (its flow components, how long it stayed) a chosen region gives
  // way to them, so that anterior-infarct's stagnant blood shows at its apex.
  const bool bloodIsThePicture = options.bloodColour == render::BloodColour::Components ||
                                 options.bloodColour == render::BloodColour::Stay;
  if (m_controls.region.paintMode || (m_controls.region.showRegion && !bloodIsThePicture))
    options.bloodOpacity = 0.3f;
  options.bloodLook = render::BloodLook(std::clamp(m_controls.bloodLook, 0, 1));
  options.flow = render::FlowView(std::clamp(m_controls.flowView, 0, 2));
  options.pathlines = &m_pathlines;
  // A --screenshot run is for the picture (it keeps 4x multisampling too): the liquid stays at
  // full resolution; otherwise the pacer keeps 25 fps.
  const bool forPicture = !m_options.screenshot.empty();
  options.liquidDownsample = forPicture ? 1 : m_liquidPacer.downsample();
  const bool liquid = options.bloodLook == render::BloodLook::Liquid && m_status.hasBlood;
  if (!forPicture) m_liquidPacer.observe(wallSeconds * 1000, liquid);
  m_status.liquidNote = !liquid      ? std::string()
                        : forPicture ? std::string("liquid look: full resolution for the picture")
                                     : m_liquidPacer.note();
  const render::Scene scene = exchange(wallSeconds, options);

  int w = 0, h = 0, fbw = 0, fbh = 0;
  glfwGetWindowSize(m_window.handle, &w, &h);
  glfwGetFramebufferSize(m_window.handle, &fbw, &fbh);
  drawControlPanel(m_controls, m_status, m_scenarios, h);
  if (rightPanelWidth() > 0) drawPumpPanel(m_controls.pump, m_status.pump, m_history, m_runs, w, h);
  followStrip(h);
  if (m_controls.showCirculation)
    drawCirculationPanel(m_status.circulation, m_circulation, kPanelWidth, float(w) - rightPanelWidth(), h,
                         m_runs.previousLoop());
  drawCompareWindow(m_controls.pump.showCompare, m_runs, m_history, m_circulation, m_status.pump.axes);
  const SceneArea area{kPanelWidth, float(w) - rightPanelWidth(), stripHeight(h)};
  const std::vector<render::LabelBox> overlays = drawSceneWindows(m_status, m_lesson.get(), m_lessonRequests, area, h);
  drawSceneLabels(m_labels, m_camera->camera(), w, h, area, overlays);
  postMessage();
  drawToasts(m_toasts.visible(glfwGetTime()), area);
  drawHelpWindow(m_controls.showHelp, m_controls.helpPage, w, h);
  if (m_status.hasHeart) drawBrushOutline(m_controls.region);
  ImGui::Render();

  if (fbw > 0 && fbh > 0) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    // The panels are opaque: the scene is drawn only between them.
    const double pixels = double(fbw) / double(std::max(w, 1));
    m_renderer->draw(scene, m_camera->camera(), fbw, fbh, int(std::floor(kPanelWidth * pixels)),
                     int(std::ceil((double(w) - rightPanelWidth()) * pixels)));
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (!captureTo.empty()) saveScreenshot(captureTo, fbw, fbh, false);
    if (m_lesson && m_lesson->screenshotStep() > 0 && !m_options.screenshot.empty())
      saveScreenshot(stepScreenshotPath(m_options.screenshot, m_lesson->screenshotStep()), fbw, fbh, false);
    if (m_controls.screenshotRequested) {
      try {
        saveScreenshot(nextScreenshotName(), fbw, fbh, true);
      } catch (const std::runtime_error& e) {
        m_status.message = std::string("screenshot failed: ") + e.what();
      }
    }
  }
  m_controls.screenshotRequested = false;
  glfwSwapBuffers(m_window.handle);
}

}  // namespace hs::viewer::detail
