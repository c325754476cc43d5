#pragma once
// The viewer's circulation panel: a strip under the heart, between the two side panels, shown
// when the scenario has the lumped circulation (circulation.lumped). It holds the live
// pressure-volume loop (pv_loop_panel.h) and the Wiggers diagram of the last complete beat
// (wiggers_panel.h), headed by the last beat's blood pressure, stroke volume and ejection
// fraction. It sits under the heart rather than in a window of its own so that a student sees
// the loop next to the beating wall without looking for it; `C` hides it. Like the other panels
// it only reads a status; the app fills it from the simulation thread. Needs an ImGui frame in
// progress.
#include <optional>
#include <span>

#include "cardiac/circulation/circulation_trace.h"
#include "cardiac/circulation/lumped_beat.h"
#include "viewer/plots/circulation_history.h"

namespace hs::viewer {

struct CirculationStatus {
  bool lumped = false;                                 // the scenario has the lumped circulation
  cardiac::PressureVolumeRelations relations;          // effective: Ees scaled by the wall's beating share
  std::optional<cardiac::LumpedBeatFigures> lastBeat;  // the last complete beat's figures
};

// The strip's height for a window `windowHeight` pixels tall: about two fifths of it, so the
// heart keeps the larger part.
float circulationPanelHeight(int windowHeight);

// The strip from x = left to x = right at the bottom of the window.
// previousLoop: the run before the restart's last loop, drawn in grey (empty for none).
void drawCirculationPanel(const CirculationStatus& status, const CirculationHistory& history, float left,
                          float right, int windowHeight,
                          std::span<const cardiac::CirculationSample> previousLoop = {});

}  // namespace hs::viewer
