#include "viewer/plots/wiggers_panel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "cardiac/circulation/clinical_units.h"
#include "viewer/plots/chart_drawing.h"
#include "viewer/plots/label_row.h"

namespace hs::viewer {
namespace {

using cardiac::CirculationSample;
using cardiac::kCubicMetresPerMl;
using cardiac::kPascalPerMmHg;
using Beat = std::span<const CirculationSample>;

// One curve: its name at its right end, its value in display units, its colour.
struct Trace {
  const char* label;
  double (*value)(const CirculationSample&);
  ImU32 colour;
  float thickness;
};
struct Panel {
  const char* unit;
  std::array<Trace, 3> traces;
  int count;
  float share;  // of the panels' height
  bool includeZero;
};

// The curves in display units.
double aorticMmHg(const CirculationSample& s) { return s.aorticPressure / kPascalPerMmHg; }
double lvMmHg(const CirculationSample& s) { return s.lvPressure / kPascalPerMmHg; }
double laMmHg(const CirculationSample& s) { return s.laPressure / kPascalPerMmHg; }
double lvMl(const CirculationSample& s) { return s.lvVolume / kCubicMetresPerMl; }
double mitralMlPerS(const CirculationSample& s) { return s.mitralFlow / kCubicMetresPerMl; }
double aorticMlPerS(const CirculationSample& s) { return s.aorticFlow / kCubicMetresPerMl; }
double ecgMv(const CirculationSample& s) { return s.ecg; }

// The colours of the pump panel's plots (pump_panel.cpp) for the same quantities.
constexpr ImU32 kRed = IM_COL32(215, 60, 40, 255), kBlue = IM_COL32(40, 110, 220, 255);
constexpr ImU32 kBlack = IM_COL32(25, 25, 30, 255), kVolume = IM_COL32(170, 30, 45, 255);
const std::array<Panel, 4> kPanels = {{
    {"mmHg",
     {{{"Ao", aorticMmHg, kRed, 1.8f}, {"LV", lvMmHg, kBlack, 2.0f}, {"LA", laMmHg, kBlue, 1.8f}}},
     3,
     0.39f,
     true},
    {"mL", {{{"LV", lvMl, kVolume, 2.0f}}}, 1, 0.20f, false},
    {"mL/s", {{{"mitral", mitralMlPerS, kBlue, 1.8f}, {"aortic", aorticMlPerS, kRed, 1.8f}}}, 2, 0.26f, true},
    {"mV", {{{"ECG", ecgMv, kBlack, 1.4f}}}, 1, 0.15f, true},
}};

constexpr std::size_t kFlowPanel = 2;  // its first trace is the mitral flow
constexpr std::size_t kEcgPanel = 3;

// The heart sounds on the ECG strip: S1 as the mitral valve closes, S2 as the aortic valve
// closes (cardiac::heartSoundAt), right of their lines (S1 stands at the beat's start).
void drawHeartSounds(ImDrawList* draw, const ChartFrame& f, const ValveEvents& e, double start) {
  for (const auto& [time, name] : {std::pair{e.mitralClose, "S1"}, std::pair{e.aorticClose, "S2"}}) {
    if (!time) continue;
    const float x = std::round(f.px((*time - start) * 1000));
    draw->AddText(ImVec2(x + 3, f.y0 + 1), IM_COL32(120, 60, 20, 255), name);
  }
}

// The phases' tints, by CyclePhaseKind.
constexpr std::array<ImU32, 4> kPhaseColours = {IM_COL32(255, 222, 170, 255), IM_COL32(255, 200, 205, 255),
                                                IM_COL32(222, 208, 245, 255), IM_COL32(198, 224, 250, 255)};
ImU32 phaseColour(const CyclePhase& p) { return kPhaseColours[std::size_t(p.kind)]; }

constexpr const char* kWiggersHelp =
    "One heartbeat, from the start of the ventricle's contraction to the next, on one time axis:\n"

