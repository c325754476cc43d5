#include "viewer/panels/circulation_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cardiac/circulation/clinical_units.h"
#include "viewer/plots/panel_widgets.h"
#include "viewer/plots/pv_loop_panel.h"
#include "viewer/plots/wiggers_panel.h"

namespace hs::viewer {
namespace {

using cardiac::kCubicMetresPerMl;
using cardiac::kPascalPerMmHg;

// One line of what a clinician reads off the last beat, from the lumped model's own figures.
void beatReadout(const CirculationStatus& s) {
  if (!s.lastBeat) {
    ImGui::TextDisabled("Circulation: waiting for the first complete beat");
    return;
  }
  const cardiac::LumpedBeatFigures& b = *s.lastBeat;
  const double ef = b.edv > 0 ? 100 * b.totalStrokeVolume() / b.edv : 0;
  // SV as the pump panel and the lessons give it (EDV - ESV); with a leaking valve the forward
  // part beside it.
  const double sv = b.totalStrokeVolume() / kCubicMetresPerMl, forward = b.forwardStrokeVolume / kCubicMetresPerMl;
  ImGui::Text("Last beat:  BP %.0f/%.0f mmHg   LVEDP %.0f mmHg   SV %.0f mL   EF %.0f%%",
              b.aorticSystolic / kPascalPerMmHg, b.aorticDiastolic / kPascalPerMmHg,
              b.lvEndDiastolic / kPascalPerMmHg, sv, ef);
  if (std::lround(forward) != std::lround(sv)) {
    ImGui::SameLine();
    ImGui::TextDisabled("(forward %.0f mL)", forward);
  }
  tooltip(
      "The last complete beat of the lumped circulation:\n"
      "BP: aortic systolic / diastolic pressure (normal about 120/80 mmHg);\n"
      "LVEDP: the ventricle's end-diastolic pressure (normal 4 to 12 mmHg);\n"
      "SV: the stroke volume, EDV - ESV (normal about 70 mL); with a leaking valve the part ejected\n"
      "forward through the aortic valve is given beside it;\n"
      "EF: (EDV - ESV) / EDV (normal 55 to 70 %).\n"
      "The right panel reads the 3D heart's cavity, which follows this model's volume.");
}

}  // namespace

float circulationPanelHeight(int windowHeight) {
  return std::clamp(0.4f * float(windowHeight), std::min(240.0f, float(windowHeight) / 2), 460.0f);
}

void drawCirculationPanel(const CirculationStatus& status, const CirculationHistory& history, float left,
                          float right, int windowHeight,
                          std::span<const cardiac::CirculationSample> previousLoop) {
  if (!status.lumped) return;
  const float height = circulationPanelHeight(windowHeight);
  ImGui::SetNextWindowPos(ImVec2(left, float(windowHeight) - height), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(right - left, height), ImGuiCond_Always);
  ImGui::Begin("circulation", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar |
                   ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoSavedSettings);
  beatReadout(status);
  ImGui::Separator();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  // The loop about square (its axes in mL and mmHg are not alike, but a square reads as the
  // textbook's figure); the Wiggers diagram takes the rest of the width.
  constexpr float kGap = 18;
  const float loopWidth = std::min(avail.y * 1.1f, 0.45f * (avail.x - kGap));
  drawPressureVolumeLoop(history, status.relations, ImVec2(loopWidth, avail.y), previousLoop);
  ImGui::SameLine(0, kGap);
  drawWiggersDiagram(history, ImVec2(avail.x - loopWidth - kGap, avail.y));
  ImGui::End();
}

}  // namespace hs::viewer
