#include "viewer/plots/chart_drawing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hs::viewer {

int ticksFitting(float pixels, float spacing) { return std::max(2, int(pixels / std::max(spacing, 1.0f))); }

std::string tickLabel(double value, double step) {
  char text[32];
  const int decimals = std::clamp(int(-std::floor(std::log10(step) + 1e-9)), 0, 6);
  if (std::abs(value) < step * 1e-6) value = 0;
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

void drawChartGrid(ImDrawList* draw, const ChartFrame& f, int maxXTicks, int maxYTicks, bool xLabels,
                   bool yLabelsInside) {
  draw->AddRectFilled(ImVec2(f.x0, f.y0), ImVec2(f.x1, f.y1), kChartBackground);
  const ImU32 zero = IM_COL32(175, 175, 185, 255);
  const AxisTicks yt = niceTicks(f.y.lo, f.y.hi, maxYTicks);
  for (int i = 0; i < yt.count; ++i) {
    const double v = yt.first + i * yt.step;
    const float y = std::round(f.py(v));
    draw->AddLine(ImVec2(f.x0, y), ImVec2(f.x1, y), std::abs(v) < yt.step * 1e-6 ? zero : kChartGrid);
    const std::string label = tickLabel(v, yt.step);
    const ImVec2 size = ImGui::CalcTextSize(label.c_str());
    const float top =
        yLabelsInside ? std::clamp(y - size.y / 2, f.y0, std::max(f.y0, f.y1 - size.y)) : y - size.y / 2;
    draw->AddText(ImVec2(f.x0 - 4 - size.x, top), kChartText, label.c_str());
  }
  const AxisTicks xt = niceTicks(f.x.lo, f.x.hi, maxXTicks);
  for (int i = 0; i < xt.count; ++i) {
    const double v = xt.first + i * xt.step;
    const float x = std::round(f.px(v));
    draw->AddLine(ImVec2(x, f.y0), ImVec2(x, f.y1), std::abs(v) < xt.step * 1e-6 ? zero : kChartGrid);
    if (!xLabels) continue;
    const std::string label = tickLabel(v, xt.step);
    const float w = ImGui::CalcTextSize(label.c_str()).x;
    draw->AddText(ImVec2(std::clamp(x - w / 2, f.x0 - w / 2, f.x1 - w / 2), f.y1 + 2), kChartText,
                  label.c_str());
  }
}

void drawChartBorder(ImDrawList* draw, const ChartFrame& f) {
  draw->AddRect(ImVec2(f.x0, f.y0), ImVec2(f.x1 + 1, f.y1 + 1), kChartBorder);
}

void drawDashedLine(ImDrawList* draw, ImVec2 a, ImVec2 b, ImU32 colour, float dash, float thickness) {
  const float length = std::hypot(b.x - a.x, b.y - a.y);
  if (length <= 0 || dash <= 0) return;
  const ImVec2 d((b.x - a.x) / length, (b.y - a.y) / length);
  for (float s = 0; s < length; s += 2 * dash) {
    const float e = std::min(s + dash, length);
    draw->AddLine(ImVec2(a.x + d.x * s, a.y + d.y * s), ImVec2(a.x + d.x * e, a.y + d.y * e), colour,
                  thickness);
  }
}

void drawCentredText(ImDrawList* draw, float x, float y, ImU32 colour, const char* text) {
  draw->AddText(ImVec2(x - ImGui::CalcTextSize(text).x / 2, y), colour, text);
}

float drawLegendEntry(ImDrawList* draw, ImVec2 p, ImU32 colour, const char* label) {
  const float h = ImGui::GetTextLineHeight();
  draw->AddLine(ImVec2(p.x, p.y + h / 2), ImVec2(p.x + 14, p.y + h / 2), colour, 2.5f);
  draw->AddText(ImVec2(p.x + 18, p.y), kChartText, label);
  return p.x + 18 + ImGui::CalcTextSize(label).x + 10;
}

ImU32 fade(ImU32 colour, float alpha) {
  const auto a = ImU32(float((colour >> IM_COL32_A_SHIFT) & 0xFF) * std::clamp(alpha, 0.0f, 1.0f));
  return (colour & ~IM_COL32_A_MASK) | (a << IM_COL32_A_SHIFT);
}

}  // namespace hs::viewer
