#pragma once
// The Compare window (the pump panel's Compare button): the run before the last restart and the
// run going on side by side, as a student compares two cases: their beat means in two columns
// with the change between them, their cavity volume over one beat on one plot (each run's last
// complete beat, from the start of its systole), and their pressure-volume loops where the
// scenario has the lumped circulation. Reads only; needs an ImGui frame in progress. What it
// draws is computed by run_comparison.h (tested).
#include "viewer/plots/circulation_history.h"
#include "viewer/plots/plot_axes.h"
#include "viewer/plots/plot_history.h"
#include "viewer/plots/run_comparison.h"

namespace hs::viewer {

// open: the window is shown while true; its close box clears it.
void drawCompareWindow(bool& open, const RunComparison& runs, const PlotHistory& history,
                       const CirculationHistory& circulation, const PlotAxes& axes);

}  // namespace hs::viewer
