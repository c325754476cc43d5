#include "viewer/panels/pump_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "render/scene.h"
#include "viewer/plots/panel_widgets.h"
#include "viewer/plots/plot_widget.h"

namespace hs::viewer {
namespace {

constexpr ImU32 kVolumeColour = IM_COL32(170, 30, 45, 255);
constexpr ImU32 kMitralColour = IM_COL32(40, 110, 220, 255);
constexpr ImU32 kAorticColour = IM_COL32(215, 60, 40, 255);
constexpr ImU32 kInflowColour = IM_COL32(40, 110, 220, 255);
constexpr ImU32 kOutflowColour = IM_COL32(235, 140, 20, 255);
const ImVec4 kOpen(0.1f, 0.6f, 0.2f, 1), kClosed(0.45f, 0.45f, 0.5f, 1), kMuted(0.45f, 0.45f, 0.5f, 1);

// Normal values mean nothing for a model metres across.
std::string normal(const PumpStatus& s, const char* adult) {
  return s.scale.thesis ? "\n(Thesis-scale model, metres across: not comparable with a real heart.)"
                        : std::string("\nNormal adult at rest: ") + adult + ".";
}

// The phase's colour: red while the ventricle ejects, blue while it fills, grey when shut.
ImVec4 phaseColour(cardiac::HeartPhase phase, cardiac::Phase wall) {
  using cardiac::HeartPhase;
  if (phase == HeartPhase::Ejection || (phase == HeartPhase::None && wall == cardiac::Phase::Systole))
    return ImVec4(0.75f, 0.15f, 0.15f, 1);
  if (phase == HeartPhase::Filling || phase == HeartPhase::None) return ImVec4(0.15f, 0.35f, 0.75f, 1);
  return ImVec4(0.4f, 0.3f, 0.45f, 1);
}

void phaseAndValves(const PumpStatus& s) {
  if (!s.cycleOn) {
    ImGui::TextColored(kMuted, "phase: rest (the cardiac cycle is off)");
  } else if (s.phase == cardiac::Phase::Rest) {
    ImGui::TextColored(kMuted, "phase: rest (the wall does not beat)");
  } else {
    ImGui::PushStyleColor(ImGuiCol_Text, phaseColour(s.heartPhase, s.phase));
    ImGui::TextWrapped("phase: %s", s.phaseLabel.c_str());
    ImGui::PopStyleColor();
  }
  tooltip(std::string(cardiac::heartPhaseExplanation(s.heartPhase)) +
          "\nThe phase is read from the valves, as the Wiggers diagram's bands are. The wall's own clock "
          "(systole: the muscle contracts, diastole: it relaxes) is metrics.csv's wall_phase column.");
  if (!s.hasBlood) return;
  const char* mode = s.valveMode == cardiac::ValveMode::Timing     ? "they follow the phase (timing)"
                     : s.valveMode == cardiac::ValveMode::Pressure ? "each opens when the pressure before it "
                                                                     "is higher than after it"
                                                                   : "both are always open";
  const std::string tip = std::string("Open: blood can pass. Mode: ") + mode +
                          ".\nThe mitral valve lets blood in from the atrium, the aortic valve lets it out "
                          "into the aorta.";
  ImGui::TextUnformatted("valves:");
  ImGui::SameLine();
  ImGui::TextUnformatted("mitral");
  ImGui::SameLine(0, 4);
  ImGui::TextColored(s.valves.mitralOpen ? kOpen : kClosed, s.valves.mitralOpen ? "open" : "closed");
  tooltip(tip);
  ImGui::SameLine(0, 14);
  ImGui::TextUnformatted("aortic");
  ImGui::SameLine(0, 4);
  ImGui::TextColored(s.valves.aorticOpen ? kOpen : kClosed, s.valves.aorticOpen ? "open" : "closed");
  tooltip(tip);
}

struct Row {
  std::string label, tip;
  double ClinicalFigures::*value;
  bool needsCompleteBeat;  // rate and output need the beat's length
};

std::vector<Row> beatRows(const PumpStatus& s) {
  const VolumeScale& u = s.scale;
  const std::string v = u.volumeUnit;
  const std::string timing = s.thesisTiming
                                 ? "\nThesis timing: a fixed number of steps per phase, so the beat is "
                                   "far shorter than a real one."
                                 : "";
  std::vector<Row> rows = {
      {"EDV (" + v + ")",
       "End-diastolic volume: the blood in the ventricle when it is fullest, just before it contracts "
       "(the start of systole)." +
           normal(s, "about 120 mL"),
       &ClinicalFigures::edv, false},
      {"ESV (" + v + ")",
       "End-systolic volume: the blood left in the ventricle when it is emptiest, at the end of its "
       "contraction." +
           normal(s, "about 50 mL"),
       &ClinicalFigures::esv, false},
      {"SV (" + v + ")", "Stroke volume, SV = EDV - ESV: the blood one beat ejects." + normal(s, "about 70 mL"),
       &ClinicalFigures::strokeVolume, false}};
  if (s.hasBlood)
    rows.push_back({"forward SV (" + v + ")",
                    "Forward stroke volume = SV - regurgitant volume: what one beat moves on into the "
                    "aorta and stays there. With a leaking valve part of SV goes back the wrong way." +
                        normal(s, "the same as SV, valves do not leak"),
                    &ClinicalFigures::forwardStrokeVolume, false});
  rows.push_back({"EF (%)",
                  "Ejection fraction, EF = SV / EDV: the share of the filled ventricle one beat ejects. "
                  "Normal: 55 to 70 %; below 40 % the heart pumps poorly (heart failure with reduced EF).",
                  &ClinicalFigures::ejectionFraction, false});
  rows.push_back({"CO (" + std::string(u.outputUnit) + ")",
                  "Cardiac output, CO = SV x heart rate: the blood pumped per minute." +
                      normal(s, "about 5 L/min"),
                  &ClinicalFigures::cardiacOutput, true});
  rows.push_back({"HR (bpm)",
                  "Heart rate, beats per minute, from the beat's length: 60 / length (s)." +
                      normal(s, "60 to 100 bpm") + timing,
                  &ClinicalFigures::heartRate, true});
  if (s.hasBlood)
    rows.push_back(
        {"regurgitation (" + v + ")",
         "Regurgitant volume: blood that went back the wrong way in a beat, back through the mitral "
         "valve in systole or back through the aortic valve in diastole (mitral or aortic "
         "regurgitation, a leaking valve). Healthy valves: close to 0.",
         &ClinicalFigures::regurgitantVolume, false});
  return rows;
}

void cell(const std::optional<ClinicalFigures>& f, const Row& row, const char* pendingTip) {
  if (!f) {
    ImGui::TextColored(kMuted, "-");
    tooltip(pendingTip);
  } else if (row.needsCompleteBeat && !f->complete) {
    ImGui::TextColored(kMuted, "...");
    tooltip("Known when the beat ends (the next systole starts)");
  } else {
    ImGui::TextUnformatted(formatValue((*f).*row.value).c_str());
  }
}

std::string beatsText(int count) { return std::to_string(count) + (count == 1 ? " beat" : " beats"); }

// Which run "before" and "now" are, and the button that opens them side by side.
void runLabels(PumpControls& c, const RunComparison& runs) {
  const std::optional<RunRecord>& before = runs.previous();
  // The button at the first line's right end; a long label wraps short of it.
  const float button = ImGui::CalcTextSize("Compare").x + 2 * ImGui::GetStyle().FramePadding.x;
  const float buttonX = ImGui::GetWindowContentRegionMax().x - button;
  const ImVec2 lineStart = ImGui::GetCursorPos();
  ImGui::TextColored(kMuted, "before:");
  ImGui::SameLine();
  ImGui::PushTextWrapPos(buttonX - ImGui::GetStyle().ItemSpacing.x);
  ImGui::TextUnformatted(before ? before->label.c_str() : "(no earlier run yet)");
  ImGui::PopTextWrapPos();
  tooltip(
      "The run before the last restart (a region applied, a slider moved, Reset, another "
      "scenario): its numbers stay in the 'before' column and its last beat is drawn in grey "
      "in the plots, so you can see what the change did.");
  const ImVec2 afterLabel = ImGui::GetCursorPos();
  ImGui::SetCursorPos(ImVec2(buttonX, lineStart.y));
  if (ImGui::SmallButton("Compare")) c.showCompare = !c.showCompare;
  tooltip("Open a window with the run before and this one side by side: their numbers, their "
          "volume curves over one beat and their pressure-volume loops.");
  ImGui::SetCursorPos(afterLabel);
  ImGui::TextColored(kMuted, "now:");
  ImGui::SameLine();
  ImGui::TextUnformatted(runs.current().label.c_str());
}

void beatTable(PumpControls& c, const PumpStatus& s, const RunComparison& runs) {
  runLabels(c, runs);
  const BeatReadings& b = s.beats;
  std::optional<ClinicalFigures> last;
  if (b.last) last = clinicalFigures(*b.last, s.scale);
  const std::optional<BeatMean> now = meanOfLastBeats(b.recent, RunRecord::kMeanBeats, s.scale);
  // The run before is shown beside this one only when its units are this run's.
  const std::optional<RunRecord>& previous = runs.previous();
  const std::optional<BeatMean> before = previous && runs.comparable() ? previous->mean() : std::nullopt;
  const int columns = previous ? 4 : 3;
  if (!ImGui::BeginTable("beats", columns, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) return;
  ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthStretch);
  for (int k = 1; k < columns; ++k) ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, 54);
  ImGui::TableNextRow(ImGuiTableRowFlags_Headers);
  ImGui::TableSetColumnIndex(0);
  ImGui::TextDisabled(b.beating ? "beat %d now" : "no beat yet", b.beatsCompleted + 1);
  tooltip("The beat in progress, counted from the start of its systole");
  ImGui::TableSetColumnIndex(1);
  ImGui::TextUnformatted(b.last ? ("#" + std::to_string(b.last->index)).c_str() : "last");
  tooltip("The last complete beat, from one systole's start to the next");
  ImGui::TableSetColumnIndex(2);
  ImGui::TextUnformatted("now");
  tooltip("This run: the mean of its last complete beats since the circulation settled (up to 5; the row "
          "below says how many)");
  if (previous) {
    ImGui::TableSetColumnIndex(3);
    ImGui::TextUnformatted("before");
    tooltip("The run before the last restart: the mean of its last complete beats (up to 5)");
  }
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  ImGui::TextDisabled("mean of");
  ImGui::TableSetColumnIndex(1);
  ImGui::TextDisabled(b.last ? "1 beat" : "-");
  ImGui::TableSetColumnIndex(2);
  const bool settling = b.last && !b.settled;
  ImGui::TextDisabled("%s", now ? beatsText(now->count).c_str() : settling ? "settling..." : "-");
  if (settling)
    tooltip("After a restart the circulation starts from rest and takes a few beats to find its balance. "
            "'now' averages only the beats after it has settled: a beat whose end-diastolic and end-systolic "
            "volumes are both within 1% of the beat before's (an irregular rhythm: after three time "
            "constants of the arteries, R x C).");
  if (previous) {
    ImGui::TableSetColumnIndex(3);
    ImGui::TextDisabled("%s", before ? beatsText(before->count).c_str() : "other units");
  }
  for (const Row& row : beatRows(s)) {
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextUnformatted(row.label.c_str());
    tooltip(row.tip);
    ImGui::TableSetColumnIndex(1);
    cell(last, row, "No complete beat yet");
    ImGui::TableSetColumnIndex(2);
    cell(now ? std::optional(now->figures) : std::nullopt, row,
         settling ? "The circulation is still settling after the restart" : "No complete beat yet");
    if (previous) {
      ImGui::TableSetColumnIndex(3);
      cell(before ? std::optional(before->figures) : std::nullopt, row,
           "The run before is at another scale (thesis-scale m^3 against a real heart's mL)");
    }
  }
  ImGui::EndTable();
}

// The four flow components in the papers' colours (render/scene.h), in the order a bar shows
// them: what leaves in the beat first, then what stays.
struct ComponentShare {
  cardiac::FlowComponent component;
  const char* word;
  double cardiac::FlowComponents::*share;
};
constexpr ComponentShare kShares[] = {
    {cardiac::FlowComponent::Direct, "direct", &cardiac::FlowComponents::direct},
    {cardiac::FlowComponent::DelayedEjection, "delayed", &cardiac::FlowComponents::delayedEjection},
    {cardiac::FlowComponent::RetainedInflow, "retained", &cardiac::FlowComponents::retainedInflow},
    {cardiac::FlowComponent::Residual, "residual", &cardiac::FlowComponents::residual}};

ImU32 componentU32(cardiac::FlowComponent component) {
  const render::Vec3f c = render::componentColour(component);
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c.x(), c.y(), c.z(), 1));
}