    "  top: pressures in the aorta (Ao), the left ventricle (LV) and the left atrium (LA);\n"
    "  middle: the ventricle's volume;\n"
    "  below: flow through the mitral valve (into the ventricle) and the aortic valve (out);\n"
    "  bottom: the ECG, P (the atrium's excitation), QRS (the ventricle's) just before it contracts,\n"
    "  T as it relaxes, with the heart sounds S1 and S2 as the mitral and the aortic valve close.\n"
    "A valve opens when the pressure behind it exceeds the pressure ahead of it:\n"
    "  MC mitral closes (LV rises above LA), AO aortic opens (LV above Ao),\n"
    "  AC aortic closes (LV falls below Ao), MO mitral opens (LV below LA).\n"
    "Phases: IVC isovolumic contraction (both valves shut, the volume stays), ejection, IVR "
    "isovolumic relaxation, filling (early E wave, then the atrium's A wave).";

// Each label at its curve's last value, pushed apart so none overlaps; the unit on top.
void drawEndLabels(ImDrawList* draw, const ChartFrame& f, const Panel& panel, Beat beat) {
  struct Label {
    float y;
    const char* text;
    ImU32 colour;
  };
  const float line = ImGui::GetTextLineHeight();
  std::vector<Label> labels;
  for (int i = 0; i < panel.count; ++i) {
    const Trace& t = panel.traces[std::size_t(i)];
    labels.push_back({f.py(t.value(beat.back())) - line / 2, t.label, t.colour});
  }
  std::sort(labels.begin(), labels.end(), [](const Label& a, const Label& b) { return a.y < b.y; });
  float next = f.y0 + line;  // below the unit
  for (Label& l : labels) {
    l.y = std::max(l.y, next);
    next = l.y + line;
  }
  // Back up from the bottom when they ran past it.
  float limit = f.y1 - line;
  for (auto it = labels.rbegin(); it != labels.rend(); ++it) {
    it->y = std::min(it->y, limit);
    limit = it->y - line;
  }
  draw->AddText(ImVec2(f.x1 + 5, f.y0 - 2), kChartText, panel.unit);
  for (const Label& l : labels) draw->AddText(ImVec2(f.x1 + 5, l.y), l.colour, l.text);
}

void drawTrace(ImDrawList* draw, const ChartFrame& f, Beat beat, double start, const Trace& t) {
  std::vector<ImVec2> points;
  points.reserve(beat.size());
  for (const CirculationSample& s : beat) {
    const ImVec2 p = f.at((s.time - start) * 1000, t.value(s));
    if (!points.empty() && std::abs(p.x - points.back().x) < 0.5f && std::abs(p.y - points.back().y) < 0.5f)
      continue;
    points.push_back(p);
  }
  if (points.size() >= 2) draw->AddPolyline(points.data(), int(points.size()), t.colour, 0, t.thickness);
}

// Returns the panel's frame with its value range.
ChartFrame drawPanel(ImDrawList* draw, ChartFrame f, const Panel& panel, Beat beat, double start,
                     const std::vector<CyclePhase>& phases, bool timeLabels) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const CirculationSample& s : beat)
    for (int i = 0; i < panel.count; ++i) {
      const double v = panel.traces[std::size_t(i)].value(s);
      lo = std::min(lo, v), hi = std::max(hi, v);
    }
  const float line = ImGui::GetTextLineHeight();
  const int yTicks = ticksFitting(f.y1 - f.y0, line * 1.5f);
  f.y = paddedRange(lo, hi, panel.includeZero);
  drawChartGrid(draw, f, ticksFitting(f.x1 - f.x0, 38), yTicks, timeLabels, true);
  for (const CyclePhase& p : phases)
    draw->AddRectFilled(ImVec2(f.px((p.from - start) * 1000), f.y0),
                        ImVec2(f.px((p.to - start) * 1000), f.y1), fade(phaseColour(p), 0.3f));
  draw->PushClipRect(ImVec2(f.x0, f.y0), ImVec2(f.x1 + 1, f.y1 + 1), true);
  for (int i = panel.count; i-- > 0;) drawTrace(draw, f, beat, start, panel.traces[std::size_t(i)]);
  draw->PopClipRect();
  drawChartBorder(draw, f);
  drawEndLabels(draw, f, panel, beat);
  return f;
}

