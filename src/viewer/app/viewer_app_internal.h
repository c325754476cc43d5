#pragma once
// ViewerApp, the viewer's frame loop behind runViewer (viewer_app.h), shared by its two source
// files: viewer_app.cpp (start-up, restarts, the panel's requests, mouse and keys) and
// viewer_frame.cpp (one frame: the exchange with the simulation thread, the panels, the
// scene, the overlays and the pictures). Internal to src/viewer.
#include <array>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cardiac/heart_simulation.h"
#include "io/output/output_paths.h"
#include "io/scenario/scenario_file.h"
#include "render/renderer.h"
#include "render/scene.h"
#include "viewer/app/camera_controller.h"
#include "viewer/app/liquid_pacer.h"
#include "viewer/app/pacing.h"
#include "viewer/app/resolution_probe.h"
#include "viewer/app/scene_framing.h"
#include "viewer/app/scene_labels.h"
#include "viewer/app/scene_overlays.h"
#include "viewer/app/scene_windows.h"
#include "viewer/app/simulation_runner.h"
#include "viewer/app/toasts.h"
#include "viewer/app/viewer_app.h"
#include "viewer/app/viewer_keys.h"
#include "viewer/app/viewer_window.h"
#include "viewer/lessons/lesson_panel.h"
#include "viewer/panels/compare_window.h"
#include "viewer/panels/help_window.h"
#include "viewer/panels/ui_panel.h"
#include "viewer/plots/circulation_history.h"
#include "viewer/plots/plot_axes.h"
#include "viewer/plots/plot_history.h"
#include "viewer/plots/run_comparison.h"
#include "viewer/region/region_editor.h"

namespace hs::viewer::detail {

using Clock = std::chrono::steady_clock;

// A brush dab to apply to the simulation's wall at the next access.
struct BrushDab {
  BrushQuery query;
  bool erase = false;
};

class ViewerApp {
 public:
  explicit ViewerApp(const ViewerOptions& options);

  void run();

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
  LiquidPacer m_liquidPacer;         // the liquid look's resolution for 25 fps
  // The streaks' trajectories, sampled once a frame: 40 ms, so that a few frames make a streak
  // at the simulation's usual pace in the viewer.
  render::PathlineRecorder m_pathlines{0.04, 2};
  std::unique_ptr<LessonPlayer> m_lesson;  // with --lesson
  LessonRequests m_lessonRequests;         // from the lesson window, for the next frame
  // The start-up measurement of the blood's levels (the simulation is held while it runs) and
  // the paces it measured.
  std::unique_ptr<ResolutionProbe> m_probe;
  std::array<std::optional<double>, kResolutionCount> m_measuredPace;
  // Where the simulation stood when it was let go after start-up: a scripted run's pace.
  std::optional<Clock::time_point> m_paceStart;
  double m_simulatedAtStart = 0, m_steppingAtStart = 0;
  SimulationRunner m_runner;  // last, so destroyed first: its thread stops before the app goes

  // The position of a built-in scenario in the preset list; -1 for any other name.
  int scenarioIndex(const std::string& name) const;

  // A new scenario: controls from its settings, the camera framing it. When it cannot start,
  // the one running stays, with its controls.
  void startScenario(const cardiac::Scenario& scenario);

  // From t = 0 with the configured scenario; false (and a message) when it is rejected and a
  // simulation already runs, which then goes on.
  // `change`: what this restart changed ("region applied"), for the "before" label; "" for a
  // new scenario.
  bool restart(const std::string& change = "");

  // The lesson window's width while it is shown: the heart is framed to its right.

  // The pump panel's width, when it is shown: with a heart, in a window wide enough to keep a
  // scene of kMinSceneWidth beside both panels.
  static constexpr float kMinSceneWidth = 320;
  float rightPanelWidth() const;

  // The circulation panel's height when it is shown (the lumped circulation, not hidden by C).
  float stripHeight(int windowHeight) const;

  // Frames the bounds in the part of the window between the panels, above the circulation panel.
  void resetCamera(render::View view);

  // The circulation panel shown, hidden or resized: the heart moves into the space left,
  // keeping the user's view.
  void followStrip(int windowHeight);

  void handleInput();

  // Measures the blood's levels (auto resolution with blood and no count fixed); followProbe,
  // each frame, shows its progress and starts the level it picks when it is done.
  void startResolutionProbe();
  void followProbe();

  void applyRequests();
  void saveState();

  // Paints along the cursor's path since the last frame (window pixels), every half brush
  // radius, so a fast stroke leaves no gaps.
  void paintStroke(float x0, float y0, float x1, float y1, int width, int height, bool erase);

  // The frame's one visit to the simulation thread's state (the worker waits meanwhile, so it
  // is kept short): controls in; brush dabs applied; status, plot samples and the scene out.
  render::Scene exchange(double frameSeconds, const render::SceneOptions& options);

  // announce: a toast gives the picture's full path (not for the scripted pictures, which
  // would show the previous one's message in the next).
  void saveScreenshot(const std::string& path, int width, int height, bool announce);

  // The status's pending message becomes a toast; a refusal or a stop is a warning.
  void postMessage();

  std::string nextScreenshotName();

  // A scripted run's frame rate, for benchmarks (docs/performance.md): the first 10 frames
  // (shader compilation, the first steps) are left out; and the simulation's pace since it
  // was let go after start-up, with its particle count.
  void reportScriptedRun(const std::vector<double>& seconds);

  void drawFrame(const std::string& captureTo);
};

}  // namespace hs::viewer::detail