// One bar of the four shares, each segment as wide as its share, its percentage in it where
// there is room.
void shareBar(const char* label, const std::string& which, const std::optional<cardiac::FlowComponents>& f,
              const char* missing) {
  ImGui::TextColored(kMuted, "%s", label);
  ImGui::SameLine(56);
  if (!f || f->particles == 0) {
    ImGui::TextColored(kMuted, "%s", missing);
    return;
  }
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x, height = ImGui::GetTextLineHeight();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  float x = origin.x;
  std::string tip = which + ", of the blood in the ventricle at its end-diastole:";
  for (const ComponentShare& c : kShares) {
    const double share = (*f).*c.share;
    const float w = float(share) * width;
    draw->AddRectFilled(ImVec2(x, origin.y), ImVec2(x + w, origin.y + height), componentU32(c.component));
    char percent[16];
    std::snprintf(percent, sizeof percent, "%.0f", share * 100);
    if (ImGui::CalcTextSize(percent).x + 4 < w)
      draw->AddText(ImVec2(x + (w - ImGui::CalcTextSize(percent).x) / 2, origin.y),
                    c.component == cardiac::FlowComponent::DelayedEjection ? IM_COL32(40, 40, 40, 255)
                                                                           : IM_COL32(255, 255, 255, 255),
                    percent);
    tip += std::string("\n  ") + c.word + ": " + percent + "%";
    x += w;
  }
  ImGui::Dummy(ImVec2(width, height));
  tooltip(tip);
}

