#include "viewer/lessons/lesson_player.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace hs::viewer {

bool rhythmVaries(const std::vector<PlayedBeat>& beats) {
  if (beats.size() < 3) return false;
  const auto [shortest, longest] = std::minmax_element(
      beats.begin(), beats.end(),
      [](const PlayedBeat& a, const PlayedBeat& b) { return a.intervalBeforeMs < b.intervalBeforeMs; });
  return longest->intervalBeforeMs > 1.05 * shortest->intervalBeforeMs;
}

LessonPlayer::LessonPlayer(Lesson lesson, bool scripted) : m_lesson(std::move(lesson)), m_scripted(scripted) {
  if (m_lesson.steps.empty()) throw LessonError(m_lesson.source + ": a lesson needs at least one step");
}

void LessonPlayer::frame(LessonRequests& requests, const ViewerStatus& status,
                         const std::vector<ScenarioChoice>& scenarios, ViewerControls& controls) {
  const bool shotTaken = m_screenshotStep > 0;
  m_screenshotStep = 0;
  if (!m_started) {
    m_started = true;
    enter(0, false, scenarios);
  }
  if (requests.close) m_closed = true;
  if (requests.reopen) m_closed = false;
  if (requests.back && m_finished)
    m_finished = false;  // back to the last step's result
  else if (requests.back && canGoBack())
    enter(m_index - 1, true, scenarios);
  else if (requests.next && canGoOn())
    next(scenarios);
  else if (requests.answer >= 0 && m_stage == StepStage::Predicting)
    answer(requests.answer, status, controls);
  requests = {};
  // Scripted: the finished step was photographed at the end of the last frame.
  if (m_scripted && shotTaken && m_stage == StepStage::Done) next(scenarios);

  switch (m_stage) {
    case StepStage::Applying:
      if (!m_edits.empty()) {
        writeEdit(m_edits.front(), controls);
        m_edits.pop_front();
      } else {
        // The last action was applied (and the simulation restarted) during the last frame:
        // `status` is the new simulation's.
        begin(status, controls);
      }
      break;
    case StepStage::Predicting:
      if (m_scripted) answer(step().predict->scripted, status, controls);
      break;
    case StepStage::Playing: {
      const int beats = status.pump.beats.beatsCompleted;
      // Fewer beats than at the start: the student restarted the simulation; count from there.
      m_beatBase = std::min(m_beatBase, beats);
      m_beatsPlayed = beats - m_beatBase;
      // The result quotes a beat after the circulation has settled from the restart (PumpReadout's
      // SettlingRule): until then the panel's `now` says "settling..." and the step plays on.
      const bool settled = !status.pump.hasHeart || status.pump.beats.settled;
      if (m_beatsPlayed >= step().beats && settled) finishStep(status, controls);
      break;
    }
    case StepStage::Done:
      // Scripted: photographed once the window has had frames to size itself to the result
      // (ImGui's auto-resize follows the content a frame late).
      if (m_scripted && ++m_doneFrames == kFramesBeforeScreenshot) m_screenshotStep = m_index + 1;
      break;
  }
}

void LessonPlayer::enter(int index, bool replay, const std::vector<ScenarioChoice>& scenarios) {
  m_index = index;
  m_stage = StepStage::Applying;
  m_chosen.reset();
  m_beatsPlayed = 0;
  m_finished = false;
  m_edits.clear();
  m_settle = {};
  const LessonStep& s = step();
  // The blood's colour is a display setting, not restarted with a scenario: the one the lesson
  // had chosen by this step: set on entering a step that chooses one, and restored on Back
  // (speed before any step chose one).
  std::optional<int> colour;
  bool chooses = false;
  for (std::size_t i = 0; i < m_lesson.steps.size(); ++i) {
    chooses = chooses || m_lesson.steps[i].bloodColour.has_value();
    if (int(i) <= index && m_lesson.steps[i].bloodColour) colour = m_lesson.steps[i].bloodColour;
  }
  if (replay ? chooses : s.bloodColour.has_value()) m_edits.push_back({Edit::Kind::BloodColour, colour.value_or(0)});
  if (!replay) {
    queueActions(s.scenario, s.beatingSegments, s.sliders, scenarios);
    return;
  }
  // Back: the settings the lesson had reached at this step, from its last scenario on (a
  // scenario resets every control), so what the later steps changed is undone.
  std::optional<std::string> scenario = m_lesson.scenario;
  std::optional<std::vector<int>> segments;
  std::map<LessonSlider, double> sliders;
  for (int i = 0; i <= index; ++i) {
    const LessonStep& earlier = m_lesson.steps[std::size_t(i)];
    if (earlier.scenario) scenario = earlier.scenario, segments.reset(), sliders.clear();
    if (earlier.beatingSegments) segments = earlier.beatingSegments;
    for (const SliderSetting& setting : earlier.sliders) sliders[setting.slider] = setting.value;
  }
  std::vector<SliderSetting> settings;
  for (const auto& [slider, value] : sliders) settings.push_back({slider, value});
  queueActions(scenario, segments, settings, scenarios);
}

