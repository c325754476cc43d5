// A lesson beside the heart, at the window sizes of a classroom's laptops: every step of every
// built-in lesson, in each of its stages (setting up, the question, playing, the result), drawn
// with the whole viewer's windows around it. The lesson covers the control panel and its whole
// text shows without scrolling; the status corner and the colour key, folded, cover none of the
// places the lessons name on the heart; no text is cut in any window (windowless_imgui.h); the
// names on the heart never lie on each other in any of the four views.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "cardiac/heart_simulation.h"
#include "io/scenario/scenario_file.h"
#include "render/scene.h"
#include "viewer/app/camera_controller.h"
#include "viewer/app/scene_labels.h"
#include "viewer/app/scene_overlays.h"
#include "viewer/app/scene_windows.h"
#include "viewer/app/simulation_runner.h"
#include "viewer/lessons/lesson.h"
#include "viewer/panels/circulation_panel.h"
#include "viewer/panels/help_window.h"
#include "viewer/panels/pump_panel.h"
#include "viewer/panels/ui_panel.h"
#include "viewer/plots/circulation_history.h"
#include "viewer/plots/panel_widgets.h"
#include "viewer/plots/plot_history.h"
#include "viewer/plots/run_comparison.h"
#include "lessons/beat_summary.h"
#include "windowless_imgui.h"

