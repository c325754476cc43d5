#include "viewer/panels/compare_window.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cardiac/circulation/clinical_units.h"
#include "viewer/plots/chart_drawing.h"
#include "viewer/plots/plot_widget.h"
#include "viewer/plots/pv_loop_panel.h"

namespace hs::viewer {
namespace {

using cardiac::CirculationSample;
using cardiac::kCubicMetresPerMl;
using cardiac::kPascalPerMmHg;


struct CompareRow {
  const char* name;
  double ClinicalFigures::*value;
  bool volume;  // in the volume unit (else the unit is in the name)
};

std::string beatsText(const std::optional<BeatMean>& m) {
  if (!m) return "no complete beat";
  return "mean of " + std::to_string(m->count) + (m->count == 1 ? " beat" : " beats");
}

void numbers(const RunComparison& runs) {
  const RunRecord& now = runs.current();
  const std::optional<RunRecord>& before = runs.previous();
  const std::optional<BeatMean> a = before ? before->mean() : std::nullopt;
  const std::optional<BeatMean> b = now.mean();
  const std::string v = now.scale.volumeUnit;
  const CompareRow rows[] = {{"EDV", &ClinicalFigures::edv, true},
                             {"ESV", &ClinicalFigures::esv, true},
                             {"stroke volume", &ClinicalFigures::strokeVolume, true},
                             {"forward SV", &ClinicalFigures::forwardStrokeVolume, true},
                             {"ejection fraction (%)", &ClinicalFigures::ejectionFraction, false},
                             {"cardiac output", &ClinicalFigures::cardiacOutput, false},
                             {"heart rate (bpm)", &ClinicalFigures::heartRate, false},
                             {"regurgitation", &ClinicalFigures::regurgitantVolume, true}};
  if (!ImGui::BeginTable("compare numbers", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) return;
  ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, 170);
  ImGui::TableSetupColumn("before", ImGuiTableColumnFlags_WidthStretch);
  ImGui::TableSetupColumn("now", ImGuiTableColumnFlags_WidthStretch);
  ImGui::TableSetupColumn("change", ImGuiTableColumnFlags_WidthFixed, 70);
  ImGui::TableHeadersRow();
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(1);
  ImGui::TextWrapped("%s", before ? before->label.c_str() : "(no earlier run yet)");
  ImGui::TextDisabled("%s", beatsText(a).c_str());
  ImGui::TableSetColumnIndex(2);
  ImGui::TextWrapped("%s", now.label.c_str());
  ImGui::TextDisabled("%s", beatsText(b).c_str());
  const bool sameUnits = runs.comparable();
  for (const CompareRow& row : rows) {
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    if (row.volume)
      ImGui::Text("%s (%s)", row.name, v.c_str());
    else if (row.value == &ClinicalFigures::cardiacOutput)
      ImGui::Text("%s (%s)", row.name, now.scale.outputUnit);
    else
      ImGui::TextUnformatted(row.name);
    ImGui::TableSetColumnIndex(1);
    ImGui::TextUnformatted(a ? formatValue(a->figures.*row.value).c_str() : "-");
    if (a && !sameUnits) ImGui::SameLine(), ImGui::TextDisabled("(%s)", before->scale.volumeUnit);
    ImGui::TableSetColumnIndex(2);
    ImGui::TextUnformatted(b ? formatValue(b->figures.*row.value).c_str() : "-");
    ImGui::TableSetColumnIndex(3);
    if (a && b && sameUnits) {
      const double d = b->figures.*row.value - a->figures.*row.value;
      ImGui::Text("%s%s", d > 0 ? "+" : "", formatValue(d).c_str());
    } else {
      ImGui::TextDisabled("-");
    }
  }
  ImGui::EndTable();
}

// The runs' names are in the table's heads above: the legend names the columns.
void legend(ImDrawList* draw, ImVec2 at, const RunComparison& runs) {
  const float x = drawLegendEntry(draw, at, kLoopColour, "now");
  if (runs.previous()) drawLegendEntry(draw, ImVec2(x, at.y), kBeforeLoopColour, "before");
}

// Both runs' cavity volume over their last complete beat, from the start of systole.
void volumeCurves(const RunComparison& runs, const PlotHistory& history, const PlotAxes& axes, ImVec2 size) {
  const std::vector<PumpSample> now = lastBeatCurve(history);
  const std::vector<PumpSample> empty;
  const bool showBefore = runs.previous() && runs.comparable();
  const std::vector<PumpSample>& before = showBefore ? runs.previous()->beatCurve : empty;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::Dummy(size);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float line = ImGui::GetTextLineHeight();
  ChartFrame f;
  f.x0 = origin.x + ImGui::CalcTextSize("0000").x + 8, f.x1 = origin.x + size.x - 8;
  f.y0 = origin.y + 2 * line + 6, f.y1 = origin.y + size.y - 2 * line - 4;
  const double length = std::max(now.empty() ? 0.0 : now.back().time, before.empty() ? 0.0 : before.back().time);
  f.x = {0, length > 0 ? length : 1};
  f.y = axes.volume();
  const double scale = axes.scale().volume;
  draw->AddText(origin, kChartText,
                ("Cavity volume over one beat (" + std::string(axes.scale().volumeUnit) + ")").c_str());
  legend(draw, ImVec2(origin.x, origin.y + line + 2), runs);
  drawChartGrid(draw, f, ticksFitting(f.x1 - f.x0, 50), ticksFitting(f.y1 - f.y0, line * 1.8f), true);
  drawCentredText(draw, (f.x0 + f.x1) / 2, f.y1 + line + 4, kChartText, "time from the start of systole (s)");
  draw->PushClipRect(ImVec2(f.x0, f.y0), ImVec2(f.x1 + 1, f.y1 + 1), true);
  for (const auto* curve : {&before, &now}) {
    std::vector<ImVec2> points;
    for (const PumpSample& s : *curve) points.push_back(f.at(s.time, s.cavity * scale));
    if (points.size() >= 2)
      draw->AddPolyline(points.data(), int(points.size()), curve == &now ? kLoopColour : kBeforeLoopColour, 0,
                        curve == &now ? 2.2f : 2.0f);
  }
  if (now.empty() && before.empty())
    draw->AddText(ImVec2(f.x0 + 8, f.y0 + 4), kChartText, "no complete beat yet");
  draw->PopClipRect();
  drawChartBorder(draw, f);
}

// Both runs' last complete pressure-volume loops (mL, mmHg) on shared axes.
void loops(const RunComparison& runs, const CirculationHistory& circulation, ImVec2 size) {
  const std::vector<CirculationSample> now = lastLoop(circulation);
  const std::vector<CirculationSample> before =
      runs.previous() ? runs.previous()->loop : std::vector<CirculationSample>{};
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::Dummy(size);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float line = ImGui::GetTextLineHeight();
  draw->AddText(origin, kChartText, "Pressure-volume loop (last complete beat)");
  if (now.empty() && before.empty()) {
    draw->AddText(ImVec2(origin.x, origin.y + line + 4), kChartText,
                  "No loop: neither run has the lumped circulation's complete beat.");
    return;
  }
  legend(draw, ImVec2(origin.x, origin.y + line + 2), runs);
  ChartFrame f;
  f.x0 = origin.x + ImGui::CalcTextSize("0000").x + 8, f.x1 = origin.x + size.x - 8;
  f.y0 = origin.y + 2 * line + 6, f.y1 = origin.y + size.y - 2 * line - 4;
  double vMin = 1e300, vMax = -1e300, pMax = 0;
  for (const auto* loop : {&before, &now})
    for (const CirculationSample& s : *loop) {
      vMin = std::min(vMin, s.lvVolume / kCubicMetresPerMl), vMax = std::max(vMax, s.lvVolume / kCubicMetresPerMl);
      pMax = std::max(pMax, s.lvPressure / kPascalPerMmHg);
    }
  f.x = niceRange(std::min(vMin, 0.0), vMax, true, ticksFitting(f.x1 - f.x0, 42));
  f.y = niceRange(0, pMax, true, ticksFitting(f.y1 - f.y0, line * 1.8f));
  drawChartGrid(draw, f, ticksFitting(f.x1 - f.x0, 42), ticksFitting(f.y1 - f.y0, line * 1.8f), true);
  drawCentredText(draw, (f.x0 + f.x1) / 2, f.y1 + line + 4, kChartText, "LV volume (mL); LV pressure (mmHg) up");
  draw->PushClipRect(ImVec2(f.x0, f.y0), ImVec2(f.x1 + 1, f.y1 + 1), true);
  drawPressureVolumeBeat(draw, f, before, kBeforeLoopColour, 2.0f, true);
  drawPressureVolumeBeat(draw, f, now, kLoopColour, 2.0f, true);
  draw->PopClipRect();
  drawChartBorder(draw, f);
}

}  // namespace

void drawCompareWindow(bool& open, const RunComparison& runs, const PlotHistory& history,
                       const CirculationHistory& circulation, const PlotAxes& axes) {
  if (!open) return;
  ImGui::SetNextWindowSize(ImVec2(760, 560), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_FirstUseEver, ImVec2(0.5f, 0.5f));
  if (!ImGui::Begin("Compare: before and now", &open, ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::End();
    return;
  }
  if (!runs.previous())
    ImGui::TextWrapped(
        "No earlier run yet: apply a beating region, move a slider, press Reset or pick a scenario, "
        "and the run going on now becomes 'before'.");
  numbers(runs);
  ImGui::Spacing();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float gap = 16, width = (avail.x - gap) / 2, height = std::max(avail.y, 200.0f);
  volumeCurves(runs, history, axes, ImVec2(width, height));
  ImGui::SameLine(0, gap);
  loops(runs, circulation, ImVec2(width, height));
  ImGui::End();
}

}  // namespace hs::viewer
