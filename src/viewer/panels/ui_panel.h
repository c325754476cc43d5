#pragma once
// The viewer's Dear ImGui windows: the control panel (left), the status corner (top right of
// the scene), the colour key (bottom left of the scene) and the help window. They only read a
// ViewerStatus and write requests into ViewerControls; ViewerApp acts on the requests between
// frames, so nothing here touches the simulation.
// Needs an ImGui frame in progress (between ImGui::NewFrame and ImGui::Render).
#include <optional>
#include <string>
#include <vector>

#include "render/renderer.h"
#include "viewer/panels/blood_controls.h"
#include "viewer/panels/circulation_controls.h"
#include "viewer/panels/circulation_panel.h"
#include "viewer/panels/pump_panel.h"
#include "viewer/region/region_panel.h"

namespace hs::viewer {

// The control panel's folding sections: one is open at a time, so that the whole panel fits a
// 1280x800 window without scrolling (tests/viewer/panels/test_panel_layout.cpp).
enum class PanelSection { None, Circulation, Blood, Region, Display };

// What the user set; the *Requested / *Changed flags are one-frame requests, cleared by the app.
struct ViewerControls {
  bool playing = true;
  float speed = 1;         // simulated seconds per wall-clock second
  int scenarioIndex = -1;  // into the scenario list; -1: a file given on the command line
  bool cycleEnabled = true;
  float heartRateBpm = 72;  // physiological mode
  float contraction = 0;    // m, physiological mode: inward travel of a beating point per systole
  int beatingDuration = 8;  // steps per phase, thesis mode (Table 5.4's BEATING_DURATION)
  float beatingDisplace = 0;  // m per systolic step, thesis mode (BEATING_DISPLACE)
  bool clip = true;
  float clipZ = 0;  // m: what lies at z > clipZ is cut away
  float wallOpacity = 1;
  int bloodColour = 0;  // render::BloodColour: speed, pressure, origin, components, stay
  int bloodLook = 0;    // render::BloodLook: liquid, spheres
  int flowView = 0;     // render::FlowView: off, streaks, arrows
  bool showHelp = false;
  int helpPage = 0;  // the Help window's page (help_window.h)
  bool showLabels = true;  // the anatomy's names and the flow's arrows on the scene (N)
  PanelSection openSection = PanelSection::Region;
  RegionControls region;  // the beating region: bull's-eye, brush, Apply
  BloodControls blood;    // viscosity, particles, start, coupling, valves (restart)
  PumpControls pump;      // the right panel's plots
  CirculationControls circulation;  // preload, afterload, contractility (lumped circulation; restart)
  bool showCirculation = true;      // the PV loop and Wiggers panel under the heart (C)

  bool stepRequested = false;
  bool resetRequested = false;
  bool scenarioChanged = false;
  bool cycleChanged = false;  // cycle on/off, heart rate or contraction: restarts the simulation
  bool screenshotRequested = false;
  bool saveStateRequested = false;  // a checkpoint into the working directory (F5)
  bool resetCameraRequested = false;
  std::optional<render::View> viewRequested;
};

// What the panels show.
struct ViewerStatus {
  std::string scenarioName;
  double time = 0;            // s, simulated
  double dt = 0;              // s per step
  std::string phase;  // the heart's phase's name (cardiac::heartPhaseName), "" without a beating heart
  double cavity = -1;         // m^3; < 0: no heart
  double frameMs = 0;         // wall time per frame, smoothed
  double realTimeFactor = 1;  // simulated / wall seconds achieved, smoothed
  bool behind = false;        // the step budget could not keep up with the requested speed
  bool hasHeart = false, hasBlood = false;
  bool wallYields = false;          // some wall vertex is free for two-way coupling to move
  bool physiological = false;       // cycle timing mode (heart rate applies)
  std::string recordedBeat;         // [motion]: "25 frames over 0.80 s (75 bpm)"; "" = none
  float heartSize = 1;              // m, the cavity's radius at the base: scales the beat's sliders
  double speedMax = 1;              // m/s at the top of the blood colour scale
  double pressureMax = 1;           // mmHg at the top of the pressure colour scale
  int bloodColour = 0;              // what the blood's colour shows (render::BloodColour)
  int flowView = 0;                 // the flow lines drawn (render::FlowView): they carry the speed key
  std::string liquidNote;           // the liquid look's resolution and why (liquid_pacer.h)
  float clipMin = -1, clipMax = 1;  // range of the clipping plane's slider (m)
  std::string message;              // an event to show as a toast: "saved /home/a/heartsim_normal_001.png"
  ResolutionStatus resolution;  // the blood's resolution and its pace (blood_resolution.h)
  RegionStatus region;
  PumpStatus pump;  // the right panel (with a heart)
  CirculationStatus circulation;  // the PV loop and Wiggers panel (lumped circulation)
};

// Where a built-in scenario sits in the preset list: the human-size hearts a student learns
// from, the thesis's own models at their scale (metres across), and blood without a heart.
enum class ScenarioGroup { HumanHeart, ThesisModel, BloodOnly };
const char* scenarioGroupTitle(ScenarioGroup group);

// A built-in scenario for the preset list; the description is its tooltip.
struct ScenarioChoice {
  std::string name, description;
  ScenarioGroup group = ScenarioGroup::HumanHeart;
};

// Width of the control panel in pixels (the camera frames the rest of the window).
inline constexpr float kPanelWidth = 300;

void drawControlPanel(ViewerControls& controls, const ViewerStatus& status,
                      const std::vector<ScenarioChoice>& scenarios, int windowHeight);
// A window's rectangle on the screen (pixels, y down).
struct OverlayBox {
  float x = 0, y = 0, width = 0, height = 0;
};

// The status corner, its bottom right corner kept `rightEdge`, `bottomEdge` less a margin (the
// scene's right and bottom edges). Folded (a lesson open beside the heart): the time, the phase
// and the pace; no name, volume, frame time or liquid note.
OverlayBox drawStatusOverlay(const ViewerStatus& status, float rightEdge, float bottomEdge, bool folded = false);
// The colour key (the wall's colours, the blood's speed scale), its bottom left corner at
// `leftEdge`, `bottomEdge` plus a margin. Folded: the blood's scale alone (without blood, the
// wall's first line). An empty box at (leftEdge, bottomEdge) when there is nothing to key.
OverlayBox drawColourKey(const ViewerStatus& status, float leftEdge, float bottomEdge, bool folded = false);

// "asked 4x, reaching 0.21x" when the simulation cannot keep the asked speed, else "".
std::string speedShortfall(double asked, const ViewerStatus& status);

}  // namespace hs::viewer