// E and A over the mitral inflow's two peaks: the letters an echocardiogram's E/A ratio names.
void drawMitralWaves(ImDrawList* draw, const ChartFrame& f, Beat beat, double start, const Trace& mitral) {
  const MitralWaves waves = mitralWaves(beat);
  const float line = ImGui::GetTextLineHeight();
  for (const auto& [index, name] : {std::pair{waves.early, "E"}, std::pair{waves.atrial, "A"}}) {
    if (!index) continue;
    const CirculationSample& s = beat[*index];
    const ImVec2 p = f.at((s.time - start) * 1000, mitral.value(s));
    drawCentredText(draw, p.x, std::max(f.y0, p.y - line - 1), mitral.colour, name);
  }
}

// The phases' band: each tinted span named, or abbreviated when the name does not fit.
void drawPhaseBand(ImDrawList* draw, const ChartFrame& f, float top, float bottom,
                   const std::vector<CyclePhase>& phases, double start) {
  draw->AddRectFilled(ImVec2(f.x0, top), ImVec2(f.x1, bottom), IM_COL32(245, 245, 248, 255));
  for (const CyclePhase& p : phases)
    draw->AddRectFilled(ImVec2(f.px((p.from - start) * 1000), top),
                        ImVec2(f.px((p.to - start) * 1000), bottom), phaseColour(p));
  // The names after every tint, each centred on its phase, or abbreviated when the name does not
  // fit; an abbreviation wider than its phase (IVC lasts 30 to 60 ms) gets its tint behind it, so
  // it reads as that phase's, and the row is spread so that no name covers its neighbour's.
  std::vector<const char*> texts;
  std::vector<float> xs, widths, spans;
  for (const CyclePhase& p : phases) {
    const float x0 = f.px((p.from - start) * 1000), x1 = f.px((p.to - start) * 1000);
    const char* text = ImGui::CalcTextSize(p.name).x + 4 <= x1 - x0 ? p.name : p.shortName;
    const float w = ImGui::CalcTextSize(text).x;
    texts.push_back(text);
    xs.push_back((x0 + x1 - w) / 2);
    widths.push_back(w);
    spans.push_back(x1 - x0);
  }
  spreadLabelRow(xs, widths, f.x0 + 3, f.x1 - 3, 5);
  for (std::size_t i = 0; i < phases.size(); ++i) {
    if (widths[i] > spans[i])
      draw->AddRectFilled(ImVec2(xs[i] - 2, top + 1), ImVec2(xs[i] + widths[i] + 2, bottom - 1), phaseColour(phases[i]));
    draw->AddText(ImVec2(xs[i], top + 1), kChartText, texts[i]);
  }
  draw->AddRect(ImVec2(f.x0, top), ImVec2(f.x1 + 1, bottom + 1), kChartBorder);
}

// The valve events: a dashed line through the band and the panels, the name above; a closing
// valve's name left of its line, an opening one's right of it, so MC and AO (40 ms apart) do not
// collide.
void drawValveEvents(ImDrawList* draw, const ChartFrame& f, float labelY, float bottom, const ValveEvents& e,
                     double start) {
  const struct {
    std::optional<double> time;
    const char* name;
    bool closing;
  } marks[] = {{e.mitralClose, "MC", true},
               {e.aorticOpen, "AO", false},
               {e.aorticClose, "AC", true},
               {e.mitralOpen, "MO", false}};
  const float line = ImGui::GetTextLineHeight();
  for (const auto& m : marks) {
    if (!m.time) continue;
    const float x = std::round(f.px((*m.time - start) * 1000));
    drawDashedLine(draw, ImVec2(x, labelY + line), ImVec2(x, bottom), IM_COL32(70, 70, 80, 200), 3, 1);
    const float w = ImGui::CalcTextSize(m.name).x;
    draw->AddText(ImVec2(m.closing ? x - w - 2 : x + 3, labelY), kChartText, m.name);
  }
}

