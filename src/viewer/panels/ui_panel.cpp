#include "viewer/panels/ui_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

#include "render/scene.h"
#include "viewer/plots/panel_widgets.h"

namespace hs::viewer {
namespace {

// ImGui 1.86 has no SeparatorText.
void sectionTitle(const char* title) {
  ImGui::Separator();
  ImGui::TextDisabled("%s", title);
}

ImU32 colourU32(const render::Vec3f& c) { return ImGui::GetColorU32(ImVec4(c.x(), c.y(), c.z(), 1)); }

// The blood colour scale as a horizontal bar, 0 on the left, top on the right.
OverlayBox currentWindowBox() {
  const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  return {pos.x, pos.y, size.x, size.y};
}

void scaleLegend(const char* title, double speedMax, const char* unit) {
  ImGui::TextUnformatted(title);
  const float width = ImGui::GetContentRegionAvail().x, height = 14;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  constexpr int kSegments = 32;
  for (int i = 0; i < kSegments; ++i) {
    const float x0 = origin.x + width * float(i) / kSegments,
                x1 = origin.x + width * float(i + 1) / kSegments;
    const ImU32 left = colourU32(render::speedColour(double(i) / kSegments));
    const ImU32 right = colourU32(render::speedColour(double(i + 1) / kSegments));
    draw->AddRectFilledMultiColor(ImVec2(x0, origin.y), ImVec2(x1, origin.y + height), left, right, right,
                                  left);
  }
  draw->AddRect(origin, ImVec2(origin.x + width, origin.y + height), IM_COL32(90, 90, 100, 255));
  ImGui::Dummy(ImVec2(width, height));
  char top[32], mid[32];
  std::snprintf(top, sizeof top, "%g", speedMax);
  std::snprintf(mid, sizeof mid, "%g", speedMax / 2);
  ImGui::TextUnformatted("0");
  ImGui::SameLine(width / 2 - ImGui::CalcTextSize(mid).x / 2);
  ImGui::TextUnformatted(mid);
  ImGui::SameLine(width - ImGui::CalcTextSize(top).x + ImGui::GetStyle().WindowPadding.x);
  ImGui::TextUnformatted(top);
  char key[96];
  std::snprintf(key, sizeof key, "Blue = 0, yellow = %g %s or more", speedMax, unit);
  tooltip(key);
}

// Blood coloured by where it started: one swatch per origin.
void originLegend() {
  ImGui::TextUnformatted("Blood by where it started");
  for (const render::OriginKeyRow& row : render::originKey()) {
    const render::Vec3f c = render::originColour(row.origin);
    ImGui::TextColored(ImVec4(c.x(), c.y(), c.z(), 1), "o");
    ImGui::SameLine();
    ImGui::TextUnformatted(row.label);
  }
}

// Blood coloured by flow component or by how long it stayed: one swatch per row, the rule in
// the tooltip.
template <class Rows, class Colour, class Label>
void swatchLegend(const char* title, const Rows& rows, Colour colour, Label label, const char* tip) {
  ImGui::TextUnformatted(title);
  tooltip(tip);
  for (const auto& row : rows) {
    const render::Vec3f c = colour(row);
    ImGui::TextColored(ImVec4(c.x(), c.y(), c.z(), 1), "o");
    ImGui::SameLine();
    ImGui::TextUnformatted(label(row));
    tooltip(tip);
  }
}

void componentLegend() {
  static const std::string tip = [] {
    std::string t = "The flow components of 4D-flow MRI (Bolger 2007, Eriksson 2010), of the blood in the "
                    "ventricle at end-diastole:";
    for (const render::ComponentKeyRow& row : render::componentKey()) t += std::string("\n  ") + row.label;
    return t + ".\nThe colours: " + render::kComponentRule + ". The shares are in the pump panel.";
  }();
  swatchLegend(
      "Blood by flow component", render::componentKey(),
      [](const render::ComponentKeyRow& r) { return render::componentColour(r.component); },
      [](const render::ComponentKeyRow& r) { return r.shortLabel; }, tip.c_str());
}

void stayLegend() {
  swatchLegend("Blood by how long it stayed", render::stayKey(),
               [](const render::StayKeyRow& r) { return render::stayColour(r.stay); },
               [](const render::StayKeyRow& r) { return r.label; },
               "How many beats each particle has been in the ventricle, counted from the diastole it entered "
               "in: blood that stays long is slow blood, where a clot can form (an akinetic apex).");
}

void simulationSection(ViewerControls& c, const ViewerStatus& s) {
  if (ImGui::Button(c.playing ? "Pause" : "Play", ImVec2(54, 0))) c.playing = !c.playing;
  tooltip("Run or pause the simulation (Space)");
  ImGui::SameLine();
  if (ImGui::Button("Step", ImVec2(42, 0))) c.stepRequested = true;
  char stepTip[96];
  std::snprintf(stepTip, sizeof stepTip, "Advance one time step of %g ms and pause (S)", s.dt * 1000);
  tooltip(stepTip);
  ImGui::SameLine();
  if (ImGui::Button("Reset", ImVec2(46, 0))) c.resetRequested = true;
  tooltip("Restart the scenario from t = 0 (Backspace)");
  ImGui::SameLine();
  if (ImGui::Button("Picture")) c.screenshotRequested = true;
  tooltip("Save the window as a PNG in the working directory (P); the message in the scene gives its path");
  ImGui::SameLine();
  if (ImGui::Button("Help")) c.showHelp = !c.showHelp;
  tooltip("What the numbers, colours and controls mean; mouse and keys (H or F1)");
  if (ImGui::Button("Save state")) c.saveStateRequested = true;
  tooltip("Save the whole simulation as checkpoint_<time>s.hsck in the working directory (F5); "
          "heartsim view --resume FILE or heartsim run --resume FILE continues it from there");
  ImGui::SliderFloat("speed", &c.speed, 0.01f, 4.0f, "%.2fx", ImGuiSliderFlags_Logarithmic);
  tooltip("Simulated seconds per second of wall-clock time (1x = real time)");
  if (const std::string shortfall = speedShortfall(double(c.speed), s); !shortfall.empty()) {
    ImGui::TextColored(ImVec4(0.75f, 0.35f, 0.0f, 1), "%s", shortfall.c_str());
    tooltip("The simulation computes as fast as this machine allows and still falls short of the "
            "speed asked: the heart is shown in slow motion, every step of it computed. Fewer blood "
            "particles (Blood section) run faster.");
  }
  if (s.hasBlood) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", resolutionLine(s.resolution, s.realTimeFactor, s.behind, !c.playing).c_str());
    ImGui::PopStyleColor();
    tooltip("The blood's resolution (Blood section): at start-up the viewer measures each level on this "
            "computer and picks the finest that keeps up with real time; a finer one runs in slow motion.");
  }
}

// A folding section of the panel; opening one closes the one open before.
bool section(const char* title, PanelSection id, PanelSection& open) {
  ImGui::SetNextItemOpen(open == id, ImGuiCond_Always);
  const bool shown = ImGui::CollapsingHeader(title);
  if (ImGui::IsItemToggledOpen()) open = shown ? id : PanelSection::None;
  return shown;
}

void scenarioSection(ViewerControls& c, const ViewerStatus& s, const std::vector<ScenarioChoice>& scenarios) {
  const char* preview = c.scenarioIndex >= 0 && c.scenarioIndex < int(scenarios.size())
                            ? scenarios[std::size_t(c.scenarioIndex)].name.c_str()
                            : s.scenarioName.c_str();
  if (ImGui::BeginCombo("scenario", preview, ImGuiComboFlags_HeightLarge)) {
    for (const ScenarioGroup group : {ScenarioGroup::HumanHeart, ScenarioGroup::ThesisModel, ScenarioGroup::BloodOnly}) {
      ImGui::TextDisabled("%s", scenarioGroupTitle(group));
      for (int i = 0; i < int(scenarios.size()); ++i) {
        const ScenarioChoice& choice = scenarios[std::size_t(i)];
        if (choice.group != group) continue;
        const bool selected = i == c.scenarioIndex;
        ImGui::Indent(8);
        if (ImGui::Selectable(choice.name.c_str(), selected) && !selected) {
          c.scenarioIndex = i;
          c.scenarioChanged = true;
        }
        ImGui::Unindent(8);
        if (!choice.description.empty()) tooltip(choice.description.c_str());
      }
    }
    ImGui::EndCombo();
  }
  tooltip("Built-in scenario presets (scenarios/*.toml); choosing one restarts the simulation");
  if (!s.hasHeart) return;
  if (c.circulation.lumped) {
    // The lumped circulation drives the wall: its volume, not a contraction, moves it (and it
    // needs the beat: no cycle checkbox); its heart rate sits with the circulation's settings.
    ImGui::TextDisabled("the lumped circulation drives the wall");
    tooltip("circulation.lumped: the wall follows the lumped ventricle's volume. Heart rate, preload, "
            "afterload and contractility are in the Circulation section below.");
    return;
  }
  if (!s.recordedBeat.empty()) {
    // A recorded beat ([motion]) moves the wall as recorded: no contraction, rate or region of
    // the cycle's applies (the scenario refuses them), so none is offered.
    ImGui::TextDisabled("a recorded beat drives the wall");
    tooltip(("[motion]: the endocardium follows " + s.recordedBeat +
             " recorded from a patient; the recording sets the heart rate and how the wall moves")
                .c_str());
    return;
  }
  if (ImGui::Checkbox("cardiac cycle", &c.cycleEnabled)) c.cycleChanged = true;
  tooltip("Let the wall beat (systole / diastole); changing it restarts the simulation");
  ImGui::BeginDisabled(!c.cycleEnabled);
  ImGui::SliderFloat("heart rate", &c.heartRateBpm, 30, 180, "%.0f bpm");
  if (ImGui::IsItemDeactivatedAfterEdit()) c.cycleChanged = true;
  tooltip(s.physiological
              ? "Beats per minute (physiological timing); applied on release, restarts the simulation"
              : "Beats per minute; switches the cycle to physiological timing (the scenario uses the "
                "thesis's step-count timing) and restarts the simulation");
  // Contraction strength, in the scenario's own timing (the sliders reach 40% of the cavity's
  // radius: beyond that the wall folds).
  if (s.physiological) {
    ImGui::SliderFloat("contraction", &c.contraction, 0, 0.4f * s.heartSize, "%.3g m");
    if (ImGui::IsItemDeactivatedAfterEdit()) c.cycleChanged = true;
    tooltip("How far each beating point of the wall moves inward in one systole: a stronger "
            "contraction ejects more (higher EF). Applied on release; restarts the simulation");
  } else {
    ImGui::SliderInt("phase length", &c.beatingDuration, 1, 40, "%d steps");
    if (ImGui::IsItemDeactivatedAfterEdit()) c.cycleChanged = true;
    tooltip("Thesis timing: time steps of each systole and each diastole (Table 5.4: 8). "
            "Applied on release; restarts the simulation");
    ImGui::SliderFloat("displacement", &c.beatingDisplace, 0, 0.1f * s.heartSize, "%.3g m/step");
    if (ImGui::IsItemDeactivatedAfterEdit()) c.cycleChanged = true;
    tooltip("Thesis timing: how far a beating point moves inward in each systolic step "
            "(Table 5.4: 0.08 m). Applied on release; restarts the simulation");
  }
  ImGui::EndDisabled();
}

void displaySection(ViewerControls& c, const ViewerStatus& s) {
  if (s.hasHeart) {
    ImGui::Checkbox("labels and flow arrows", &c.showLabels);
    tooltip("Name the left ventricle, the inflow (from the left atrium), the mitral and aortic valves, "
            "the aorta, the septum and the apex on the heart, with arrows the way blood flows forward (N)");
    ImGui::Checkbox("clipping plane", &c.clip);
    tooltip("Cut the wall open to see into the cavity (removes what lies in front of the plane z = const)");
    ImGui::BeginDisabled(!c.clip);
    ImGui::SliderFloat("clip z", &c.clipZ, s.clipMin, s.clipMax, "%.3f m");
    tooltip("Position of the cutting plane z = const (m); everything at larger z (toward the viewer in the front view) is removed: z = 0 opens the three-chamber plane");
    ImGui::EndDisabled();
    ImGui::SliderFloat("wall opacity", &c.wallOpacity, 0.1f, 1.0f, "%.2f");
    tooltip("Below 1 the wall is drawn see-through (0.1 to 1, no unit)");
  }
  if (s.hasBlood) {
    const char* kinds[] = {"speed", "pressure", "origin", "components", "stay"};
    ImGui::Combo("blood colour", &c.bloodColour, kinds, 5);
    tooltip("What the blood's colour shows: its speed (m/s) or its pressure (mmHg, from the density "
            "solve), both smoothed over the neighbours; where it started (inflow vessel, "
            "ventricle, or outside, through the loop); its flow component in the beat (green direct, "
            "blue retained inflow, yellow delayed ejection, red residual); or whether it has stayed "
            "in the ventricle more than 3 beats");
    const char* looks[] = {"liquid", "spheres"};
    ImGui::Combo("blood look", &c.bloodLook, looks, 2);
    tooltip("Liquid: a smooth surface over the particles (screen-space fluid); spheres: each "
            "particle as a ball. The liquid's resolution is lowered when needed to keep 25 fps");
    const char* flows[] = {"off", "streaks", "arrows"};
    ImGui::Combo("flow", &c.flowView, flows, 3);
    tooltip("Streaks: where blood went over the last 40 ms; arrows: its velocity now (the distance "
            "it covers in 10 ms). Both coloured by speed over pale blood");
  }
  ImGui::TextUnformatted("view");
  ImGui::SameLine();
  constexpr struct {
    const char* label;
    render::View view;
    const char* tip;
  } kViews[] = {{"front", render::View::Front, "Anterior view, from +z (1 or F)"},
                {"left", render::View::Left, "From -x, the lateral side (2 or L)"},
                {"right", render::View::Right, "From +x, the septal side (3)"},
                {"top", render::View::Top, "From +y onto the base (4 or T)"}};
  for (const auto& v : kViews) {
    if (ImGui::SmallButton(v.label)) c.viewRequested = v.view;
    tooltip(v.tip);
    ImGui::SameLine();
  }
  if (ImGui::SmallButton("reset")) c.resetCameraRequested = true;
  tooltip("Back to the front view, framing the heart (R)");
}

}  // namespace