void LessonPlayer::queueActions(const std::optional<std::string>& scenario,
                                const std::optional<std::vector<int>>& segments,
                                const std::vector<SliderSetting>& sliders,
                                const std::vector<ScenarioChoice>& scenarios) {
  if (scenario) {
    const auto found = std::find_if(scenarios.begin(), scenarios.end(),
                                    [&](const ScenarioChoice& c) { return c.name == *scenario; });
    if (found != scenarios.end()) m_edits.push_back({Edit::Kind::Scenario, int(found - scenarios.begin())});
  }
  if (segments) {
    m_edits.push_back({Edit::Kind::ClearRegion});
    for (const int s : *segments) m_edits.push_back({Edit::Kind::ToggleSegment, s});
    m_settle.applyRegion = true;
  }
  m_settle.sliders = sliders;
  if (segments || !sliders.empty()) m_edits.push_back({Edit::Kind::Settle});
}

void LessonPlayer::writeEdit(const Edit& edit, ViewerControls& controls) const {
  switch (edit.kind) {
    case Edit::Kind::Scenario:
      controls.scenarioIndex = edit.value;
      controls.scenarioChanged = true;
      return;
    case Edit::Kind::ClearRegion:
      controls.region.clearRequested = true;
      return;
    case Edit::Kind::ToggleSegment:
      controls.region.segmentToggled = edit.value;
      return;
    case Edit::Kind::BloodColour:
      controls.bloodColour = edit.value;
      return;
    case Edit::Kind::Settle:
      break;
  }
  CirculationControls& c = controls.circulation;
  for (const SliderSetting& s : m_settle.sliders) {
    switch (s.slider) {
      case LessonSlider::Preload: c.atrialPressureMmHg = s.value, c.changed = true; break;
      case LessonSlider::Resistance: c.resistance = s.value, c.changed = true; break;
      case LessonSlider::Compliance: c.compliance = s.value, c.changed = true; break;
      case LessonSlider::Contractility: c.contractility = s.value, c.changed = true; break;
      case LessonSlider::HeartRate:
        controls.heartRateBpm = float(s.value);
        controls.cycleChanged = true;
        break;
    }
  }
  if (m_settle.applyRegion) controls.region.applyRequested = true;
}

void LessonPlayer::begin(const ViewerStatus& status, ViewerControls& controls) {
  m_beatBase = status.pump.beats.beatsCompleted;
  m_beatsPlayed = 0;
  if (step().predict) {
    // Paused until the prediction is made, so the outcome is not seen first.
    m_stage = StepStage::Predicting;
    controls.playing = false;
    return;
  }
  m_stage = StepStage::Playing;
  controls.playing = true;
  if (step().beats == 0) finishStep(status, controls);
}

void LessonPlayer::answer(int choice, const ViewerStatus& status, ViewerControls& controls) {
  const LessonPredict& predict = *step().predict;
  if (choice < 0 || choice >= int(predict.choices.size())) return;
  m_chosen = choice;
  m_answers.emplace(m_index, choice == predict.answer);  // the first answer counts
  m_stage = StepStage::Playing;
  m_beatBase = status.pump.beats.beatsCompleted;
  controls.playing = true;
  if (step().beats == 0) finishStep(status, controls);
}

void LessonPlayer::finishStep(const ViewerStatus& status, ViewerControls& controls) {
  m_stage = StepStage::Done;
  // Paused on the beat the result quotes, so that the panels beside it show the same beat.
  if (step().beats > 0) controls.playing = false;
  m_doneFrames = 0;
  m_measured = measuredFigures(status);
  if (!step().mark.empty()) m_marks[step().mark] = m_measured;
  m_played.clear();
  const std::vector<cardiac::BeatSummary>& recent = status.pump.beats.played;
  for (std::size_t i = 1; i < recent.size(); ++i)
    if (recent[i].index > m_beatBase && recent[i - 1].index + 1 == recent[i].index)
      m_played.push_back({recent[i].index, 1e3 * recent[i - 1].duration,
                          clinicalFigures(recent[i], status.pump.scale).strokeVolume, status.pump.scale.volumeUnit});
}

void LessonPlayer::next(const std::vector<ScenarioChoice>& scenarios) {
  if (m_index + 1 < stepCount())
    enter(m_index + 1, false, scenarios);
  else
    m_finished = true;
}

std::string LessonPlayer::text() const { return fillFigures(step().text, m_measured, m_marks); }

std::string LessonPlayer::result() const {
  return m_stage == StepStage::Done ? fillFigures(step().result, m_measured, m_marks) : "";
}

std::string LessonPlayer::explanation() const {
  return m_stage == StepStage::Done ? fillFigures(step().explanation, m_measured, m_marks) : "";
}

std::string stepScreenshotPath(const std::string& screenshot, int step) {
  const std::filesystem::path path(screenshot);
  char suffix[32];
  std::snprintf(suffix, sizeof suffix, "_step%02d.png", step);
  return (path.parent_path() / (path.stem().string() + suffix)).string();
}

int LessonPlayer::rightAnswers() const {
  return int(std::count_if(m_answers.begin(), m_answers.end(), [](const auto& a) { return a.second; }));
}

}  // namespace hs::viewer
