// The panel at the window sizes of a classroom's laptops: with any one of its folding sections
// open, every control of the control panel lies inside the window without scrolling, and the
// toasts stay inside the scene. The panels are drawn in an ImGui context without a window
// (ImGui lays out without rendering), so this checks the layout itself, not a picture of it.
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <string>

#include "viewer/app/scene_overlays.h"
#include "viewer/app/simulation_runner.h"
#include "viewer/panels/pump_panel.h"
#include "viewer/panels/ui_panel.h"
#include "viewer/plots/run_comparison.h"
#include "windowless_imgui.h"

namespace hs::viewer {
namespace {

class PanelLayout : public ::testing::TestWithParam<std::pair<int, int>> {
 protected:
  // A few frames (ImGui sizes windows from the frame before) of `draw`.
  template <typename Draw>
  void frames(int width, int height, Draw draw) {
    m_imgui.frames(width, height, draw);
  }

 private:
  testing::WindowlessImGui m_imgui;
};

// The status of the richest scenario: a heart with blood and the lumped circulation.
ViewerStatus richStatus() {
  ViewerStatus status;
  status.scenarioName = "normal";
  status.hasHeart = status.hasBlood = true;
  status.physiological = true;
  status.circulation.lumped = true;
  status.behind = true;  // the speed line shows
  status.realTimeFactor = 0.21;
  // The blood's resolution line at its longest: wrapped over two lines.
  status.resolution.level = kScenarioResolution;
  status.resolution.particles = 16800;
  status.resolution.fixedBy = "as my-own-heart-scenario.toml sets it";
  status.heartSize = 0.032f;
  status.region.outOfStep[7] = true;  // the out-of-step line shows
  status.region.pending = true;       // "not applied yet" shows
  return status;
}

TEST_P(PanelLayout, EveryControlIsInsideTheWindowWithAnySectionOpen) {
  const auto [width, height] = GetParam();
  const std::vector<ScenarioChoice> scenarios = builtinScenarioChoices();
  for (const PanelSection open : {PanelSection::None, PanelSection::Circulation, PanelSection::Blood,
                                  PanelSection::Region, PanelSection::Display}) {
    ViewerControls controls;
    controls.circulation.lumped = true;
    controls.openSection = open;
    const ViewerStatus status = richStatus();
    frames(width, height, [&] { drawControlPanel(controls, status, scenarios, height); });
    EXPECT_EQ(controls.openSection, open) << "drawing alone opens or closes nothing";
    const ImGuiWindow* panel = ImGui::FindWindowByName("heartsim");
    ASSERT_NE(panel, nullptr);
    EXPECT_LE(panel->Pos.y + panel->Size.y, float(height));
    // Content bottom (the last control's lower edge, with the window's padding) within it:
    // nothing needs the scroll bar.
    EXPECT_EQ(panel->ScrollMax.y, 0.0f) << "section " << int(open) << " at " << width << "x" << height;
    EXPECT_LE(panel->ContentSize.y + 2 * panel->WindowPadding.y, panel->Size.y)
        << "section " << int(open) << " at " << width << "x" << height;
  }
}

TEST_P(PanelLayout, ThePumpPanelFitsWithoutScrolling) {
  const auto [width, height] = GetParam();
  PumpStatus status;
  status.hasHeart = status.hasBlood = status.cycleOn = status.lumped = true;
  status.scale = volumeScaleFor(120e-6);  // a human-size heart
  PumpControls controls;
  const PlotHistory history;
  const RunComparison runs;
  frames(width, height, [&] { drawPumpPanel(controls, status, history, runs, width, height); });
  const ImGuiWindow* panel = ImGui::FindWindowByName("pump");
  ASSERT_NE(panel, nullptr);
  EXPECT_GE(panel->Pos.x, 0.0f);
  EXPECT_LE(panel->Pos.x + panel->Size.x, float(width));
  EXPECT_LE(panel->Pos.y + panel->Size.y, float(height));
  EXPECT_EQ(panel->ScrollMax.y, 0.0f) << width << "x" << height;
  EXPECT_LE(panel->ContentSize.y + 2 * panel->WindowPadding.y, panel->Size.y) << width << "x" << height;
}

TEST_P(PanelLayout, ToastsStayInsideTheScene) {
  const auto [width, height] = GetParam();
  const SceneArea area{kPanelWidth, float(width) - 340.0f, 0.4f * float(height)};
  std::vector<Toast> toasts;
  for (int i = 0; i < 3; ++i)
    toasts.push_back({"picture saved: /home/student/lectures/cardiology/week 3/heartsim_normal_00" +
                          std::to_string(i) + ".png (a long path that needs wrapping to fit)",
                      ToastKind::Info, 0, 10});
  frames(width, height, [&] { drawToasts(toasts, area); });
  for (int i = 0; i < 3; ++i) {
    const ImGuiWindow* toast = ImGui::FindWindowByName(("##toast" + std::to_string(i)).c_str());
    ASSERT_NE(toast, nullptr);
    EXPECT_GE(toast->Pos.x, area.left);
    EXPECT_LE(toast->Pos.x + toast->Size.x, area.right);
    EXPECT_GE(toast->Pos.y, 0);
    EXPECT_LE(toast->Pos.y + toast->Size.y, float(height) - area.strip);
    EXPECT_EQ(toast->ScrollMax.y, 0.0f) << "the whole message is shown";
  }
}

INSTANTIATE_TEST_SUITE_P(ClassroomScreens, PanelLayout,
                         ::testing::Values(std::pair{1280, 800}, std::pair{1366, 768}),
                         [](const auto& param) {
                           return std::to_string(param.param.first) + "x" + std::to_string(param.param.second);
                         });

}  // namespace
}  // namespace hs::viewer
