#include "viewer/panels/help_window.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <span>

#include "viewer/panels/ui_panel.h"

namespace hs::viewer {
namespace {

struct Row {
  const char* name;
  const char* meaning;
  const char* normal;  // "" where a range does not apply
};

// Adult at rest. Volumes and fractions: ASE/EACVI chamber quantification (Lang et al. 2015,
// J Am Soc Echocardiogr 28:1); pressures: the physiology textbooks' resting values.
constexpr Row kNumbers[] = {
    {"EDV", "End-diastolic volume: the blood in the ventricle when it is fullest, just before it contracts.",
     "about 100-160 mL"},
    {"ESV", "End-systolic volume: the blood left in it when it has finished ejecting.", "about 35-70 mL"},
    {"SV", "Stroke volume = EDV - ESV: what one beat moves out of the ventricle.", "60-100 mL"},
    {"forward SV", "Stroke volume minus what leaks back (regurgitation): what reaches the body.",
     "equal to SV in a healthy heart"},
    {"EF", "Ejection fraction = SV / EDV: the share of its blood the ventricle ejects each beat.",
     "55-70 %; below 40 % is reduced"},
    {"CO", "Cardiac output = SV x heart rate: blood pumped per minute.", "4-8 L/min"},
    {"heart rate", "Beats per minute.", "60-100 bpm"},
    {"regurgitation", "Blood flowing backwards through a valve in one beat (a leaking valve).", "about 0 mL"},
    {"BP", "Aortic pressure, highest (systolic) over lowest (diastolic) in a beat.", "below 120/80 mmHg"},
    {"LV pressure", "Pressure in the ventricle: it rises above the aorta's to eject.",
     "peak = systolic BP; end-diastolic 4-12 mmHg"},
    {"LA pressure", "Left atrial pressure: what fills the ventricle (the preload).", "6-12 mmHg"},
    {"now / before", "'now' averages the last complete beats of this run; 'before' the run you had before "
                     "the last restart, so a change can be compared.",
     ""},
};

constexpr Row kColours[] = {
    {"red", "Myocardium (heart muscle); dark red: the face the clipping plane cuts.", ""},
    {"orange", "The beating region you chose (Beating region section).", ""},
    {"violet", "Segments that beat out of step (the 'inconsistent' heart).", ""},
    {"pale pink, cream", "The vessels and the fibrous plate between the valves: they do not contract.", ""},
    {"blue to yellow", "Blood speed: blue still, yellow at the top of the key (bottom left).", ""},
    {"pressure colours", "Blood pressure from the blood solver, on the same scale (key bottom left).", ""},
    {"grey curves", "The run before the last restart, for comparison.", ""},
};

constexpr Row kControls[] = {
    {"Scenario", "Loads another heart (or a thesis model, or blood alone) and restarts.", ""},
    {"Circulation",
     "In the human-size hearts a model of the body's circulation drives the wall: preload (filling "
     "pressure) changes EDV and SV (Frank-Starling); resistance (afterload) raises the pressures and "
     "lowers SV; contractility changes ESV and EF; compliance how the aorta stretches.",
     "restarts"},
    {"Beating region",
     "Which parts of the wall contract. With the circulation model, a resting region lowers the "
     "ventricle's contractility by its share of the wall, so EF falls.",
     "Apply restarts"},
    {"Blood",
     "How the blood is simulated: viscosity, number of particles, where it starts, valves. Where the "
     "circulation model drives the wall, the wall does not feel the blood: these change how the blood "
     "moves and looks, not EF or the pressures.",
     "restarts"},
    {"cardiac cycle", "Thesis models: the wall's motion is prescribed (heart rate, contraction); the "
                      "blood follows the wall, pressures do not change the filling.",
     "restarts"},
    {"Display", "Clipping plane, wall opacity, blood colours, look (liquid or spheres), flow streaks or "
                "arrows, labels and views: only the picture changes.",
     ""},
    {"speed", "Simulated seconds per second. When the computer cannot keep up, the panel says so "
              "('asked 1x, reaching 0.3x'): you see slow motion, nothing is skipped.",
     ""},
};

constexpr const char* kKeys[][2] = {
    {"left drag", "orbit around the heart"},
    {"right or middle drag", "pan"},
    {"wheel", "zoom"},
    {"1 / F", "front view (anterior, from +z)"},
    {"2 / L", "left view (from -x, lateral side)"},
    {"3", "right view (from +x, septal side)"},
    {"4 / T", "top view (onto the base)"},
    {"R", "reset the camera"},
    {"Space", "play / pause"},
    {"S", "single step (pauses)"},
    {"Backspace", "restart the scenario"},
    {"P", "picture (PNG in the working directory)"},
    {"F5", "save the state (checkpoint in the working directory; view --resume FILE loads it)"},
    {"N", "labels and flow arrows on / off"},
    {"B", "paint mode on / off (beating region)"},
    {"left drag (paint mode)", "add the wall under the brush"},
    {"Shift + left drag", "remove it (paint mode)"},
    {"[ / ]", "smaller / larger brush"},
    {"Enter", "apply the region (restarts from t = 0)"},
    {"C", "PV loop and Wiggers diagram on / off (circulation model)"},
    {"H / F1", "this help"},
    {"Esc", "close this window (or Compare); with none open, quit"},
};

void rowsTable(const char* id, std::span<const Row> rows, const char* thirdColumn) {
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_SizingStretchProp;
  if (!ImGui::BeginTable(id, 3, flags)) return;
  ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, 110);
  ImGui::TableSetupColumn("what it is", ImGuiTableColumnFlags_WidthStretch);
  ImGui::TableSetupColumn(thirdColumn, ImGuiTableColumnFlags_WidthFixed, 150);
  ImGui::TableHeadersRow();
  for (const Row& row : rows) {
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextUnformatted(row.name);
    ImGui::TableSetColumnIndex(1);
    ImGui::TextWrapped("%s", row.meaning);
    ImGui::TableSetColumnIndex(2);
    ImGui::TextWrapped("%s", row.normal);
  }
  ImGui::EndTable();
}

}  // namespace

