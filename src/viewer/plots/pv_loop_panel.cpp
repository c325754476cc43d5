#include "viewer/plots/pv_loop_panel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include "cardiac/circulation/clinical_units.h"
#include "viewer/plots/chart_drawing.h"

namespace hs::viewer {
namespace {

using cardiac::CirculationSample;
using cardiac::kCubicMetresPerMl;
using cardiac::kPascalPerMmHg;

constexpr ImU32 kEndSystolicColour = IM_COL32(45, 70, 150, 255);
constexpr ImU32 kEndDiastolicColour = IM_COL32(20, 125, 105, 255);
constexpr ImU32 kEventColour = IM_COL32(50, 50, 60, 255);
// The loops drawn, newest first: how strong each is.
constexpr std::array<float, 3> kLoopAlpha = {1.0f, 0.42f, 0.2f};
constexpr std::array<float, 3> kLoopThickness = {2.6f, 1.7f, 1.3f};

constexpr const char* kLoopHelp =
    "The left ventricle's pressure against its volume through each beat: the loop runs "
    "anticlockwise.\n"
    "  bottom (MO to MC): filling, along the end-diastolic line (EDPVR);\n"
    "  right side (MC to AO): isovolumic contraction, both valves shut;\n"
    "  top (AO to AC): ejection into the aorta;\n"
    "  left side (AC to MO): isovolumic relaxation.\n"
    "Width = stroke volume; area = the work of one beat. The top-left corner (end-systole) sits on "
    "the end-systolic line (ESPVR), whose slope Ees is the contractility.\n"
    "The newest beat is drawn strongest, two before it fainter; the dot is now. Grey: the last "
    "loop of the run before the last restart.";

ImVec2 point(const ChartFrame& f, const CirculationSample& s) {
  return f.at(s.lvVolume / kCubicMetresPerMl, s.lvPressure / kPascalPerMmHg);
}



// ESPVR: the straight line from (V0, 0); EDPVR: the exponential, both across the frame (clipped
// by the caller), each named where it leaves the frame's upper or right side.
void drawRelations(ImDrawList* draw, const ChartFrame& f, const cardiac::PressureVolumeRelations& r) {
  const double v0 = r.unstressedVolume / kCubicMetresPerMl;
  const double slope = r.endSystolicElastance * kCubicMetresPerMl / kPascalPerMmHg;  // mmHg/mL
  if (slope > 0) {
    const double vTop = std::min(f.x.hi, v0 + f.y.hi / slope);
    draw->AddLine(f.at(v0, 0), f.at(vTop, slope * (vTop - v0)), kEndSystolicColour, 1.6f);
    // Left of the line near the top: the loop lies to its right.
    const double pLabel = slope * (vTop - v0) * 0.93;
    const ImVec2 at = f.at(v0 + pLabel / slope, pLabel);
    const float width = ImGui::CalcTextSize("ESPVR").x;
    draw->AddText(ImVec2(std::max(f.x0 + 2, at.x - width - 6), at.y), kEndSystolicColour, "ESPVR");
  }
  constexpr int kPoints = 64;
  std::vector<ImVec2> curve;
  for (int i = 0; i <= kPoints; ++i) {
    const double v = v0 + (f.x.hi - v0) * double(i) / kPoints;
    curve.push_back(f.at(v, endDiastolicPressure(r, v * kCubicMetresPerMl) / kPascalPerMmHg));
  }
  draw->AddPolyline(curve.data(), int(curve.size()), kEndDiastolicColour, 0, 1.6f);
  // Above the curve's right end (the loop's filling limb ends left of it).
  const float width = ImGui::CalcTextSize("EDPVR").x, line = ImGui::GetTextLineHeight();
  const ImVec2 end = curve.back();
  draw->AddText(ImVec2(f.x1 - width - 3, std::clamp(end.y - line - 3, f.y0 + 2, f.y1 - line - 2)),
                kEndDiastolicColour, "EDPVR");
}

// MC, AO, AC, MO on the last complete beat: the loop's four corners, as in a textbook.
void drawValveEvents(ImDrawList* draw, const ChartFrame& f, std::span<const CirculationSample> samples,
                     const BeatSpan& beat) {
  const std::span<const CirculationSample> s = samples.subspan(beat.begin, beat.size());
  const ValveEvents e = valveEvents(s, beat.start);
  const float line = ImGui::GetTextLineHeight();
  // Labels outside the anticlockwise loop's corners: right-below, right-above, left-above, left-below.
  const struct {
    std::optional<double> time;
    const char* name;
    bool left, above;
  } marks[] = {{e.mitralClose, "MC", false, false},
               {e.aorticOpen, "AO", false, true},
               {e.aorticClose, "AC", true, true},
               {e.mitralOpen, "MO", true, false}};
  for (const auto& m : marks) {
    if (!m.time) continue;
    // The sample at the event's time (events fall on sample times, or the beat's start).
    const auto it = std::lower_bound(s.begin(), s.end(), *m.time - 1e-9,
                                     [](const CirculationSample& a, double t) { return a.time < t; });
    const ImVec2 p = point(f, it == s.end() ? s.front() : *it);
    draw->AddCircleFilled(p, 3.5f, kEventColour);
    const float w = ImGui::CalcTextSize(m.name).x;
    draw->AddText(ImVec2(m.left ? p.x - w - 4 : p.x + 4, m.above ? p.y - line - 1 : p.y + 1), kEventColour,
                  m.name);
  }
}

void hoverReadout(const ChartFrame& f, const CirculationHistory& history) {
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  ImGui::BeginTooltip();
  if (f.contains(mouse)) ImGui::Text("V = %.0f mL, P = %.0f mmHg (cursor)", f.xAt(mouse.x), f.yAt(mouse.y));
  if (!history.samples().empty()) {
    const CirculationSample& now = history.samples().back();
    ImGui::Text("now: V = %.1f mL, P = %.1f mmHg", now.lvVolume / kCubicMetresPerMl,
                now.lvPressure / kPascalPerMmHg);
  }
  ImGui::Separator();
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 32);
  ImGui::TextUnformatted(kLoopHelp);
  ImGui::PopTextWrapPos();
  ImGui::EndTooltip();
}

}  // namespace

