#pragma once
// A live line plot for the viewer's panel, drawn with ImGui's draw list (Debian's ImGui has no
// ImPlot): a title with the unit, a legend with each line's latest value, a value axis with
// tick labels, simulated time along the bottom, and on hover the values at that time. Needs an
// ImGui frame in progress; the arithmetic it rests on (plot_history.h) is tested separately.
#include <cstdint>
#include <string>
#include <vector>

#include "viewer/plot_history.h"

namespace hs::viewer {

struct PlotSeries {
  const char* label;          // "mitral"
  double PumpSample::*value;  // the SI value it draws
  std::uint32_t colour;       // ImU32 (IM_COL32)
};

struct PlotSpec {
  const char* title = "";    // "Cavity volume"
  std::string unit;          // "mL"
  double scale = 1;          // shown value = SI value x scale
  const char* tooltip = "";  // what it shows, for a student
  std::vector<PlotSeries> series;
  bool includeZero = false;  // the value axis always shows zero (flows, pressures)
  // A second unit beside the first in the legend and on hover (mmHg beside Pa): value x scale x
  // secondScale, or none when secondUnit is empty.
  std::string secondUnit;
  double secondScale = 0;
};

// height: of the chart itself in pixels (the title and legend come on top).
void drawPlot(const char* id, const PlotSpec& spec, const PlotHistory& history, float height);

// Values as a panel shows them: four significant digits, and no exponent for large numbers.
std::string formatValue(double value);

}  // namespace hs::viewer
