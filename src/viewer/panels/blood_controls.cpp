#include "viewer/panels/blood_controls.h"

#include <imgui.h>

#include <array>
#include <cstdio>
#include <cstddef>
#include <span>

#include "viewer/plots/panel_widgets.h"

namespace hs::viewer {
namespace {

using Start = cardiac::BloodSettings::Start;
using cardiac::ValveMode;

// A value of a combo box below and the name it shows.
template <class E>
struct Choice {
  E value;
  const char* name;
};

// Every start has a name; the first three are offered (a block needs corners the panel has no
// controls for, but a scenario may start there).
constexpr std::array<Choice<Start>, 4> kStarts = {{{Start::Vessel, "inflow vessel"},
                                                   {Start::Chamber, "chamber"},
                                                   {Start::Heart, "heart and vessels"},
                                                   {Start::Block, "block"}}};
constexpr std::size_t kOfferedStarts = 3;
constexpr std::array<Choice<ValveMode>, 3> kValveModes = {
    {{ValveMode::Timing, "timing"}, {ValveMode::Pressure, "pressure"}, {ValveMode::Open, "open"}}};

template <class E>
const char* nameOf(std::span<const Choice<E>> choices, E value) {
  for (const Choice<E>& c : choices)
    if (c.value == value) return c.name;
  return "?";
}

// A combo box showing `value`'s name and offering `offered`; picking another value sets it and
// `changed`.
template <class E>
void choiceCombo(const char* label, std::span<const Choice<E>> named, std::span<const Choice<E>> offered,
                 E& value, bool& changed) {
  if (ImGui::BeginCombo(label, nameOf(named, value))) {
    for (const Choice<E>& c : offered)
      if (ImGui::Selectable(c.name, c.value == value) && c.value != value) {
        value = c.value;
        changed = true;
      }
    ImGui::EndCombo();
  }
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
  applyResolution(c.resolution, scenario);
  if (c.particlesEdited) scenario.blood.particles = c.particles;
  scenario.blood.start = c.start;
  scenario.circulation.twoWay = c.twoWay;
  scenario.circulation.valveMode = c.valveMode;
}

// The resolution list: each level with the count and spacing it gives.
void resolutionCombo(BloodControls& c, const ResolutionStatus& running, double spacing) {
  char item[96];
  const auto describe = [&](BloodResolution level) {
    std::snprintf(item, sizeof item, "%s: %s particles, %.2g mm apart", resolutionName(level),
                  withThousands(particlesAtLevel(level, running.level, running.particles)).c_str(),
                  1000 * spacing * resolutionSpacingScale(level) / resolutionSpacingScale(running.level));
    return item;
  };
  if (ImGui::BeginCombo("resolution", resolutionName(c.resolution))) {
    for (const ResolutionLevel& l : kResolutionLevels)
      if (ImGui::Selectable(describe(l.level), l.level == c.resolution) && l.level != c.resolution) {
        c.resolution = l.level;
        c.particlesEdited = false;  // the level's own count
        c.changed = true;
      }
    ImGui::EndCombo();
  }
  tooltip(
      "How finely the blood is divided into particles. Finer: smaller particles, more of them, closer "
      "flow detail, a slower simulation. 'fine' is the scenario as written; each level halves or "
      "doubles the count, the particles' size following so the heart stays full.\nAt start-up the viewer "
      "picks the finest level that holds real time on this computer. Restarts from t = 0.");
}

void drawBloodSection(BloodControls& c, const ResolutionStatus& resolution, bool hasHeart, bool lumped,
                      bool wallYields) {
  if (lumped) {
    ImGui::TextDisabled("cannot change EF or the pressures (?)");
    tooltip(
        "Here the circulation model moves the wall and computes the pressures; the wall does not feel "
        "the blood. These settings change how the blood moves and looks (its speed, the jets), not the "
        "ejection fraction, the volumes or the pressures.");
  }
  resolutionCombo(c, resolution, resolution.spacing);
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
      "Blood particles, each a small parcel of blood of a fixed size. More: a slower simulation.\nWhere "
      "the blood starts filling the heart and vessels, they hold a fixed number: more than that wait "
      "in the body outside the model and enter through the inflow, so the picture barely changes; "
      "fewer leave the heart part-empty. Applied on release, restarting from t = 0.");
  if (!hasHeart) return;
  const std::span<const Choice<Start>> starts(kStarts);
  choiceCombo("blood start", starts, starts.first(kOfferedStarts), c.start, c.changed);
  tooltip(
      "Where the blood is at t = 0: in the inflow vessel (it fills the ventricle through the mitral "
      "valve), already in the chamber, or filling the heart and both vessels (what the lumped "
      "circulation needs: it moves the wall from the first step). Restarts from t = 0.");
  if (wallYields) {
    if (ImGui::Checkbox("two-way coupling", &c.twoWay)) c.changed = true;
    tooltip(
        "On: the blood pushes the heart wall back (the wall feels the blood's pressure).\nOff: the wall "
        "moves the blood but does not feel it, as in the thesis. Restarts from t = 0.");
  } else {
    // The lumped circulation drives every wall vertex: the switch would move nothing (the
    // simulation refuses it).
    ImGui::TextDisabled("two-way coupling: nothing to push (?)");
    tooltip(
        "The circulation model moves the whole wall, so the blood has nothing it could push back. A heart "
        "with segments that do not beat (e.g. anterior-infarct) or a scenario without the circulation "
        "model (e.g. heart-only) offers it.");
  }
  if (lumped) {
    // The lumped circulation opens the valves on its own pressures (another mode is refused).
    ImGui::TextDisabled("valves: by the circulation model's pressures (?)");
    tooltip(
        "The circulation model opens each valve when the pressure before it is higher than after it, as "
        "real valves do, so the valve modes do not apply to this heart. A scenario without the "
        "circulation model (e.g. heart-only) offers them.");
    return;
  }
  const std::span<const Choice<ValveMode>> modes(kValveModes);
  choiceCombo("valves", modes, modes, c.valveMode, c.changed);
  tooltip(
      "When the valves open.\ntiming: the mitral valve in diastole, the aortic valve in systole (the "
      "thesis).\npressure: a valve opens while the pressure before it is higher than after it, as real "
      "valves do.\nopen: both always open, as if there were no valves.\nRestarts from t = 0.");
}

}  // namespace hs::viewer
