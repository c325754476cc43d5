#include "viewer/plots/panel_widgets.h"

#include <imgui.h>

namespace hs::viewer {

void wrappedTooltip(const char* text) {
  ImGui::BeginTooltip();
  ImGui::PushTextWrapPos(kTooltipWidth);
  ImGui::TextUnformatted(text);
  ImGui::PopTextWrapPos();
  ImGui::EndTooltip();
}

void tooltip(const char* text) {
  if (ImGui::IsItemHovered()) wrappedTooltip(text);
}

void tooltip(const std::string& text) { tooltip(text.c_str()); }

void beginSidePanel(const char* id, const char* title, float left, float width, int windowHeight) {
  ImGui::SetNextWindowPos(ImVec2(left, 0), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(width, float(windowHeight)), ImGuiCond_Always);
  ImGui::Begin(id, nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoTitleBar);
  ImGui::PushItemWidth(-90);
  ImGui::TextUnformatted(title);
  ImGui::Separator();
}

void endSidePanel() {
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace hs::viewer