namespace hs::viewer {
namespace {

using testing::cutText;
using testing::joined;

using testing::completeBeat;

// The status of `normal` after `beats` beats, its figures an adult's, the phase's name at its
// longest, the pace behind and a rhythm that varies (so the rhythm lesson draws its beats' table).
ViewerStatus adultStatus(int beats) {
  ViewerStatus status;
  status.scenarioName = "heart-failure-preserved-ef";
  status.hasHeart = status.hasBlood = status.physiological = true;
  status.time = 12.345;
  status.phase = "isovolumic contraction";
  status.cavity = 120e-6;
  status.behind = true;
  status.realTimeFactor = 0.071;
  status.liquidNote = "liquid look: 1/3 resolution for 25 fps (76 ms a frame at 1/2); now 79 ms";
  status.circulation.lumped = true;
  cardiac::LumpedBeatFigures figures;
  figures.edv = 120e-6, figures.esv = 50e-6;
  figures.aorticSystolic = 123 * 133.322, figures.aorticDiastolic = 79 * 133.322;
  figures.lvPeak = 124 * 133.322, figures.lvEndDiastolic = 9 * 133.322;
  figures.forwardStrokeVolume = 70e-6;
  status.circulation.lastBeat = figures;
  status.pump.hasHeart = status.pump.hasBlood = status.pump.cycleOn = status.pump.lumped = true;
  status.pump.scale = volumeScaleFor(120e-6);
  status.pump.beats.beatsCompleted = beats;
  status.pump.beats.settled = true;
  for (int k = 0; k < beats; ++k)
    status.pump.beats.played.push_back(completeBeat(k + 1, 0.55 + 0.1 * (k % 5), 100 + 5 * (k % 5), 45));
  // The blood's flow components of the last beat (the pump panel's bar).
  cardiac::FlowComponents shares;
  shares.direct = 0.38, shares.retainedInflow = 0.16, shares.delayedEjection = 0.16, shares.residual = 0.30;
  shares.particles = 1000;
  status.pump.flowComponents = shares;
  status.pump.flowBeat = beats;
  return status;
}

// normal's heart framed in the scene as the viewer frames it, seen from `view`, and its names.
struct FramedHeart {
  std::vector<SceneLabel> labels;
  render::Camera camera;
};
FramedHeart framedHeart(render::View view, const SceneArea& area, int width, int height) {
  static const cardiac::HeartSimulation sim(io::loadScenario("normal"), 1);
  CameraController controller(render::sceneBounds(sim), float(width) / float(height));
  frameView(controller, view, area, width, height);
  return {anatomyLabels(sim), controller.camera()};
}

class LessonLayout : public ::testing::TestWithParam<std::pair<int, int>> {};

TEST_P(LessonLayout, EveryStepOfEveryLessonLeavesTheHeartInSightAndCutsNoText) {
  const auto [width, height] = GetParam();
  testing::WindowlessImGui imgui;
  const std::vector<ScenarioChoice> scenarios = builtinScenarioChoices();
  const SceneArea area{kPanelWidth, float(width) - kPumpPanelWidth, circulationPanelHeight(height)};
  // The places a lesson names: none under the status corner or the colour key.
  const FramedHeart heart = framedHeart(render::View::Front, area, width, height);
  for (const std::string& name : builtinLessonNames()) {
    LessonPlayer player(loadLesson(name), false);
    ViewerControls controls;
    controls.circulation.lumped = true;
    LessonRequests requests;
    PlotHistory history;
    CirculationHistory circulation;
    RunComparison runs;
    int beats = 3, shown = 0;
    std::map<std::pair<int, int>, bool> seen;  // (step, stage) drawn
    for (int frame = 0; frame < 2000 && !player.finished(); ++frame) {
      ViewerStatus status = adultStatus(beats);
      player.frame(requests, status, scenarios, controls);
      status.bloodColour = controls.bloodColour;  // the key follows the lesson's colour, as the app's

      const std::pair<int, int> moment{player.stepIndex(), int(player.stage())};
      if (!seen[moment]) {
        seen[moment] = true;
        ++shown;
        const std::string where = name + " step " + std::to_string(player.stepIndex() + 1) + " stage " +
                                  std::to_string(int(player.stage())) + " at " + std::to_string(width) + "x" +
                                  std::to_string(height);
        std::vector<render::LabelBox> overlays;
        imgui.frames(width, height, [&] {
          drawControlPanel(controls, status, scenarios, height);
          drawPumpPanel(controls.pump, status.pump, history, runs, width, height);
          drawCirculationPanel(status.circulation, circulation, kPanelWidth, area.right, height, {});
          LessonRequests ignored;
          overlays = drawSceneWindows(status, &player, ignored, area, height);
        });
        EXPECT_EQ(joined(cutText()), "") << where;
        const ImGuiWindow* lesson = ImGui::FindWindowByName("###lesson");
        ASSERT_NE(lesson, nullptr);
        EXPECT_EQ(lesson->Pos.x, 0.0f);
        EXPECT_LE(lesson->Size.x, kPanelWidth) << "over the control panel, not the scene";
        EXPECT_EQ(lesson->ScrollMax.y, 0.0f) << where << ": the whole step shows without scrolling";
        ASSERT_EQ(overlays.size(), 2u) << "the key and the status";
        for (const SceneLabel& label : heart.labels) {
          const ProjectedLabel p = projectLabel(label, heart.camera, width, height);
          for (const render::LabelBox& box : overlays)
            EXPECT_FALSE(p.x >= box.x && p.x <= box.right() && p.y >= box.y && p.y <= box.bottom())
                << where << ": " << label.text << " at (" << p.x << ", " << p.y << ") is covered";
        }
      }
      // The student: a wrong answer first (the longest marking), beats that come, then Next.
      if (player.stage() == StepStage::Predicting) requests.answer = player.step().predict->answer == 0 ? 1 : 0;
      if (player.stage() == StepStage::Playing) ++beats;
      if (player.stage() == StepStage::Done) requests.next = true;
    }
    EXPECT_TRUE(player.finished()) << name;
    EXPECT_GE(shown, 2 * player.stepCount()) << name << ": each step drawn at least set up and done";
  }
}

// Hidden, the lesson leaves the control panel free and waits behind a button in the scene.
TEST_P(LessonLayout, AHiddenLessonUncoversTheControlPanelAndComesBack) {
  const auto [width, height] = GetParam();
  testing::WindowlessImGui imgui;
  const std::vector<ScenarioChoice> scenarios = builtinScenarioChoices();
  const SceneArea area{kPanelWidth, float(width) - kPumpPanelWidth, circulationPanelHeight(height)};
  LessonPlayer player(loadLesson("rhythm"), false);
  ViewerControls controls;
  LessonRequests requests;
  const ViewerStatus status = adultStatus(3);
  player.frame(requests, status, scenarios, controls);
  requests.close = true;
  player.frame(requests, status, scenarios, controls);
  ASSERT_TRUE(player.closed());
  imgui.frames(width, height, [&] {
    drawControlPanel(controls, status, scenarios, height);
    drawSceneWindows(status, &player, requests, area, height);
  });
  const ImGuiWindow* lesson = ImGui::FindWindowByName("###lesson");
  EXPECT_TRUE(lesson == nullptr || !lesson->Active) << "hidden";
  const ImGuiWindow* button = ImGui::FindWindowByName("##lesson hidden");
  ASSERT_NE(button, nullptr);
  EXPECT_TRUE(button->Active);
  EXPECT_GE(button->Pos.x, area.left) << "in the scene, not over the panel";
  EXPECT_EQ(joined(cutText()), "");
  requests.reopen = true;
  player.frame(requests, status, scenarios, controls);
  EXPECT_FALSE(player.closed());
}

// The anatomy's names in the four views, laid out as the viewer lays them out beside the status
// corner and the colour key: no two boxes overlap, and none lies on a window.
TEST_P(LessonLayout, TheNamesNeverLieOnEachOtherInAnyView) {
  const auto [width, height] = GetParam();
  testing::WindowlessImGui imgui;
  const SceneArea area{kPanelWidth, float(width) - kPumpPanelWidth, circulationPanelHeight(height)};
  std::vector<render::LabelBox> overlays;
  imgui.frames(width, height, [&] {
    LessonRequests none;
    overlays = drawSceneWindows(adultStatus(3), nullptr, none, area, height);
  });
  for (const render::View view : render::kAllViews) {
    const FramedHeart heart = framedHeart(view, area, width, height);
    const render::LabelBox bounds{area.left, 0, area.right - area.left, float(height) - area.strip};
    const std::vector<render::PlacedLabel> placed =
        render::layoutLabels(heart.labels, labelTextSizes(heart.labels), heart.camera, width, height, bounds,
                             kLabelSpacing, overlays);
    EXPECT_GE(placed.size(), heart.labels.size() - 1) << render::viewName(view);
    for (std::size_t i = 0; i < placed.size(); ++i) {
      for (std::size_t j = i + 1; j < placed.size(); ++j)
        EXPECT_FALSE(placed[i].box.overlaps(placed[j].box))
            << render::viewName(view) << ": " << heart.labels[placed[i].label].text << " / "
            << heart.labels[placed[j].label].text;
      for (const render::LabelBox& window : overlays)
        EXPECT_FALSE(placed[i].box.overlaps(window)) << render::viewName(view) << ": "
                                                     << heart.labels[placed[i].label].text << " under a window";
    }
  }
}

TEST_P(LessonLayout, EveryHelpPageShowsWhole) {
  const auto [width, height] = GetParam();
  testing::WindowlessImGui imgui;
  for (int page = 0; page < kHelpPageCount; ++page) {
    bool open = true;
    int shown = page;
    imgui.frames(width, height, [&] { drawHelpWindow(open, shown, width, height); });
    EXPECT_EQ(joined(cutText()), "") << "page " << page << " at " << width << "x" << height;
  }
}

// A tooltip over an item at the screen's right edge, its text longer than the room beside it:
// wrapped, it lies inside the screen, its whole text shown.
TEST_P(LessonLayout, ATooltipAtTheRightEdgeShowsWhole) {
  const auto [width, height] = GetParam();
  testing::WindowlessImGui imgui;
  ImGui::GetIO().MousePos = ImVec2(float(width) - 20, 40);
  imgui.frames(width, height, [&] {
    ImGui::SetNextWindowPos(ImVec2(float(width) - kPumpPanelWidth, 0));
    ImGui::SetNextWindowSize(ImVec2(kPumpPanelWidth, 200));
    ImGui::Begin("edge", nullptr, ImGuiWindowFlags_NoDecoration);
    ImGui::Button("hover me", ImVec2(-1, 60));
    tooltip("The last beat of the run before the restart, laid under each beat of this run from its start; "
            "a second sentence as long again, so that no screen holds the line unwrapped beside the item at "
            "the edge where the pump panel stands, and a third to be sure of it.");
    ImGui::End();
  });
  bool tooltipShown = false;
  for (const ImGuiWindow* w : GImGui->Windows) tooltipShown |= w->Active && (w->Flags & ImGuiWindowFlags_Tooltip);
  EXPECT_TRUE(tooltipShown);
  EXPECT_EQ(joined(cutText()), "");
}

INSTANTIATE_TEST_SUITE_P(ClassroomScreens, LessonLayout,
                         ::testing::Values(std::pair{1280, 800}, std::pair{1366, 768}),
                         [](const auto& param) {
                           return std::to_string(param.param.first) + "x" + std::to_string(param.param.second);
                         });

}  // namespace
}  // namespace hs::viewer