void drawHelpWindow(bool& open, int& page, int windowWidth, int windowHeight) {
  if (!open) return;
  const float width = 640, height = std::min(560.0f, float(windowHeight) - 40);
  ImGui::SetNextWindowPos(ImVec2(float(windowWidth) / 2 + kPanelWidth / 2, float(windowHeight) / 2),
                          ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_Appearing);
  ImGui::Begin("Help", &open, ImGuiWindowFlags_NoSavedSettings);
  // The pages as a row of buttons, the one shown marked. Not ImGui's tab bar: Debian's ImGui
  // (1.86) lets a tab take a click only if the pointer was on it or on nothing the frame before,
  // so a tap or a quick click after the pointer jumped from another tab chose nothing while the
  // tab lit up (tests/viewer/panels/test_help_window.cpp).
  constexpr std::array<const char*, kHelpPageCount> kPages = {"The numbers", "Colours", "Controls", "Mouse and keys"};
  page = std::clamp(page, 0, kHelpPageCount - 1);
  for (int i = 0; i < kHelpPageCount; ++i) {
    if (i > 0) ImGui::SameLine();
    const bool shown = page == i;
    if (shown) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_TabActive));
    if (ImGui::Button(kPages[std::size_t(i)])) page = i;
    if (shown) ImGui::PopStyleColor();
  }
  ImGui::Separator();
  switch (page) {
    case 0:
      rowsTable("numbers", kNumbers, "normal (adult, rest)");
      break;
    case 1:
      rowsTable("colours", kColours, "");
      break;
    case 2:
      rowsTable("controls", kControls, "then");
      break;
    default:
      if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
        for (const auto& row : kKeys) {
          ImGui::TableNextRow();
          ImGui::TableSetColumnIndex(0);
          ImGui::TextUnformatted(row[0]);
          ImGui::TableSetColumnIndex(1);
          ImGui::TextUnformatted(row[1]);
        }
        ImGui::EndTable();
      }
  }
  ImGui::End();
}

}  // namespace hs::viewer