void drawPressureVolumeBeat(ImDrawList* draw, const ChartFrame& f, std::span<const CirculationSample> beat,
                            ImU32 colour, float thickness, bool closed) {
  std::vector<ImVec2> points;
  points.reserve(beat.size());
  for (const CirculationSample& s : beat) {
    const ImVec2 p = point(f, s);
    if (!points.empty() && std::abs(p.x - points.back().x) + std::abs(p.y - points.back().y) < 1) continue;
    points.push_back(p);
  }
  if (points.size() >= 2)
    draw->AddPolyline(points.data(), int(points.size()), colour, closed ? ImDrawFlags_Closed : 0, thickness);
}

void drawPressureVolumeLoop(const CirculationHistory& history,
                            const cardiac::PressureVolumeRelations& relations, ImVec2 size,
                            std::span<const CirculationSample> before) {
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("pv loop", size);
  const bool hovered = ImGui::IsItemHovered();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float line = ImGui::GetTextLineHeight();

  ChartFrame f;
  f.x0 = origin.x + ImGui::CalcTextSize("000").x + 8;
  f.x1 = origin.x + size.x - 4;
  f.y0 = origin.y + 2 * line + 4;
  f.y1 = origin.y + size.y - 2 * line - 4;
  const std::span<const CirculationSample> samples = history.samples();
  const std::vector<BeatSpan> beats = beatSpans(samples, history.beatStarts());
  // The axes fit the beats drawn, not older ones.
  const std::size_t shown = std::min(beats.size(), kLoopAlpha.size());
  const std::size_t from = shown > 0 ? beats[beats.size() - shown].begin : samples.size();
  // ... and the grey loop of the run before, so it is not cut off.
  std::vector<CirculationSample> withBefore;
  if (!before.empty()) {
    withBefore.assign(samples.begin() + std::ptrdiff_t(from), samples.end());
    withBefore.insert(withBefore.end(), before.begin(), before.end());
  }
  const LoopAxes axes = loopAxes(before.empty() ? samples.subspan(from) : std::span(withBefore), relations,
                                 ticksFitting(f.x1 - f.x0, 42), ticksFitting(f.y1 - f.y0, line * 1.8f));
  f.x = axes.volume, f.y = axes.pressure;

  draw->AddText(origin, kChartText, "Pressure-volume loop");
  // The contractility the ESPVR's slope shows, where the figure's title ends.
  char slope[48];
  std::snprintf(slope, sizeof slope, "Ees %.2f mmHg/mL",
                relations.endSystolicElastance * kCubicMetresPerMl / kPascalPerMmHg);
  draw->AddText(ImVec2(f.x1 - ImGui::CalcTextSize(slope).x, origin.y + line + 2), kEndSystolicColour, slope);
  draw->AddText(ImVec2(origin.x, origin.y + line + 2), kChartText, "LV pressure (mmHg)");
  drawChartGrid(draw, f, ticksFitting(f.x1 - f.x0, 42), ticksFitting(f.y1 - f.y0, line * 1.8f), true);
  drawCentredText(draw, (f.x0 + f.x1) / 2, f.y1 + line + 4, kChartText, "LV volume (mL)");

  draw->PushClipRect(ImVec2(f.x0, f.y0), ImVec2(f.x1 + 1, f.y1 + 1), true);
  drawRelations(draw, f, relations);
  if (before.size() >= 2) drawPressureVolumeBeat(draw, f, before, kBeforeLoopColour, 1.8f);
  for (std::size_t k = shown; k-- > 0;) {  // oldest first, so the newest lies on top
    const BeatSpan& b = beats[beats.size() - 1 - k];
    drawPressureVolumeBeat(draw, f, samples.subspan(b.begin, b.size()), fade(kLoopColour, kLoopAlpha[k]),
             kLoopThickness[k]);
  }
  if (const std::optional<BeatSpan> last = lastCompleteBeat(samples, history.beatStarts()))
    drawValveEvents(draw, f, samples, *last);
  if (!samples.empty()) {
    const ImVec2 now = point(f, samples.back());
    draw->AddCircleFilled(now, 5.5f, kLoopColour);
    draw->AddCircle(now, 5.5f, IM_COL32(255, 255, 255, 255), 0, 1.5f);
  } else {
    draw->AddText(ImVec2(f.x0 + 8, f.y0 + 4), IM_COL32(120, 120, 130, 255), "no beat yet");
  }
  draw->PopClipRect();
  drawChartBorder(draw, f);
  if (hovered) hoverReadout(f, history);
}

}  // namespace hs::viewer
