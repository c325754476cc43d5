#include "viewer/panels/circulation_controls.h"

#include <imgui.h>

#include "cardiac/circulation/clinical_units.h"
#include "viewer/plots/panel_widgets.h"

namespace hs::viewer {
namespace {

constexpr const char* kRestartNote =
    "\nApplied when you release the slider: the simulation restarts from t = 0 with it (the model "
    "fixes its circulation when it starts); the loop settles within two or three beats.";

// A slider over a clinical range that asks for a restart when released after an edit.
void restartSlider(const char* label, double& value, CirculationRange range, const char* format,
                   bool logarithmic, bool& changed, const std::string& tip) {
  ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &range.lo, &range.hi, format,
                      logarithmic ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None);
  if (ImGui::IsItemDeactivatedAfterEdit()) changed = true;
  tooltip(tip + kRestartNote);
}

}  // namespace

CirculationControls circulationControlsFrom(const cardiac::Scenario& scenario) {
  const cardiac::CirculationSettings& c = scenario.circulation;
  const cardiac::LumpedParameters& p = c.lumpedParameters;
  CirculationControls controls;
  controls.lumped = scenario.heart && c.lumped;
  controls.atrialPressureMmHg = double(c.atrialPressureMmHg);
  controls.resistance = cardiac::resistanceToClinical(p.peripheralResistance);
  controls.compliance = cardiac::complianceToClinical(p.arterialCompliance);
  controls.contractility = cardiac::elastanceToClinical(p.contractility);
  return controls;
}

void applyCirculationControls(const CirculationControls& controls, cardiac::Scenario& scenario) {
  const CirculationControls own = circulationControlsFrom(scenario);
  cardiac::CirculationSettings& c = scenario.circulation;
  cardiac::LumpedParameters& p = c.lumpedParameters;
  if (controls.atrialPressureMmHg != own.atrialPressureMmHg)
    c.atrialPressureMmHg = cardiac::Real(controls.atrialPressureMmHg);
  if (controls.resistance != own.resistance)
    p.peripheralResistance = cardiac::resistanceFromClinical(controls.resistance);
  if (controls.compliance != own.compliance)
    p.arterialCompliance = cardiac::complianceFromClinical(controls.compliance);
  if (controls.contractility != own.contractility)
    p.contractility = cardiac::elastanceFromClinical(controls.contractility);
}

void drawCirculationSection(CirculationControls& c, float& heartRateBpm, bool& heartRateChanged,
                            bool& showFigures) {
  ImGui::Checkbox("PV loop and Wiggers (C)", &showFigures);
  tooltip("Show the pressure-volume loop and the Wiggers diagram of the last beat under the heart (C)");
  restartSlider("preload", c.atrialPressureMmHg, kAtrialPressureRange, "%.1f mmHg", false, c.changed,
                "Preload: the filling pressure of the pulmonary veins and left atrium, which stretches the "
                "ventricle before it contracts (circulation.atrial_pressure_mmhg).\n"
                "Higher: a fuller ventricle (larger EDV, the loop's right side moves right along the EDPVR) "
                "and a larger stroke volume: the Frank-Starling law. Normal about 5 to 12 mmHg; above about "
                "18 mmHg fluid backs up into the lungs.");
  restartSlider("resistance", c.resistance, kResistanceRange, "%.2f mmHg s/mL", true, c.changed,
                "Afterload: the systemic vascular resistance the ventricle ejects against "
                "(circulation.peripheral_resistance_mmhg_s_per_ml).\n"
                "Higher (hypertension, vasoconstriction): a higher aortic pressure, the loop's top rises and "
                "meets the ESPVR at a larger end-systolic volume, so the stroke volume falls. Lower (sepsis, "
                "exercise): the opposite. Normal about 1 mmHg s/mL.");
  restartSlider("compliance", c.compliance, kComplianceRange, "%.2f mL/mmHg", true, c.changed,
                "Afterload: how much the aorta and large arteries stretch per mmHg "
                "(circulation.arterial_compliance_ml_per_mmhg).\n"
                "Lower (stiff arteries with age, arteriosclerosis): each stroke raises the pressure more, "
                "so the pulse pressure (systolic - diastolic) widens. Normal about 1 to 2 mL/mmHg.");
  restartSlider(
      "contractility", c.contractility, kContractilityRange, "%.2f mmHg/mL", true, c.changed,
      "Contractility (inotropy): the end-systolic elastance Ees, the slope of the ESPVR line "
      "(circulation.contractility_mmhg_per_ml).\n"
      "Higher (adrenaline, dobutamine): a steeper line, a smaller end-systolic volume, a larger stroke "
      "volume and ejection fraction. Lower (heart failure, infarction): the loop shifts right and "
      "narrows. Normal about 2 to 3 mmHg/mL.");
  ImGui::SliderFloat("heart rate##lumped", &heartRateBpm, kLumpedHeartRateMin, kLumpedHeartRateMax,
                     "%.0f bpm");
  if (ImGui::IsItemDeactivatedAfterEdit()) heartRateChanged = true;
  tooltip(std::string(
              "Heart rate (cycle.heart_rate_bpm). Faster: diastole shortens far more than systole (the "
              "ejection time follows LVET = 413 - 1.7 HR ms, Weissler 1968), so the ventricle fills less: "
              "EDV and stroke volume fall while the cardiac output first rises. Normal at rest 60 to "
              "100 bpm.") +
          kRestartNote);
  if (ImGui::SmallButton("scenario values")) c.defaultsRequested = true;
  tooltip(
      "Back to the scenario's own preload, afterload, contractility and heart rate (restarts from t = 0)");
}

}  // namespace hs::viewer
