#include "viewer/blood_controls.h"

#include <imgui.h>

#include <array>

namespace hs::viewer {
namespace {

using Start = cardiac::BloodSettings::Start;
using cardiac::ValveMode;

void tooltip(const char* text) {
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

const char* startName(Start start) {
  switch (start) {
    case Start::Vessel:
      return "inflow vessel";
    case Start::Chamber:
      return "chamber";
    case Start::Block:
      return "block";
  }
  return "?";
}

const char* valveName(ValveMode mode) {
  switch (mode) {
    case ValveMode::Timing:
      return "timing";
    case ValveMode::Pressure:
      return "pressure";
    case ValveMode::Open:
      return "open";
  }
  return "?";
}

}  // namespace

BloodControls bloodControlsFrom(const cardiac::Scenario& scenario, int particleCount) {
  BloodControls c;
  c.viscosity = double(scenario.blood.viscosity);
  c.particles = scenario.blood.particles > 0 ? scenario.blood.particles : particleCount;
  c.start = scenario.blood.start;
  c.twoWay = scenario.circulation.twoWay;
  c.valveMode = scenario.circulation.valveMode;
  return c;
}

void applyBloodControls(const BloodControls& c, cardiac::Scenario& scenario) {
  scenario.blood.viscosity = cardiac::Real(c.viscosity);
  if (c.particlesEdited) scenario.blood.particles = c.particles;
  scenario.blood.start = c.start;
  scenario.circulation.twoWay = c.twoWay;
  scenario.circulation.valveMode = c.valveMode;
}

void drawBloodSection(BloodControls& c, bool hasHeart) {
  const double minViscosity = 0.0005, maxViscosity = 0.5;
  ImGui::SliderScalar("viscosity", ImGuiDataType_Double, &c.viscosity, &minViscosity, &maxViscosity,
                      "%.4f Pa s", ImGuiSliderFlags_Logarithmic);
  if (ImGui::IsItemDeactivatedAfterEdit()) c.changed = true;
  tooltip(
      "How thick (syrupy) the blood is, in pascal seconds. Real blood: about 0.0035 Pa s, water 0.001; "
      "the thesis used 0.04.\nThe simulation fixes it when it starts: applied when you release the "
      "slider, restarting from t = 0.");
  ImGui::SliderInt("particles", &c.particles, 100, 20000, "%d", ImGuiSliderFlags_Logarithmic);
  if (ImGui::IsItemDeactivatedAfterEdit()) c.changed = c.particlesEdited = true;
  tooltip(
      "Blood particles, each a small parcel of blood. More: finer flow, slower simulation.\nApplied on "
      "release, restarting from t = 0. A start region too small for them is reported below.");
  if (!hasHeart) return;
  constexpr std::array kStarts = {Start::Vessel, Start::Chamber};
  if (ImGui::BeginCombo("blood start", startName(c.start))) {
    for (const Start s : kStarts)
      if (ImGui::Selectable(startName(s), s == c.start) && s != c.start) {
        c.start = s;
        c.changed = true;
      }
    ImGui::EndCombo();
  }
  tooltip(
      "Where the blood is at t = 0: in the inflow vessel (it fills the ventricle through the mitral "
      "valve) or already in the chamber. Restarts from t = 0.");
  if (ImGui::Checkbox("two-way coupling", &c.twoWay)) c.changed = true;
  tooltip(
      "On: the blood pushes the heart wall back (the wall feels the blood's pressure).\nOff: the wall "
      "moves the blood but does not feel it, as in the thesis. Restarts from t = 0.");
  constexpr std::array kModes = {ValveMode::Timing, ValveMode::Pressure, ValveMode::Open};
  if (ImGui::BeginCombo("valves", valveName(c.valveMode))) {
    for (const ValveMode m : kModes)
      if (ImGui::Selectable(valveName(m), m == c.valveMode) && m != c.valveMode) {
        c.valveMode = m;
        c.changed = true;
      }
    ImGui::EndCombo();
  }
  tooltip(
      "When the valves open.\ntiming: the mitral valve in diastole, the aortic valve in systole (the "
      "thesis).\npressure: a valve opens while the pressure before it is higher than after it, as real "
      "valves do.\nopen: both always open, as if there were no valves.\nRestarts from t = 0.");
}

}  // namespace hs::viewer
