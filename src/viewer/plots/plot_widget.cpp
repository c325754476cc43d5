#include "viewer/plots/plot_widget.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "viewer/plots/chart_drawing.h"
#include "viewer/plots/panel_widgets.h"
#include "viewer/plots/run_comparison.h"

namespace hs::viewer {
namespace {

struct Frame {
  float x0, y0, x1, y1;  // the chart's inner rectangle (pixels)
  double t0, t1;         // time range (s)
  AxisRange range;       // value range (shown units)
  float x(double t) const { return x0 + float((t - t0) / (t1 - t0)) * (x1 - x0); }
  float y(double v) const { return y1 - float((v - range.lo) / (range.hi - range.lo)) * (y1 - y0); }
};

std::string valueWithUnits(const PlotSpec& spec, double shown) {
  std::string text = formatValue(shown) + " " + spec.unit;
  if (!spec.secondUnit.empty())
    text += " (" + formatValue(shown * spec.secondScale) + " " + spec.secondUnit + ")";
  return text;
}

// The newest value that is known (a smoothed flow lags by half its window).
double newestKnown(const PlotHistory& history, const PlotSeries& s) {
  for (std::size_t i = history.size(), n = 0; i-- > 0 && n < 256; ++n)
    if (std::isfinite(history[i].*s.value)) return history[i].*s.value;
  return std::numeric_limits<double>::quiet_NaN();
}

// Coloured swatch, label and latest value of each line, wrapped to the panel's width.
void drawLegend(const PlotSpec& spec, const PlotHistory& history) {
  const float right = ImGui::GetCursorScreenPos().x + ImGui::GetContentRegionAvail().x;
  for (std::size_t i = 0; i < spec.series.size(); ++i) {
    const PlotSeries& s = spec.series[i];
    std::string text = s.label;
    if (!history.empty()) text += " " + valueWithUnits(spec, newestKnown(history, s) * spec.scale);
    const float swatch = ImGui::GetTextLineHeight() * 0.7f;
    const float width = swatch + 4 + ImGui::CalcTextSize(text.c_str()).x;
    if (i > 0) {
      ImGui::SameLine(0, 12);
      if (ImGui::GetCursorScreenPos().x + width > right) ImGui::NewLine();
    }
    const ImVec2 p = ImGui::GetCursorScreenPos();
    const float top = p.y + (ImGui::GetTextLineHeight() - swatch) / 2;
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(p.x, top), ImVec2(p.x + swatch, top + swatch), s.colour);
    ImGui::Dummy(ImVec2(swatch, ImGui::GetTextLineHeight()));
    ImGui::SameLine(0, 4);
    ImGui::TextUnformatted(text.c_str());
  }
}

void drawAxes(ImDrawList* draw, const Frame& f) {
  const ImU32 grid = IM_COL32(225, 228, 235, 255), text = IM_COL32(70, 70, 80, 255);
  const float lineHeight = ImGui::GetTextLineHeight();
  const AxisTicks yt =
      niceTicks(f.range.lo, f.range.hi, std::max(2, int((f.y1 - f.y0) / (lineHeight * 1.6f))));
  for (int i = 0; i < yt.count; ++i) {
    const double v = yt.first + i * yt.step;
    const float y = std::round(f.y(v));
    draw->AddLine(ImVec2(f.x0, y), ImVec2(f.x1, y),
                  std::abs(v) < yt.step * 1e-6 ? IM_COL32(160, 160, 170, 255) : grid);
    const std::string label = tickLabel(v, yt.step);
    const ImVec2 size = ImGui::CalcTextSize(label.c_str());
    draw->AddText(ImVec2(f.x0 - 4 - size.x, y - size.y / 2), text, label.c_str());
  }
  const AxisTicks xt = niceTicks(f.t0, f.t1, std::max(2, int((f.x1 - f.x0) / 45)));
  for (int i = 0; i < xt.count; ++i) {
    const double t = xt.first + i * xt.step;
    const float x = std::round(f.x(t));
    draw->AddLine(ImVec2(x, f.y0), ImVec2(x, f.y1), grid);
    const std::string label = tickLabel(t, xt.step);
    const float w = ImGui::CalcTextSize(label.c_str()).x;
    draw->AddText(ImVec2(std::clamp(x - w / 2, f.x0, f.x1 - w), f.y1 + 2), text, label.c_str());
  }
  draw->AddText(ImVec2(f.x0 - ImGui::CalcTextSize("t (s)").x - 4, f.y1 + 2), text, "t (s)");
  draw->AddRect(ImVec2(f.x0, f.y0), ImVec2(f.x1 + 1, f.y1 + 1), IM_COL32(150, 150, 160, 255));
}

// One line, at most two points per pixel column (the column's lowest and highest value in the
// order they came), so thousands of steps cost a few hundred points and no spike is lost.
void drawSeries(ImDrawList* draw, const Frame& f, const PlotHistory& history, std::size_t from,
                const PlotSeries& s, double scale) {
  std::vector<ImVec2> points;
  int column = std::numeric_limits<int>::min();
  std::size_t lowAt = 0, highAt = 0;
  double low = 0, high = 0;
  auto stroke = [&] {
    if (points.size() >= 2) draw->AddPolyline(points.data(), int(points.size()), s.colour, 0, 1.5f);
    points.clear();
  };
  auto flush = [&] {
    if (column == std::numeric_limits<int>::min()) return;
    const float x = float(column);
    if (lowAt <= highAt) {
      points.emplace_back(x, f.y(low));
      if (highAt != lowAt) points.emplace_back(x, f.y(high));
    } else {
      points.emplace_back(x, f.y(high));
      points.emplace_back(x, f.y(low));
    }
  };
  for (std::size_t i = from; i < history.size(); ++i) {
    const double v = history[i].*s.value * scale;
    if (!std::isfinite(v)) {  // not known: a gap in the line
      flush();
      column = std::numeric_limits<int>::min();
      stroke();
      continue;
    }
    const int c = int(std::floor(f.x(history[i].time)));
    if (c != column) {
      flush();
      column = c, low = high = v, lowAt = highAt = i;
    } else if (v < low) {
      low = v, lowAt = i;
    } else if (v > high) {
      high = v, highAt = i;
    }
  }
  flush();
  stroke();
}

// The run before the restart: its last beat, in grey, under each of this run's beats.
void drawBefore(ImDrawList* draw, const Frame& f, const PlotSpec& spec, const PlotHistory& history,
                std::span<const PumpSample> before) {
  if (before.size() < 2 || history.empty()) return;
  const std::vector<double> onsets = beatOnsets(history);
  // Up to now: the two runs are compared at the same point of their beats, not ahead of it.
  const double now = history.newest().time;
  for (OverlaySpan span : overlaySpans(onsets, before.back().time, f.t0, now)) {
    span.end = std::min(span.end, now);
    for (const PlotSeries& s : spec.series) {
      std::vector<ImVec2> points;
      for (const PumpSample& sample : before) {
        const double t = span.start + sample.time, v = sample.*s.value * spec.scale;
        if (t > span.end) break;
        if (!std::isfinite(v)) continue;
        const ImVec2 p(f.x(t), f.y(v));
        if (!points.empty() && std::abs(p.x - points.back().x) < 0.5f && std::abs(p.y - points.back().y) < 1)
          continue;
        points.push_back(p);
      }
      if (points.size() >= 2) draw->AddPolyline(points.data(), int(points.size()), kBeforeColour, 0, 1.2f);
    }
  }
}

void hoverTooltip(ImDrawList* draw, const Frame& f, const PlotSpec& spec, const PlotHistory& history) {
  const float mx = ImGui::GetIO().MousePos.x;
  if (mx < f.x0 || mx > f.x1 || history.empty()) return;
  const double t = f.t0 + double(mx - f.x0) / double(f.x1 - f.x0) * (f.t1 - f.t0);
  const std::size_t i = std::min(history.lowerBound(t), history.size() - 1);
  const PumpSample& sample = history[i];
  draw->AddLine(ImVec2(f.x(sample.time), f.y0), ImVec2(f.x(sample.time), f.y1), IM_COL32(90, 90, 100, 160));
  ImGui::BeginTooltip();
  ImGui::Text("t = %.3f s", sample.time);
  for (const PlotSeries& s : spec.series)
    ImGui::Text("%s: %s", s.label, valueWithUnits(spec, sample.*s.value * spec.scale).c_str());
  ImGui::EndTooltip();
}

}  // namespace

