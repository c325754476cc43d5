#include "viewer/region/region_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "render/scene.h"
#include "viewer/plots/panel_widgets.h"
#include "viewer/region/aha_bullseye.h"

namespace hs::viewer {
namespace {

constexpr float kRadians = float(M_PI) / 180.0f;

ImU32 colour(const render::Vec3f& c, float alpha = 1) {
  return ImGui::GetColorU32(ImVec4(c.x(), c.y(), c.z(), alpha));
}

// The fill of a segment: the heart's beating orange when chosen completely, half of it when
// painted in part, near white when resting; a little darker under the mouse.
ImU32 segmentFill(SegmentState state, bool hovered) {
  const render::Vec3f chosen = render::beatingColour(render::regionColour(cardiac::Region::Myocardium));
  const render::Vec3f rest(0.96f, 0.95f, 0.94f);
  render::Vec3f c = state == SegmentState::Full      ? chosen
                    : state == SegmentState::Partial ? (chosen + rest) / 2
                                                     : rest;
  if (hovered) c *= 0.85f;
  return colour(c);
}

const char* stateText(SegmentState state) {
  switch (state) {
    case SegmentState::Full:
      return "beats";
    case SegmentState::Partial:
      return "beats in part (painted)";
    case SegmentState::None:
      return "rests";
  }
  return "";
}

// The text centred on (x, y).
void centredText(ImDrawList* draw, float x, float y, ImU32 col, const char* text) {
  const ImVec2 size = ImGui::CalcTextSize(text);
  draw->AddText(ImVec2(std::round(x - size.x / 2), std::round(y - size.y / 2)), col, text);
}

}  // namespace

void drawBullseye(RegionControls& controls, const RegionStatus& status, float diameter) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float lineHeight = ImGui::GetTextLineHeight();
  const float side = ImGui::CalcTextSize("lateral").x + 12;  // room for the side labels
  const float width = diameter + 2 * side;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float indent = std::max(0.0f, (ImGui::GetContentRegionAvail().x - width) / 2);
  const float radius = diameter / 2;
  const float cx = origin.x + indent + side + radius, cy = origin.y + lineHeight + 2 + radius;
  const auto at = [&](float r, float degrees) {
    return ImVec2(cx + r * radius * std::cos(degrees * kRadians),
                  cy - r * radius * std::sin(degrees * kRadians));
  };

  // Which segment the mouse is over, in diagram coordinates (y up, outer radius 1).
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  ImGui::SetCursorScreenPos(ImVec2(cx - radius, cy - radius));
  ImGui::InvisibleButton("bullseye", ImVec2(diameter, diameter));
  const int hovered =
      ImGui::IsItemHovered() ? bullseyeSegmentAt((mouse.x - cx) / radius, (cy - mouse.y) / radius) : 0;
  if (hovered > 0 && ImGui::IsItemClicked(ImGuiMouseButton_Left)) controls.segmentToggled = hovered;

  for (int s = 1; s <= 17; ++s) {
    const ImU32 fill = segmentFill(status.segments[std::size_t(s)], s == hovered);
    const BullseyeSector sector = bullseyeSector(s);
    if (s == 17) {
      draw->AddCircleFilled(ImVec2(cx, cy), sector.outerRadius * radius, fill, 48);
      continue;
    }
    // Convex quads of at most 5 degrees fill the ring sector.
    const int steps = int(std::ceil((sector.endDeg - sector.startDeg) / 5));
    for (int i = 0; i < steps; ++i) {
      const float a0 = sector.startDeg + (sector.endDeg - sector.startDeg) * float(i) / float(steps);
      const float a1 = sector.startDeg + (sector.endDeg - sector.startDeg) * float(i + 1) / float(steps);
      draw->AddQuadFilled(at(sector.innerRadius, a0), at(sector.outerRadius, a0), at(sector.outerRadius, a1),
                          at(sector.innerRadius, a1), fill);
    }
  }
  // Outlines: the four ring circles, the 60-degree borders of the basal and mid rings (0, 60,
  // ..., 300: the 2/3 and 5/6 borders are horizontal) and the 45-degree diagonals of the apical.
  const ImU32 ink = IM_COL32(70, 60, 60, 255);
  for (const float r : {kBullseyeApexRadius, kBullseyeApicalRadius, kBullseyeMidRadius, 1.0f})
    draw->AddCircle(ImVec2(cx, cy), r * radius, ink, 64, 1.2f);
  for (int k = 0; k < 6; ++k)
    draw->AddLine(at(kBullseyeApicalRadius, 60.0f * float(k)), at(1, 60.0f * float(k)), ink, 1.2f);
  for (int k = 0; k < 4; ++k)
    draw->AddLine(at(kBullseyeApexRadius, 45.0f + 90.0f * float(k)),
                  at(kBullseyeApicalRadius, 45.0f + 90.0f * float(k)), ink, 1.2f);
  // Segments beating out of step: a thick violet border, the colour they have on the heart.
  const ImU32 violet = colour(render::outOfStepColour(render::regionColour(cardiac::Region::Myocardium)));
  for (int s = 1; s <= 17; ++s) {
    if (!status.outOfStep[std::size_t(s)]) continue;
    const BullseyeSector sector = bullseyeSector(s);
    if (s == 17) {
      draw->AddCircle(ImVec2(cx, cy), sector.outerRadius * radius - 2, violet, 48, 4);
      continue;
    }
    draw->PathClear();
    const int steps = int(std::ceil((sector.endDeg - sector.startDeg) / 5));
    const float in = sector.innerRadius + 0.03f, out = sector.outerRadius - 0.03f;
    for (int i = 0; i <= steps; ++i)
      draw->PathLineTo(at(out, sector.startDeg + (sector.endDeg - sector.startDeg) * float(i) / float(steps)));
    for (int i = steps; i >= 0; --i)
      draw->PathLineTo(at(in, sector.startDeg + (sector.endDeg - sector.startDeg) * float(i) / float(steps)));
    draw->PathStroke(violet, ImDrawFlags_Closed, 4);
  }
  for (int s = 1; s <= 17; ++s) {
    float x = 0, y = 0;
    bullseyeLabelPosition(s, x, y);
    centredText(draw, cx + x * radius, cy - y * radius, IM_COL32(30, 25, 25, 255), std::to_string(s).c_str());
  }
  // The walls around it, as in the standard diagram.
  const ImU32 label = ImGui::GetColorU32(ImGuiCol_TextDisabled);
  centredText(draw, cx, cy - radius - lineHeight / 2 - 1, label, "anterior");
  centredText(draw, cx, cy + radius + lineHeight / 2 + 1, label, "inferior");
  centredText(draw, cx - radius - side / 2, cy, label, "septal");
  centredText(draw, cx + radius + side / 2, cy, label, "lateral");