const char* scenarioGroupTitle(ScenarioGroup group) {
  switch (group) {
    case ScenarioGroup::HumanHeart: return "Human-size hearts";
    case ScenarioGroup::ThesisModel: return "The thesis's models (metres across, not a human heart)";
    case ScenarioGroup::BloodOnly: return "Blood alone (no heart)";
  }
  return "";
}

std::string speedShortfall(double asked, const ViewerStatus& status) {
  if (!status.behind) return "";
  char text[96];
  std::snprintf(text, sizeof text, "asked %.2gx, reaching %.2gx: slow motion", asked, status.realTimeFactor);
  return text;
}

void drawControlPanel(ViewerControls& controls, const ViewerStatus& status,
                      const std::vector<ScenarioChoice>& scenarios, int windowHeight) {
  beginSidePanel("heartsim", "heartsim viewer", 0, kPanelWidth, windowHeight);
  simulationSection(controls, status);
  ImGui::Spacing();
  sectionTitle("Scenario");
  scenarioSection(controls, status, scenarios);
  PanelSection& open = controls.openSection;
  if (controls.circulation.lumped && section("Circulation", PanelSection::Circulation, open))
    drawCirculationSection(controls.circulation, controls.heartRateBpm, controls.cycleChanged,
                           controls.showCirculation);
  if (status.hasBlood && section("Blood", PanelSection::Blood, open))
    drawBloodSection(controls.blood, status.resolution, status.hasHeart, controls.circulation.lumped,
                     status.wallYields);
  if (status.hasHeart && status.recordedBeat.empty() && section("Beating region", PanelSection::Region, open))
    drawRegionSection(controls.region, status.region);
  if (section("Display", PanelSection::Display, open)) displaySection(controls, status);
  endSidePanel();
}