void hoverReadout(ImDrawList* draw, const ChartFrame& f, float top, float bottom, Beat beat, double start) {
  const float mx = ImGui::GetIO().MousePos.x;
  if (mx < f.x0 || mx > f.x1) return;
  const double t = start + f.xAt(mx) / 1000;
  const auto it = std::lower_bound(beat.begin(), beat.end(), t,
                                   [](const CirculationSample& s, double time) { return s.time < time; });
  const CirculationSample& s = it == beat.end() ? beat.back() : *it;
  const float x = f.px((s.time - start) * 1000);
  draw->AddLine(ImVec2(x, top), ImVec2(x, bottom), IM_COL32(90, 90, 100, 160));
  ImGui::BeginTooltip();
  ImGui::Text("t = %.0f ms", (s.time - start) * 1000);
  ImGui::Text("pressure: Ao %.0f, LV %.0f, LA %.1f mmHg", aorticMmHg(s), lvMmHg(s), laMmHg(s));
  ImGui::Text("LV volume: %.1f mL", lvMl(s));
  ImGui::Text("flow: mitral %.0f, aortic %.0f mL/s", mitralMlPerS(s), aorticMlPerS(s));
  ImGui::Text("valves: mitral %s, aortic %s", s.mitralOpen ? "open" : "shut", s.aorticOpen ? "open" : "shut");
  ImGui::EndTooltip();
}

}  // namespace

void drawWiggersDiagram(const CirculationHistory& history, ImVec2 size) {
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("wiggers", size);
  const bool hovered = ImGui::IsItemHovered();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float line = ImGui::GetTextLineHeight();
  const std::span<const CirculationSample> samples = history.samples();
  const std::optional<BeatSpan> last = lastCompleteBeat(samples, history.beatStarts());

  ChartFrame f;
  f.x0 = origin.x + ImGui::CalcTextSize("-000").x + 8;
  f.x1 = origin.x + size.x - ImGui::CalcTextSize("mitral").x - 10;
  const float eventsY = origin.y + line + 3, bandTop = eventsY + line + 1, bandBottom = bandTop + line + 2;
  const float panelsTop = bandBottom + 4, panelsBottom = origin.y + size.y - line - 4;
  if (!last) {
    draw->AddText(origin, kChartText, "Wiggers diagram");
    draw->AddText(ImVec2(f.x0, panelsTop), IM_COL32(120, 120, 130, 255),
                  "waiting for the first complete beat");
    return;
  }
  const Beat beat = samples.subspan(last->begin, last->size());
  const double start = last->start, end = beat.back().time;
  f.x = {0, (end - start) * 1000};
  char title[96];
  std::snprintf(title, sizeof title, "Wiggers diagram: the last complete beat (%.0f ms)",
                (end - start) * 1000);
  draw->AddText(origin, kChartText, title);

  const ValveEvents events = valveEvents(beat, start);
  const std::vector<CyclePhase> phases = cyclePhases(events, end);
  drawPhaseBand(draw, f, bandTop, bandBottom, phases, start);
  constexpr float kGap = 5;
  const float height = panelsBottom - panelsTop - kGap * float(kPanels.size() - 1);
  float y = panelsTop;
  for (std::size_t i = 0; i < kPanels.size(); ++i) {
    ChartFrame panel = f;
    panel.y0 = y;
    panel.y1 = y + height * kPanels[i].share;
    panel = drawPanel(draw, panel, kPanels[i], beat, start, phases, i + 1 == kPanels.size());
    if (i == kFlowPanel) drawMitralWaves(draw, panel, beat, start, kPanels[i].traces[0]);
    if (i == kEcgPanel) drawHeartSounds(draw, panel, events, start);
    y = panel.y1 + kGap;
  }
  draw->AddText(ImVec2(f.x1 + 5, panelsBottom + 2), kChartText, "ms");
  drawValveEvents(draw, f, eventsY, panelsBottom, events, start);
  if (!hovered) return;
  if (ImGui::GetIO().MousePos.y < bandTop) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 34);
    ImGui::TextUnformatted(kWiggersHelp);
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  } else {
    hoverReadout(draw, f, bandTop, panelsBottom, beat, start);
  }
}

}  // namespace hs::viewer