  if (hovered > 0) {
    const SegmentState state = status.segments[std::size_t(hovered)];
    const std::string text = ahaSegmentName(hovered) + ": " + stateText(state) +
                             (status.outOfStep[std::size_t(hovered)] ? ", out of step with the rest" : "") +
                             "\nclick to " + (state == SegmentState::Full ? "let it rest" : "make it beat");
    wrappedTooltip(text.c_str());
  }
  ImGui::SetCursorScreenPos(origin);
  ImGui::Dummy(ImVec2(ImGui::GetContentRegionAvail().x, diameter + 2 * lineHeight + 4));
}

void drawRegionSection(RegionControls& c, const RegionStatus& s) {
  drawBullseye(c, s, kBullseyeDiameter);
  if (std::find(s.outOfStep.begin(), s.outOfStep.end(), true) != s.outOfStep.end()) {
    const render::Vec3f v = render::outOfStepColour(render::regionColour(cardiac::Region::Myocardium));
    ImGui::TextColored(ImVec4(v.x(), v.y(), v.z(), 1), "violet: beats out of step");
    tooltip("These segments beat at their own rate and phase (the inconsistent pattern); they are "
            "violet on the heart too");
  }
  ImGui::Text("%zu of %zu wall vertices beat", s.count, s.selectable);
  tooltip(
      "Vertices of the myocardium chosen to contract in systole (thesis 4.3.3); the base plate and "
      "the vessels never beat");
  if (!s.cycleEnabled) ImGui::TextColored(ImVec4(0.6f, 0.4f, 0.1f, 1), "cardiac cycle off: nothing beats");

  ImGui::Checkbox("paint (B)", &c.paintMode);
  tooltip(
      "Left drag on the heart adds the wall under the brush; Shift + left drag removes it. "
      "While painting, the left button does not orbit: pan with the right button, or leave paint mode");
  ImGui::SameLine();
  ImGui::Checkbox("show on heart", &c.showRegion);
  tooltip("Draw the chosen region orange on the heart, the blood see-through so that it shows");
  char radius[64];
  if (s.brushWorldRadius >= 0.1)
    std::snprintf(radius, sizeof radius, "%%.0f px = %.2f m", s.brushWorldRadius);
  else
    std::snprintf(radius, sizeof radius, "%%.0f px = %.0f mm", s.brushWorldRadius * 1000);
  ImGui::SliderFloat("brush", &c.brushRadiusPx, RegionControls::kMinBrushPx, RegionControls::kMaxBrushPx,
                     radius, ImGuiSliderFlags_Logarithmic);
  tooltip(
      "Brush radius in window pixels ([ and ] change it); the length is at the depth of the heart's centre");

  if (ImGui::Button("All myocardium")) c.allRequested = true;
  tooltip("Choose the whole myocardium (all 17 segments)");
  ImGui::SameLine();
  if (ImGui::Button("Clear")) c.clearRequested = true;
  tooltip("Choose nothing; paint or tick segments to start again");
  ImGui::SameLine();
  ImGui::BeginDisabled(!s.pending);
  if (ImGui::Button("Revert")) c.revertRequested = true;
  tooltip("Back to the region the simulation runs with");
  ImGui::EndDisabled();

  ImGui::BeginDisabled(!s.pending || s.count == 0);
  if (ImGui::Button("Apply (Enter)", ImVec2(120, 0))) c.applyRequested = true;
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    wrappedTooltip(s.count == 0 ? "Choose at least one segment or paint a region first; to stop the "
                                           "beat altogether untick 'cardiac cycle'"
                                         : "Restart the simulation from t = 0 with this region beating");
  if (s.pending) {
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(0.85f, 0.45f, 0.05f, 1), "not applied yet");
  }
}

void drawBrushOutline(const RegionControls& controls) {
  const ImGuiIO& io = ImGui::GetIO();
  if (!controls.paintMode || io.WantCaptureMouse) return;
  const float r = controls.brushRadiusPx;
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  draw->AddCircle(io.MousePos, r, IM_COL32(30, 30, 30, 200), 48, 3.0f);
  draw->AddCircle(io.MousePos, r, io.KeyShift ? IM_COL32(90, 170, 255, 255) : IM_COL32(255, 170, 40, 255), 48,
                  1.5f);
}

}  // namespace hs::viewer
