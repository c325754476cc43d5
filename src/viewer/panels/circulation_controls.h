#pragma once
// The panel's "Circulation" section, shown when the scenario has the lumped circulation
// (circulation.lumped): preload, afterload (peripheral resistance, arterial compliance),
// contractility and heart rate, in clinical units, each with a tooltip saying what it teaches.
// HeartSimulation builds its LumpedCirculation when it starts and offers no way to change its
// parameters while it runs, so a change restarts from t = 0 with the scenario's setting
// changed, through the same path as Reset and the Blood section; sliders apply when released.
// Needs an ImGui frame for drawCirculationSection; the rest is plain data, unit-tested.
#include "cardiac/scenario.h"

namespace hs::viewer {

// Clinical units, as the scenario keys name them.
struct CirculationControls {
  bool lumped = false;             // the scenario has the lumped circulation: the section is shown
  double atrialPressureMmHg = 8;   // circulation.atrial_pressure_mmhg: preload
  double resistance = 1.05;        // circulation.peripheral_resistance_mmhg_s_per_ml: afterload
  double compliance = 1.4;         // circulation.arterial_compliance_ml_per_mmhg: afterload
  double contractility = 2.7;      // circulation.contractility_mmhg_per_ml: Ees
  bool changed = false;            // one-frame request: restart with these settings
  bool defaultsRequested = false;  // one-frame request: back to the scenario's own values
};

// Slider ranges (clinical units).
struct CirculationRange {
  double lo, hi;
};
inline constexpr CirculationRange kAtrialPressureRange{0, 30};
inline constexpr CirculationRange kResistanceRange{0.3, 4};
inline constexpr CirculationRange kComplianceRange{0.3, 5};
inline constexpr CirculationRange kContractilityRange{0.5, 6};
inline constexpr float kLumpedHeartRateMin = 40, kLumpedHeartRateMax = 180;  // bpm

CirculationControls circulationControlsFrom(const cardiac::Scenario& scenario);
// Writes the controls into the scenario: only the settings that differ from what the scenario
// already says, so unchanged controls leave it bit for bit as it was (a restart runs what
// `heartsim run` runs, not a value converted to clinical units and back).
void applyCirculationControls(const CirculationControls& controls, cardiac::Scenario& scenario);

// The section's sliders. heartRateBpm / heartRateChanged: the panel's heart rate (ui_panel.h),
// which the lumped circulation's beat timing follows; showFigures: the loop and Wiggers panel.
void drawCirculationSection(CirculationControls& controls, float& heartRateBpm, bool& heartRateChanged,
                            bool& showFigures);

}  // namespace hs::viewer
