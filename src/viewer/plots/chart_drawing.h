#pragma once
// Drawing pieces the circulation figures share (pv_loop_panel, wiggers_panel): a chart's frame
// in pixels with its value ranges, ticks and grid, dashed lines and series clipped to the
// frame. Drawn with ImGui's draw list (Debian's ImGui 1.86 has no ImPlot). Needs an ImGui frame
// in progress; the axis arithmetic is plot_history.h's (tested).
#include <imgui.h>

#include <span>
#include <string>

#include "viewer/plots/plot_history.h"

namespace hs::viewer {

// Light, print-like colours: the figures should read like a textbook's.
inline constexpr ImU32 kChartBackground = IM_COL32(255, 255, 255, 255);
inline constexpr ImU32 kChartGrid = IM_COL32(228, 230, 236, 255);
inline constexpr ImU32 kChartBorder = IM_COL32(150, 150, 160, 255);
inline constexpr ImU32 kChartText = IM_COL32(60, 60, 70, 255);

// The chart's inner rectangle (pixels) and what its edges stand for (display units).
struct ChartFrame {
  float x0 = 0, y0 = 0, x1 = 1, y1 = 1;
  AxisRange x, y;
  [[nodiscard]] float px(double v) const { return x0 + float((v - x.lo) / (x.hi - x.lo)) * (x1 - x0); }
  [[nodiscard]] float py(double v) const { return y1 - float((v - y.lo) / (y.hi - y.lo)) * (y1 - y0); }
  [[nodiscard]] ImVec2 at(double xv, double yv) const { return {px(xv), py(yv)}; }
  // Display units at a pixel.
  [[nodiscard]] double xAt(float pixel) const {
    return x.lo + double(pixel - x0) / double(x1 - x0) * (x.hi - x.lo);
  }
  [[nodiscard]] double yAt(float pixel) const {
    return y.lo + double(y1 - pixel) / double(y1 - y0) * (y.hi - y.lo);
  }
  [[nodiscard]] bool contains(ImVec2 p) const { return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1; }
};

// How many ticks fit along `pixels` with `spacing` pixels between them (at least 2).
int ticksFitting(float pixels, float spacing);
// Tick labels with as many decimals as the step needs, and no "-0".
std::string tickLabel(double value, double step);

// White ground, then the grid at the ticks with labels left of the frame (y) and, when
// `xLabels`, under it (x). The zero line is darker. `yLabelsInside`: the y labels kept within
// the frame's height, for charts stacked close (a label centred on a tick at the edge would
// meet the neighbour's).
void drawChartGrid(ImDrawList* draw, const ChartFrame& f, int maxXTicks, int maxYTicks, bool xLabels,
                   bool yLabelsInside = false);
void drawChartBorder(ImDrawList* draw, const ChartFrame& f);

// A dashed straight line (a sequence of `dash`-pixel strokes with equal gaps).
void drawDashedLine(ImDrawList* draw, ImVec2 a, ImVec2 b, ImU32 colour, float dash, float thickness);

// Text centred on x at height y.
void drawCentredText(ImDrawList* draw, float x, float y, ImU32 colour, const char* text);

// A coloured swatch and its label at `p`; returns the x after it.
float drawLegendEntry(ImDrawList* draw, ImVec2 p, ImU32 colour, const char* label);

// Colour with its alpha scaled by `alpha` (0..1).
ImU32 fade(ImU32 colour, float alpha);

}  // namespace hs::viewer