// Where the blood goes: the last beat's four flow components (4D-flow MRI's, of the blood in
// the ventricle at end-diastole) now, and the run before's beside it.
void flowComponentBars(const PumpStatus& s, const RunComparison& runs) {
  const char* tip =
      "Where the blood goes, as 4D-flow MRI measures it (Bolger 2007, Eriksson 2010): of the blood in the "
      "ventricle at end-diastole, direct flow came in this diastole and leaves in the systole, retained "
      "inflow came in and stays, delayed ejection was there before and leaves, residual was there before "
      "and stays. Numbers: % of the end-diastolic volume, the last beat's. Healthy: direct about 38, "
      "retained 16, delayed 16, residual 30 (Stoll 2018). Blood colour 'components' shows them on the heart.";
  ImGui::TextUnformatted("blood:");
  tooltip(tip);
  for (const ComponentShare& c : kShares) {
    ImGui::SameLine(0, 6);
    const render::Vec3f v = render::componentColour(c.component);
    ImGui::TextColored(ImVec4(v.x(), v.y(), v.z(), 1), "%s", c.word);
    tooltip(tip);
  }
  shareBar("now", "This run's beat " + std::to_string(s.flowBeat), s.flowComponents,
           "after the first beat's systole");
  if (const std::optional<RunRecord>& previous = runs.previous())
    shareBar("before", "The run before's last beat (" + previous->label + ")", previous->flowComponents,
             "not measured (no blood)");
}

