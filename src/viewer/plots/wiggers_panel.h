#pragma once
// A Wiggers diagram of the last complete beat (Wiggers 1915; every physiology text's figure of
// the cardiac cycle): aortic, LV and left-atrial pressure (mmHg) in one panel, LV volume (mL) in
// a second, mitral and aortic flow (mL/s) in a third, on one time axis (ms from the ventricle's
// activation), with the valve events (MC, AO, AC, MO) as vertical lines and the phases between
// them named in a band on top. Needs an ImGui frame in progress; the events and phases come
// from circulation_history.h (tested).
#include <imgui.h>

#include "viewer/plots/circulation_history.h"

namespace hs::viewer {

// Draws into a `size` pixels region at the cursor (and advances the cursor past it).
void drawWiggersDiagram(const CirculationHistory& history, ImVec2 size);

}  // namespace hs::viewer