std::string formatValue(double value) {
  char text[32];
  if (!std::isfinite(value)) return "-";
  if (std::abs(value) >= 1000)
    std::snprintf(text, sizeof text, "%.0f", value);
  else
    std::snprintf(text, sizeof text, "%.4g", std::abs(value) < 1e-12 ? 0.0 : value);
  return text;
}

void drawPlot(const char* id, const PlotSpec& spec, const PlotHistory& history, float height,
              std::span<const PumpSample> before) {
  ImGui::PushID(id);
  ImGui::Text("%s (%s)", spec.title, spec.unit.c_str());
  if (!spec.note.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("%s", spec.note.c_str());
  }
  tooltip(spec.tooltip);
  drawLegend(spec, history);

  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x;
  ImGui::InvisibleButton("chart", ImVec2(width, height));
  const bool hovered = ImGui::IsItemHovered();
  const float lineHeight = ImGui::GetTextLineHeight();

  Frame f{};
  f.x0 = origin.x + ImGui::CalcTextSize("-0000.0").x + 6;
  f.x1 = origin.x + width - 6;
  f.y0 = origin.y + lineHeight / 2;
  f.y1 = origin.y + height - lineHeight - 3;
  // The window's right edge is now; until a window's worth has run, time starts at the left.
  const double window = std::max(history.window(), 1e-3);
  f.t1 = history.empty() ? window : std::max(history.newest().time, window);
  f.t0 = f.t1 - window;
  const std::size_t from = history.empty() ? 0 : std::min(history.lowerBound(f.t0), history.size() - 1);
  f.range = spec.range.hi > spec.range.lo ? spec.range : AxisRange{0, 1};

  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(ImVec2(f.x0, f.y0), ImVec2(f.x1, f.y1), IM_COL32(255, 255, 255, 255));
  drawAxes(draw, f);
  draw->PushClipRect(ImVec2(f.x0, f.y0), ImVec2(f.x1 + 1, f.y1 + 1), true);
  drawBefore(draw, f, spec, history, before);
  for (const PlotSeries& s : spec.series)
    drawSeries(draw, f, history, from > 0 ? from - 1 : 0, s, spec.scale);
  if (history.empty()) draw->AddText(ImVec2(f.x0 + 8, f.y0 + 4), IM_COL32(120, 120, 130, 255), "no data yet");
  draw->PopClipRect();
  if (hovered) hoverTooltip(draw, f, spec, history);
  ImGui::PopID();
}

}  // namespace hs::viewer
