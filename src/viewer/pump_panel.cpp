#include "viewer/pump_panel.h"

#include <imgui.h>

#include <algorithm>
#include <string>

#include "viewer/panel_widgets.h"
#include "viewer/plot_widget.h"

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

void phaseAndValves(const PumpStatus& s) {
  if (!s.cycleOn) {
    ImGui::TextColored(kMuted, "phase: rest (the cardiac cycle is off)");
  } else if (s.phase == cardiac::Phase::Systole) {
    ImGui::TextColored(ImVec4(0.75f, 0.15f, 0.15f, 1), "phase: systole (contracting, ejecting)");
  } else if (s.phase == cardiac::Phase::Diastole) {
    ImGui::TextColored(ImVec4(0.15f, 0.35f, 0.75f, 1), "phase: diastole (relaxing, filling)");
  } else {
    ImGui::TextColored(kMuted, "phase: rest (the wall does not beat)");
  }
  tooltip(
      "Systole: the wall contracts and pushes blood out through the aortic valve.\n"
      "Diastole: the wall relaxes and the ventricle fills through the mitral valve.");
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

void cell(const std::optional<ClinicalFigures>& f, const Row& row, const char* pending,
          const char* pendingTip) {
  if (!f) {
    ImGui::TextColored(kMuted, "%s", pending);
    tooltip(pendingTip);
  } else if (row.needsCompleteBeat && !f->complete) {
    ImGui::TextColored(kMuted, "...");
    tooltip("Known when the beat ends (the next systole starts)");
  } else {
    ImGui::TextUnformatted(formatValue((*f).*row.value).c_str());
  }
}

void beatTable(const PumpStatus& s) {
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
      {"stroke volume (" + v + ")", "SV = EDV - ESV: the blood one beat ejects." + normal(s, "about 70 mL"),
       &ClinicalFigures::strokeVolume, false},
      {"ejection fraction (%)",
       "EF = SV / EDV: the share of the filled ventricle one beat ejects. Normal: 55 to 70 %; below 40 % the "
       "heart pumps poorly (heart failure with reduced EF).",
       &ClinicalFigures::ejectionFraction, false},
      {"cardiac output (" + std::string(u.outputUnit) + ")",
       "CO = SV x heart rate: the blood pumped per minute." + normal(s, "about 5 L/min"),
       &ClinicalFigures::cardiacOutput, true},
      {"heart rate (bpm)",
       "Beats per minute, measured from the beat's length: 60 / length (s)." + normal(s, "60 to 100 bpm") +
           timing,
       &ClinicalFigures::heartRate, true},
  };
  if (s.hasBlood)
    rows.push_back(
        {"regurgitation (" + v + ")",
         "Regurgitant volume: blood that went back the wrong way in this beat, back through the mitral "
         "valve in systole or back through the aortic valve in diastole (mitral or aortic "
         "regurgitation, a leaking valve). Healthy valves: close to 0.",
         &ClinicalFigures::regurgitantVolume, false});

  const BeatReadings& b = s.beats;
  std::optional<ClinicalFigures> current, last;
  if (b.current) current = clinicalFigures(*b.current, u);
  if (b.last) last = clinicalFigures(*b.last, u);
  if (ImGui::BeginTable("beats", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
    ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("this beat", ImGuiTableColumnFlags_WidthFixed, 72);
    ImGui::TableSetupColumn("last beat", ImGuiTableColumnFlags_WidthFixed, 72);
    ImGui::TableNextRow(ImGuiTableRowFlags_Headers);
    ImGui::TableSetColumnIndex(0);
    ImGui::TextDisabled("beat");
    ImGui::TableSetColumnIndex(1);
    const std::string now = b.beating ? "now (" + std::to_string(b.beatsCompleted + 1) + ")" : "now";
    ImGui::TextUnformatted(now.c_str());
    tooltip("The beat in progress, counted from the start of its systole");
    ImGui::TableSetColumnIndex(2);
    const std::string before = b.last ? "last (" + std::to_string(b.last->index) + ")" : "last";
    ImGui::TextUnformatted(before.c_str());
    tooltip("The last complete beat, from one systole's start to the next");
    for (const Row& row : rows) {
      ImGui::TableNextRow();
      ImGui::TableSetColumnIndex(0);
      ImGui::TextUnformatted(row.label.c_str());
      tooltip(row.tip);
      ImGui::TableSetColumnIndex(1);
      if (!current && b.beating && row.value == &ClinicalFigures::edv) {
        ImGui::TextUnformatted(formatValue(b.currentEdv * u.volume).c_str());
      } else {
        cell(current, row, b.beating ? "..." : "-",
             b.beating ? "Known when systole ends" : "No beat yet: the wall has not contracted");
      }
      ImGui::TableSetColumnIndex(2);
      cell(last, row, "-", "No complete beat yet");
    }
    ImGui::EndTable();
  }
}

void plots(PumpControls& c, const PumpStatus& s, const PlotHistory& history) {
  const VolumeScale& u = s.scale;
  auto makeSpec = [](const char* title, std::string unit, double scale, const char* tip,
                     std::vector<PlotSeries> series, bool includeZero) {
    PlotSpec p;
    p.title = title, p.unit = std::move(unit), p.scale = scale, p.tooltip = tip;
    p.series = std::move(series), p.includeZero = includeZero;
    return p;
  };
  std::vector<PlotSpec> specs;
  specs.push_back(
      makeSpec("Cavity volume", u.volumeUnit, u.volume,
               "The blood volume inside the left ventricle: it falls in systole (ejection) and rises "
               "in diastole (filling).",
               {{"LV", &PumpSample::cavity, kVolumeColour}}, false));
  if (s.hasBlood) {
    specs.push_back(
        makeSpec("Flow through the valves", u.flowUnit, u.volume,
                 "Blood volume per second through each valve, forward (into the ventricle for the "
                 "mitral, out into the aorta for the aortic) minus backward; below zero blood flows "
                 "back.",
                 {{"mitral", &PumpSample::mitralRate, kMitralColour},
                  {"aortic", &PumpSample::aorticRate, kAorticColour}},
                 true));
    PlotSpec pressure =
        makeSpec("Mean pressure", "Pa", 1,
                 "The blood's mean pressure in the ventricle (LV), the inflow vessel (toward the "
                 "atrium) and the outflow vessel (the aorta), relative to the fluid at rest. "
                 "1 mmHg = 133.3 Pa.",
                 {{"LV", &PumpSample::pressureLv, kVolumeColour},
                  {"inflow", &PumpSample::pressureInflow, kInflowColour},
                  {"outflow", &PumpSample::pressureOutflow, kOutflowColour}},
                 true);
    if (!u.thesis) pressure.secondUnit = "mmHg", pressure.secondScale = 1 / kPascalPerMmHg;
    specs.push_back(pressure);
  }
  ImGui::SliderFloat("plot window", &c.plotWindowSeconds, 0.5f, 20.0f, "%.1f s",
                     ImGuiSliderFlags_Logarithmic);
  tooltip("Simulated seconds shown in the plots (the newest on the right)");
  // The charts share what is left of the panel's height.
  const float lineHeight = ImGui::GetTextLineHeightWithSpacing();
  const float rest = ImGui::GetContentRegionAvail().y - float(specs.size()) * (2.4f * lineHeight + 8);
  const float height = std::clamp(rest / float(specs.size()), 70.0f, 170.0f);
  for (const PlotSpec& spec : specs) {
    ImGui::Spacing();
    drawPlot(spec.title, spec, history, height);
  }
}

}  // namespace

void drawPumpPanel(PumpControls& controls, const PumpStatus& status, const PlotHistory& history,
                   int windowWidth, int windowHeight) {
  if (!status.hasHeart) return;
  beginSidePanel("pump", "Heart as a pump", float(windowWidth) - kPumpPanelWidth, kPumpPanelWidth,
                 windowHeight);
  phaseAndValves(status);
  ImGui::Spacing();
  beatTable(status);
  ImGui::Spacing();
  ImGui::Separator();
  plots(controls, status, history);
  endSidePanel();
}

}  // namespace hs::viewer
