#pragma once
// The viewer's right panel, "Heart as a pump": the cycle's phase and the valves, the clinical
// figures of the last complete beat, the mean of this run's last beats ("now") beside the mean
// of the run before the last restart ("before", run_comparison.h), a Compare button opening
// both side by side (compare_window.h), and live plots of the cavity volume, the flow through
// the valves and the pressures on fixed axes (plot_axes.h), the run before in grey. Like the left panel (ui_panel.h) it
// only reads a status and writes its controls; the app fills the status from the simulation
// thread. Needs an ImGui frame in progress.
#include <string>

#include <optional>

#include "cardiac/blood/flow_components.h"
#include "cardiac/circulation.h"
#include "cardiac/circulation/heart_phase.h"
#include "viewer/plots/plot_axes.h"
#include "viewer/plots/plot_history.h"
#include "viewer/plots/pump_readout.h"
#include "viewer/plots/run_comparison.h"

namespace hs::viewer {

struct PumpStatus {
  bool hasHeart = false, hasBlood = false;
  VolumeScale scale;
  BeatReadings beats;
  bool cycleOn = false;
  cardiac::Phase phase = cardiac::Phase::Rest;  // the wall's own clock
  cardiac::HeartPhase heartPhase = cardiac::HeartPhase::None;  // from the valves (heart_phase.h)
  std::string phaseLabel;  // cardiac::heartPhaseLabel: the same line as the information box's
  bool thesisTiming = false;  // the cycle counts steps (thesis Algorithms 2-3), not a heart rate
  cardiac::ValveStates valves;
  cardiac::ValveMode valveMode = cardiac::ValveMode::Timing;
  bool lumped = false;  // the pressures are the lumped circulation's (LV, atrium, aorta)
  PlotAxes axes;        // the plots' fixed value axes
  // The 3D blood's flow components of the last beat whose systole has ended (fractions of its
  // end-diastolic volume, cardiac/blood/flow_components.h) and that beat's number; none before.
  std::optional<cardiac::FlowComponents> flowComponents;
  int flowBeat = 0;
};

struct PumpControls {
  float plotWindowSeconds = 5;  // simulated seconds shown in the plots
  bool showCompare = false;     // the window with the run before and this one side by side
};

// Width of the panel in pixels; shown only with a heart.
inline constexpr float kPumpPanelWidth = 340;

void drawPumpPanel(PumpControls& controls, const PumpStatus& status, const PlotHistory& history,
                   const RunComparison& runs, int windowWidth, int windowHeight);

}  // namespace hs::viewer