void plots(PumpControls& c, const PumpStatus& s, const PlotHistory& history, const RunComparison& runs) {
  const VolumeScale& u = s.scale;
  const PlotAxes& axes = s.axes;
  auto makeSpec = [](const char* title, std::string unit, double scale, const char* tip,
                     std::vector<PlotSeries> series, AxisRange range) {
    PlotSpec p;
    p.title = title, p.unit = std::move(unit), p.scale = scale, p.tooltip = tip;
    p.series = std::move(series), p.range = range;
    return p;
  };
  std::vector<PlotSpec> specs;
  specs.push_back(
      makeSpec("Cavity volume", u.volumeUnit, u.volume,
               "The blood volume inside the left ventricle: it falls in systole (ejection) and rises "
               "in diastole (filling). The axis is fixed, so a small stroke looks small.",
               {{"LV", &PumpSample::cavity, kVolumeColour}}, axes.volume()));
  if (s.hasBlood) {
    char note[48];
    std::snprintf(note, sizeof note, "smoothed over %.0f ms", history.smoothingSeconds() * 1000);
    PlotSpec flow =
        makeSpec("Valve flow", u.flowUnit, u.volume,
                 "Blood volume per second through each valve, forward (into the ventricle for the "
                 "mitral, out into the aorta for the aortic) minus backward; below zero blood flows "
                 "back. Counted from the blood particles crossing each valve's disc: one particle "
                 "per step is a step of tens of mL/s, and particles jittering at an open valve "
                 "cross it to and fro, so the flow is the mean over the window named above "
                 "(centred: it lags now by half the window).",
                 {{"mitral", &PumpSample::mitralSmoothed, kMitralColour},
                  {"aortic", &PumpSample::aorticSmoothed, kAorticColour}},
                 axes.flow());
    flow.note = note;
    specs.push_back(flow);
  }
  if (s.hasBlood || s.lumped) {
    const bool mmHg = !u.thesis;
    PlotSpec pressure =
        s.lumped ? makeSpec("Pressure", "mmHg", axes.pressureScale(),
                            "The lumped circulation's pressures, as a catheter would read them: the "
                            "left ventricle (LV), the left atrium (LA) and the proximal aorta. The 3D "
                            "heart's wall follows this model's volume.",
                            {{"LV", &PumpSample::pressureLv, kVolumeColour},
                             {"LA", &PumpSample::pressureInflow, kInflowColour},
                             {"aorta", &PumpSample::pressureOutflow, kOutflowColour}},
                            axes.pressure())
                 : makeSpec("Mean pressure", mmHg ? "mmHg" : "Pa", axes.pressureScale(),
                            "The blood solver's mean gauge pressure in the ventricle (LV), the inflow "
                            "vessel (toward the atrium) and the outflow vessel (the aorta), relative to "
                            "the fluid at rest. At thesis scale it has no clinical meaning.",
                            {{"LV", &PumpSample::pressureLv, kVolumeColour},
                             {"inflow", &PumpSample::pressureInflow, kInflowColour},
                             {"outflow", &PumpSample::pressureOutflow, kOutflowColour}},
                            axes.pressure());
    specs.push_back(pressure);
  }
  ImGui::SliderFloat("plot window", &c.plotWindowSeconds, 0.5f, 20.0f, "%.1f s",
                     ImGuiSliderFlags_Logarithmic);
  tooltip("Simulated seconds shown in the plots (the newest on the right)");
  const std::optional<RunRecord>& previous = runs.previous();
  std::span<const PumpSample> before;
  if (previous && runs.comparable() && !previous->beatCurve.empty()) {
    before = previous->beatCurve;
    // Wrapped: the run's label names what changed, as long as that is.
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.45f, 0.45f, 0.45f, 1));
    ImGui::TextWrapped("grey: before (%s)", previous->label.c_str());
    ImGui::PopStyleColor();
    tooltip("The last beat of the run before the restart, laid under each beat of this run from its start");
  }
  // The charts share what is left of the panel's height.
  const float lineHeight = ImGui::GetTextLineHeightWithSpacing();
  const float rest = ImGui::GetContentRegionAvail().y - float(specs.size()) * (2.4f * lineHeight + 8);
  const float height = std::clamp(rest / float(specs.size()), 70.0f, 170.0f);
  for (const PlotSpec& spec : specs) {
    ImGui::Spacing();
    drawPlot(spec.title, spec, history, height, before);
  }
}

}  // namespace

void drawPumpPanel(PumpControls& controls, const PumpStatus& status, const PlotHistory& history,
                   const RunComparison& runs, int windowWidth, int windowHeight) {
  if (!status.hasHeart) return;
  beginSidePanel("pump", "Heart as a pump", float(windowWidth) - kPumpPanelWidth, kPumpPanelWidth,
                 windowHeight);
  phaseAndValves(status);
  ImGui::Spacing();
  beatTable(controls, status, runs);
  ImGui::Spacing();
  if (status.hasBlood) flowComponentBars(status, runs);
  ImGui::Separator();
  plots(controls, status, history, runs);
  endSidePanel();
}

}  // namespace hs::viewer
