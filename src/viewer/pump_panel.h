#pragma once
// The viewer's right panel, "Heart as a pump": the cycle's phase and the valves, the clinical
// figures of the beat in progress and of the last complete beat, and live plots of the cavity
// volume, the flow through the valves and the pressures. Like the left panel (ui_panel.h) it
// only reads a status and writes its controls; the app fills the status from the simulation
// thread. Needs an ImGui frame in progress.
#include "cardiac/circulation.h"
#include "viewer/plot_history.h"
#include "viewer/pump_readout.h"

namespace hs::viewer {

struct PumpStatus {
  bool hasHeart = false, hasBlood = false;
  VolumeScale scale;
  BeatReadings beats;
  bool cycleOn = false;
  cardiac::Phase phase = cardiac::Phase::Rest;
  bool thesisTiming = false;  // the cycle counts steps (thesis Algorithms 2-3), not a heart rate
  cardiac::ValveStates valves;
  cardiac::ValveMode valveMode = cardiac::ValveMode::Timing;
};

struct PumpControls {
  float plotWindowSeconds = 5;  // simulated seconds shown in the plots
};

// Width of the panel in pixels; shown only with a heart.
inline constexpr float kPumpPanelWidth = 340;

void drawPumpPanel(PumpControls& controls, const PumpStatus& status, const PlotHistory& history,
                   int windowWidth, int windowHeight);

}  // namespace hs::viewer
