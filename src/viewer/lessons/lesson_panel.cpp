#include "viewer/lessons/lesson_panel.h"

#include <imgui.h>

#include <algorithm>
#include <string>

#include "viewer/plots/panel_widgets.h"

namespace hs::viewer {
namespace {

const ImVec4 kTitleColour(0.98f, 0.78f, 0.35f, 1);
const ImVec4 kRightColour(0.45f, 0.9f, 0.45f, 1);
const ImVec4 kWrongColour(1.0f, 0.45f, 0.4f, 1);
const ImVec4 kResultBackground(0.2f, 0.32f, 0.5f, 0.9f);

// Wrapped at the window's edge; TextUnformatted has no length limit (Text's buffer has).
void wrapped(const std::string& text) {
  ImGui::PushTextWrapPos(0);
  ImGui::TextUnformatted(text.c_str());
  ImGui::PopTextWrapPos();
}

void wrappedColoured(const ImVec4& colour, const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  wrapped(text);
  ImGui::PopStyleColor();
}

// The choices as buttons the width of the window.
void predictionButtons(const LessonPredict& predict, LessonRequests& requests) {
  wrappedColoured(kTitleColour, "Predict: " + predict.question);
  ImGui::Spacing();
  for (int i = 0; i < int(predict.choices.size()); ++i) {
    const std::string label = std::to_string(i + 1) + ". " + predict.choices[std::size_t(i)];
    if (ImGui::Button(label.c_str(), ImVec2(-1, 0))) requests.answer = i;
  }
  ImGui::TextDisabled("The simulation waits for your answer.");
}

// Each choice marked: the right one green, a wrong pick red.
void markedChoices(const LessonPredict& predict, int chosen) {
  wrappedColoured(kTitleColour, "Predict: " + predict.question);
  for (int i = 0; i < int(predict.choices.size()); ++i) {
    const bool right = i == predict.answer, picked = i == chosen;
    std::string line = std::to_string(i + 1) + ". " + predict.choices[std::size_t(i)];
    if (right && picked) line += "   <- your answer: right";
    else if (picked) line += "   <- your answer: wrong";
    else if (right) line += "   <- the right answer";
    const ImVec4 colour =
        right ? kRightColour : picked ? kWrongColour : ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled);
    wrappedColoured(colour, line);
  }
}

// The result on a coloured band, so it stands out from the step's text.
void highlightedResult(const std::string& result) {
  if (result.empty()) return;
  ImGui::PushStyleColor(ImGuiCol_ChildBg, kResultBackground);
  const float wrapWidth = ImGui::GetContentRegionAvail().x - 2 * ImGui::GetStyle().WindowPadding.x;
  const float height = ImGui::CalcTextSize(result.c_str(), nullptr, false, wrapWidth).y +
                       2 * ImGui::GetStyle().WindowPadding.y;
  ImGui::BeginChild("result", ImVec2(0, height), false, ImGuiWindowFlags_NoScrollbar);
  wrapped(result);
  ImGui::EndChild();
  ImGui::PopStyleColor();
}

// The beats of a rhythm that varies (atrial fibrillation), shortest interval first: the relation
// the step teaches, a short filling time before a beat and a small stroke volume, read off a table.
void playedBeatsTable(std::vector<PlayedBeat> beats) {
  if (!rhythmVaries(beats)) return;
  std::sort(beats.begin(), beats.end(),
            [](const PlayedBeat& a, const PlayedBeat& b) { return a.intervalBeforeMs < b.intervalBeforeMs; });
  ImGui::Spacing();
  wrapped("The beats played, the shortest filling time first:");
  if (!ImGui::BeginTable("played beats", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) return;
  ImGui::TableSetupColumn("beat");
  ImGui::TableSetupColumn("interval before (ms)");
  ImGui::TableSetupColumn(("stroke volume (" + beats.front().volumeUnit + ")").c_str());
  ImGui::TableHeadersRow();
  for (const PlayedBeat& b : beats) {
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::Text("#%d", b.index);
    ImGui::TableSetColumnIndex(1);
    ImGui::Text("%.0f", b.intervalBeforeMs);
    ImGui::TableSetColumnIndex(2);
    ImGui::Text("%.0f", b.strokeVolume);
  }
  ImGui::EndTable();
}

void stepBody(const LessonPlayer& player, LessonRequests& requests) {
  const LessonStep& step = player.step();
  if (!step.title.empty()) wrappedColoured(kTitleColour, step.title);
  wrapped(player.text());
  ImGui::Spacing();
  switch (player.stage()) {
    case StepStage::Applying:
      ImGui::TextDisabled("setting up the heart ...");
      return;
    case StepStage::Predicting:
      predictionButtons(*step.predict, requests);
      return;
    case StepStage::Playing: {
      if (step.predict && player.chosen())
        ImGui::TextDisabled("Your prediction: %s", step.predict->choices[std::size_t(*player.chosen())].c_str());
      const std::string progress =
          "beat " + std::to_string(std::min(player.beatsPlayed() + 1, step.beats)) + " of " + std::to_string(step.beats);
      ImGui::ProgressBar(float(player.beatsPlayed()) / float(std::max(step.beats, 1)), ImVec2(-1, 0),
                         progress.c_str());
      return;
    }
    case StepStage::Done:
      break;
  }
  if (step.predict && player.chosen()) markedChoices(*step.predict, *player.chosen());
  ImGui::Spacing();
  highlightedResult(player.result());
  playedBeatsTable(player.playedBeats());
  if (const std::string why = player.explanation(); !why.empty()) {
    ImGui::Spacing();
    wrapped(why);
  }
}

// At the top of the window, so that Next can be reached however long the step's text is.
void navigation(const LessonPlayer& player, LessonRequests& requests) {
  ImGui::BeginDisabled(!player.canGoBack());
  if (ImGui::Button("< Back")) requests.back = true;
  tooltip("The step before, with the settings the lesson had then (restarts the simulation)");
  ImGui::EndDisabled();
  ImGui::SameLine();
  const bool last = player.stepIndex() + 1 == player.stepCount();
  ImGui::BeginDisabled(!player.canGoOn());
  if (ImGui::Button(last ? "Finish" : "Next >")) requests.next = true;
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::SmallButton("close")) requests.close = true;
  tooltip("Hide the lesson; the viewer goes on as it is");
  if (!player.finished()) {
    ImGui::SameLine();
    ImGui::TextDisabled("step %d of %d", player.stepIndex() + 1, player.stepCount());
  }
  ImGui::Separator();
}

}  // namespace

float lessonPanelWidth(float sceneWidth) { return std::clamp(0.36f * sceneWidth, 280.0f, 440.0f); }

void drawLessonPanel(const LessonPlayer& player, LessonRequests& requests, float left, float top, float width,
                     float maxHeight) {
  if (player.closed()) return;
  constexpr float kMargin = 10;
  ImGui::SetNextWindowPos(ImVec2(left + kMargin, top + kMargin), ImGuiCond_Always);
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0), ImVec2(width, std::max(120.0f, maxHeight - 2 * kMargin)));
  ImGui::SetNextWindowBgAlpha(0.82f);
  const std::string title = "Lesson: " + player.lesson().title + "###lesson";
  ImGui::Begin(title.c_str(), nullptr,
               ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
  navigation(player, requests);
  if (player.finished()) {
    wrappedColoured(kTitleColour, "End of the lesson.");
    if (player.answered() > 0)
      ImGui::Text("Predictions right: %d of %d", player.rightAnswers(), player.answered());
    wrapped("The viewer goes on: change anything in the panel and watch what follows.");
  } else {
    stepBody(player, requests);
  }
  ImGui::End();
}

}  // namespace hs::viewer
