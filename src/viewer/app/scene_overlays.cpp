#include "viewer/app/scene_overlays.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace hs::viewer {
namespace {

constexpr ImU32 kInk = IM_COL32(30, 30, 40, 255);
constexpr ImU32 kPaper = IM_COL32(255, 255, 255, 215);
constexpr ImU32 kArrow = IM_COL32(255, 255, 255, 255);

void arrow(ImDrawList& draw, ImVec2 from, ImVec2 to) {
  const float dx = to.x - from.x, dy = to.y - from.y, length = std::hypot(dx, dy);
  if (length < 4) return;
  const float ux = dx / length, uy = dy / length, head = std::min(14.0f, 0.5f * length);
  const ImVec2 base(to.x - head * ux, to.y - head * uy);
  const ImVec2 left(base.x + 0.55f * head * uy, base.y - 0.55f * head * ux);
  const ImVec2 right(base.x - 0.55f * head * uy, base.y + 0.55f * head * ux);
  // White with a dark rim: visible over blood of any colour and over the wall.
  for (const auto& [colour, width] : {std::pair{kInk, 7.0f}, std::pair{kArrow, 3.5f}}) {
    draw.AddLine(from, base, colour, width);
    draw.AddTriangleFilled(to, left, right, colour);
    if (colour == kInk) draw.AddTriangle(to, left, right, colour, 3);
  }
}

}  // namespace

void drawSceneLabels(const std::vector<SceneLabel>& labels, const render::Camera& camera, int width, int height,
                     const SceneArea& area, const std::vector<render::LabelBox>& avoid) {
  ImDrawList& draw = *ImGui::GetBackgroundDrawList();
  const float bottom = float(height) - area.strip;
  draw.PushClipRect(ImVec2(area.left, 0), ImVec2(area.right, bottom));
  constexpr float kEdge = 9;  // px: the names' boxes stay clear of the windows beside the scene
  const render::LabelBox bounds{area.left + kEdge, 0, area.right - area.left - 2 * kEdge, bottom};
  for (const render::PlacedLabel& placed :
       render::layoutLabels(labels, labelTextSizes(labels), camera, width, height, bounds, kLabelSpacing, avoid)) {
    const ProjectedLabel& p = placed.at;
    if (p.hasArrow) arrow(draw, ImVec2(p.arrowFromX, p.arrowFromY), ImVec2(p.arrowToX, p.arrowToY));
    const render::LabelBox& box = placed.box;
    draw.AddLine(ImVec2(p.x, p.y), ImVec2(placed.leaderX, placed.leaderY), kInk, 1.5f);
    draw.AddCircleFilled(ImVec2(p.x, p.y), 3, kInk);
    draw.AddRectFilled(ImVec2(box.x, box.y), ImVec2(box.right(), box.bottom()), kPaper, 3);
    draw.AddText(ImVec2(box.x + kLabelSpacing.pad, box.y + kLabelSpacing.pad), kInk, labels[placed.label].text.c_str());
  }
  draw.PopClipRect();
}

std::vector<std::pair<float, float>> labelTextSizes(const std::vector<SceneLabel>& labels) {
  std::vector<std::pair<float, float>> sizes;
  for (const SceneLabel& label : labels) {
    const ImVec2 size = ImGui::CalcTextSize(label.text.c_str());
    sizes.emplace_back(size.x, size.y);
  }
  return sizes;
}

void drawToasts(const std::vector<Toast>& toasts, const SceneArea& area) {
  constexpr float kMargin = 10;
  const float width = std::min(560.0f, area.right - area.left - 2 * kMargin);
  float top = kMargin;
  // Newest on top: drawn from the newest down.
  for (std::size_t k = toasts.size(); k-- > 0;) {
    const Toast& toast = toasts[k];
    ImGui::SetNextWindowPos(ImVec2((area.left + area.right) / 2, top), ImGuiCond_Always, ImVec2(0.5f, 0));
    ImGui::SetNextWindowSize(ImVec2(width, 0), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.95f);
    const bool warning = toast.kind == ToastKind::Warning;
    ImGui::PushStyleColor(ImGuiCol_WindowBg, warning ? ImVec4(1.0f, 0.93f, 0.82f, 1) : ImVec4(0.93f, 0.96f, 1, 1));
    ImGui::PushStyleColor(ImGuiCol_Border, warning ? ImVec4(0.8f, 0.4f, 0.05f, 1) : ImVec4(0.3f, 0.45f, 0.75f, 1));
    const std::string id = "##toast" + std::to_string(k);
    ImGui::Begin(id.c_str(), nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs);
    ImGui::TextWrapped("%s", toast.text.c_str());
    top = ImGui::GetWindowPos().y + ImGui::GetWindowSize().y + 6;
    ImGui::End();
    ImGui::PopStyleColor(2);
  }
}

}  // namespace hs::viewer