OverlayBox drawColourKey(const ViewerStatus& status, float leftEdge, float bottomEdge, bool folded) {
  if (!status.hasHeart && !status.hasBlood) return {leftEdge, bottomEdge, 0, 0};
  constexpr float kMargin = 10, kWidth = 260;
  ImGui::SetNextWindowPos(ImVec2(leftEdge + kMargin, bottomEdge - kMargin), ImGuiCond_Always,
                          ImVec2(0, 1));
  // A fixed width: the speed bar fills the window, which must not size itself after it.
  ImGui::SetNextWindowSize(ImVec2(kWidth, 0), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.75f);
  ImGui::Begin("colour key", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
  // Folded, the wall's colours give way to the blood's scale (or, without blood, keep their first line).
  if (status.hasHeart && !(folded && status.hasBlood)) {
    ImGui::TextColored(ImVec4(0.85f, 0.3f, 0.32f, 1), "red");
    ImGui::SameLine();
    ImGui::TextUnformatted("myocardium, dark red: cut face");
  }
  if (status.hasHeart && !folded) {
    const render::Vec3f beating = render::beatingColour(render::regionColour(cardiac::Region::Myocardium));
    ImGui::TextColored(ImVec4(beating.x(), beating.y(), beating.z(), 1), "orange");
    ImGui::SameLine();
    ImGui::TextUnformatted("the chosen beating region");
    ImGui::TextUnformatted("light: base plate and vessels");
    if (std::find(status.region.outOfStep.begin(), status.region.outOfStep.end(), true) !=
        status.region.outOfStep.end()) {
      const render::Vec3f v = render::outOfStepColour(render::regionColour(cardiac::Region::Myocardium));
      ImGui::TextColored(ImVec4(v.x(), v.y(), v.z(), 1), "violet");
      ImGui::SameLine();
      ImGui::TextUnformatted("beats out of step");
    }
  }
  if (status.hasBlood && status.flowView != 0) {
    if (status.hasHeart && !folded) ImGui::Spacing();
    scaleLegend("Flow lines: speed (m/s)", status.speedMax, "m/s");
  } else if (status.hasBlood) {
    if (status.hasHeart && !folded) ImGui::Spacing();
    switch (render::BloodColour(status.bloodColour)) {
      case render::BloodColour::Speed:
        scaleLegend("Blood speed (m/s)", status.speedMax, "m/s");
        if (status.circulation.lumped) {
          const render::Vec3f& grey = render::kVesselEndColour;
          ImGui::TextColored(ImVec4(grey.x(), grey.y(), grey.z(), 1), "grey");
          ImGui::SameLine();
          ImGui::TextUnformatted("vessels' far ends");
          tooltip("The lumped model's boundary: the blood there moves as its flows say, not as the blood flows");
        }
        break;
      case render::BloodColour::Pressure:
        scaleLegend("Blood pressure (mmHg)", status.pressureMax, "mmHg");
        break;
      case render::BloodColour::Origin: originLegend(); break;
      case render::BloodColour::Components: componentLegend(); break;
      case render::BloodColour::Stay: stayLegend(); break;
    }
  }
  const OverlayBox box = currentWindowBox();
  ImGui::End();
  return box;
}

OverlayBox drawStatusOverlay(const ViewerStatus& status, float rightEdge, float bottomEdge, bool folded) {
  constexpr float kMargin = 10;
  ImGui::SetNextWindowPos(ImVec2(rightEdge - kMargin, bottomEdge - kMargin), ImGuiCond_Always, ImVec2(1, 1));
  ImGui::SetNextWindowBgAlpha(0.75f);
  // Wide enough from the first frame for the longest phase's name: an automatic size follows its
  // content a frame late, and the box grows leftward from the corner, so a phase that just got
  // longer would be cut at the right edge for that frame.
  const float phaseWidth = ImGui::CalcTextSize("phase: isovolumic contraction").x;
  ImGui::SetNextWindowSizeConstraints(ImVec2(phaseWidth + 2 * ImGui::GetStyle().WindowPadding.x, 0),
                                      ImVec2(FLT_MAX, FLT_MAX));
  ImGui::Begin("status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav);
  // Folded, the scenario's name is left to the control panel's scenario line.
  if (!folded) ImGui::Text("%s", status.scenarioName.c_str());
  ImGui::Text("t = %.3f s", status.time);
  if (!status.phase.empty()) ImGui::Text("phase: %s", status.phase.c_str());
  // Folded, the pace only follows: the volume is in the pump panel beside, the frame time is for
  // engineers.
  if (!folded) {
    // The thesis-scale models are metres across: their volumes read better in m^3 (pump_readout.h).
    if (status.cavity >= 0 && status.pump.scale.thesis)
      ImGui::Text("cavity volume: %.3g m^3 (thesis scale)", status.cavity);
    else if (status.cavity >= 0)
      ImGui::Text("cavity volume: %.1f mL", status.cavity * status.pump.scale.volume);
    ImGui::Text("frame: %.1f ms (%.0f fps)", status.frameMs, status.frameMs > 0 ? 1000 / status.frameMs : 0.0);
    if (!status.liquidNote.empty()) {
      // Wrapped to the corner's usual width, so that it still fits beside the colour key.
      ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 220);
      ImGui::TextWrapped("%s", status.liquidNote.c_str());
      ImGui::PopTextWrapPos();
    }
  }
  // Always a line, so that the box keeps its height while the pace comes and goes (it grows
  // upward a frame late: a line that appears would be cut at the bottom for that frame).
  if (status.behind)
    ImGui::TextColored(ImVec4(0.85f, 0.45f, 0.05f, 1), "slow motion: %.2gx real time", status.realTimeFactor);
  else
    ImGui::TextDisabled("pace: as asked");
  const OverlayBox box = currentWindowBox();
  ImGui::End();
  return box;
}

}  // namespace hs::viewer
