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

// A button the width of the window whose label wraps onto as many lines as it needs (an ImGui
// button cuts its label at its edge).
bool wrappedButton(const std::string& id, const std::string& label) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float width = ImGui::GetContentRegionAvail().x, wrap = width - 2 * style.FramePadding.x;
  const float textHeight = ImGui::CalcTextSize(label.c_str(), nullptr, false, wrap).y;
  const ImVec2 corner = ImGui::GetCursorScreenPos();
  const bool pressed = ImGui::Button(("##" + id).c_str(), ImVec2(width, textHeight + 2 * style.FramePadding.y));
  ImGui::GetWindowDrawList()->AddText(ImGui::GetFont(), ImGui::GetFontSize(),
                                      ImVec2(corner.x + style.FramePadding.x, corner.y + style.FramePadding.y),
                                      ImGui::GetColorU32(ImGuiCol_Text), label.c_str(), nullptr, wrap);
  return pressed;
}

// The choices as buttons the width of the window.
void predictionButtons(const LessonPredict& predict, LessonRequests& requests) {
  wrappedColoured(kTitleColour, "Predict: " + predict.question);
  ImGui::Spacing();
  for (int i = 0; i < int(predict.choices.size()); ++i) {
    const std::string label = std::to_string(i + 1) + ". " + predict.choices[std::size_t(i)];
    if (wrappedButton("choice" + std::to_string(i), label)) requests.answer = i;
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
  wrapped("The beats played, the shortest filling time first (RR: the interval before the beat; SV: "
          "its stroke volume):");
  if (!ImGui::BeginTable("played beats", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) return;
  ImGui::TableSetupColumn("beat");
  ImGui::TableSetupColumn("RR (ms)");
  ImGui::TableSetupColumn(("SV (" + beats.front().volumeUnit + ")").c_str());
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
        wrappedColoured(ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled),
                        "Your prediction: " + step.predict->choices[std::size_t(*player.chosen())]);
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
  if (ImGui::SmallButton("hide")) requests.close = true;
  tooltip("Hide the lesson to reach the control panel under it; the viewer goes on as it is, and a button at the "
          "scene's top left shows the lesson again");
  if (!player.finished()) {
    ImGui::SameLine();
    ImGui::TextDisabled("step %d of %d", player.stepIndex() + 1, player.stepCount());
  }
  ImGui::Separator();
}

}  // namespace

void drawLessonPanel(const LessonPlayer& player, LessonRequests& requests, float left, float width,
                     int windowHeight) {
  if (player.closed()) {
    // Hidden: a button at the scene's top left corner brings it back where it was.
    ImGui::SetNextWindowPos(ImVec2(left + width + 10, 10), ImGuiCond_Always);
    ImGui::Begin("##lesson hidden", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
    const std::string show = "Lesson: " + player.lesson().title + " (show)";
    if (ImGui::Button(show.c_str())) requests.reopen = true;
    tooltip("Show the lesson again, at the step where it was");
    ImGui::End();
    return;
  }
  // Over the control panel, the whole height: the scene keeps its width for the heart, and the
  // longest step's text fits without scrolling on a 768-pixel screen.
  ImGui::SetNextWindowPos(ImVec2(left, 0), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(width, float(windowHeight)), ImGuiCond_Always);
  const std::string title = "Lesson: " + player.lesson().title + "###lesson";
  ImGui::Begin(title.c_str(), nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings);
  navigation(player, requests);
  if (player.finished()) {
    wrappedColoured(kTitleColour, "End of the lesson.");
    if (player.answered() > 0)
      ImGui::Text("Predictions right: %d of %d", player.rightAnswers(), player.answered());
    wrapped("The viewer goes on: hide the lesson to reach the control panel, change anything there and watch "
            "what follows.");
  } else {
    stepBody(player, requests);
  }
  ImGui::End();
}

}  // namespace hs::viewer
