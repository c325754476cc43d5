#pragma once
// A live line plot for the viewer's panel, drawn with ImGui's draw list (Debian's ImGui has no
// ImPlot): a title with the unit, a legend with each line's latest value, a fixed value axis
// (plot_axes.h) with tick labels, simulated time along the bottom, the run before the last
// restart in grey (its last beat laid at each of this run's beat onsets) and on hover the
// values at that time. Needs an ImGui frame in progress; the arithmetic it rests on
// (plot_history.h, plot_axes.h, run_comparison.h) is tested separately.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "viewer/plots/plot_history.h"

namespace hs::viewer {

struct PlotSeries {
  const char* label;          // "mitral"
  double PumpSample::*value;  // the SI value it draws (NaN: not known, a gap)
  std::uint32_t colour;       // ImU32 (IM_COL32)
};

struct PlotSpec {
  const char* title = "";    // "Cavity volume"
  std::string unit;          // "mL"
  double scale = 1;          // shown value = SI value x scale
  std::string note;          // after the title: "smoothed over 25 ms"
  const char* tooltip = "";  // what it shows, for a student
  std::vector<PlotSeries> series;
  AxisRange range;  // the value axis (shown units), fixed: plot_axes.h
  // A second unit beside the first in the legend and on hover (mmHg beside Pa): value x scale x
  // secondScale, or none when secondUnit is empty.
  std::string secondUnit;
  double secondScale = 0;
};

// height: of the chart itself in pixels (the title and legend come on top). before: the last
// beat of the run before the restart (times from its start), drawn in grey; empty: none.
void drawPlot(const char* id, const PlotSpec& spec, const PlotHistory& history, float height,
              std::span<const PumpSample> before = {});

// The colour of the run before the restart in every plot.
inline constexpr std::uint32_t kBeforeColour = 0xFF969696;  // IM_COL32(150, 150, 150, 255)

// Values as a panel shows them: four significant digits, and no exponent for large numbers.
std::string formatValue(double value);

}  // namespace hs::viewer
