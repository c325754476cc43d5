#pragma once
// The live pressure-volume loop of the left ventricle (LV pressure in mmHg against LV volume in
// mL): the last three beats, the newest strongest, a dot at the present step, the valve events
// of the last complete beat at its corners, and the end-systolic (P = Ees (V - V0)) and
// end-diastolic (P = A (exp(B (V - V0)) - 1)) relations it moves between (Suga & Sagawa 1974),
// as physiology texts draw it; the run before the last restart's loop in grey beneath. Needs an ImGui frame in progress; what it draws is computed by
// circulation_history.h (tested).
#include <imgui.h>

#include <span>

#include "cardiac/circulation/circulation_trace.h"
#include "viewer/plots/chart_drawing.h"
#include "viewer/plots/circulation_history.h"

namespace hs::viewer {

// The loop's colours: a run's beat, and the run before the last restart.
inline constexpr ImU32 kLoopColour = IM_COL32(175, 25, 40, 255);
inline constexpr ImU32 kBeforeLoopColour = IM_COL32(150, 150, 150, 255);

// One beat's loop (LV volume in mL across, LV pressure in mmHg up) in the chart `frame`; points
// closer than a pixel to the last one kept are skipped; `closed` joins the end to the start.
void drawPressureVolumeBeat(ImDrawList* draw, const ChartFrame& frame, std::span<const cardiac::CirculationSample> beat,
                            ImU32 colour, float thickness, bool closed = false);

// Draws into a `size` pixels region at the cursor (and advances the cursor past it).
// `relations`: the effective ones (the beating share scales Ees). `before`: the last loop of the
// run before the restart (run_comparison.h), empty for none.
void drawPressureVolumeLoop(const CirculationHistory& history,
                            const cardiac::PressureVolumeRelations& relations, ImVec2 size,
                            std::span<const cardiac::CirculationSample> before = {});

}  // namespace hs::viewer
