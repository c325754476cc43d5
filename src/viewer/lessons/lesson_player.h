#pragma once
// A lesson's step machine, as pure logic (no ImGui, no window): which step is shown, what it
// does to the viewer on entry, when its beats have been played, the prediction and the
// measured result. It acts only through ViewerControls, writing the fields and one-frame
// requests the panels would write, so ViewerApp's applyRequests does the rest (a scenario
// change, a region Apply, a slider's restart).
//
// A step's actions go out one per frame, as a student's clicks would: the scenario first (it
// resets every control), then Clear and one segment toggle per frame (RegionControls takes one
// toggle a frame), then one frame that sets the sliders and asks for Apply, which restarts the
// simulation once. The frame after that, the step begins: with a question the simulation is
// paused until it is answered; then it plays the step's beats (counted in the pump panel's
// complete beats since the restart) and the result is shown with the figures measured then.
//
// Scripted (`--frames`): the player answers with the lesson's scripted choice, asks for a
// screenshot when each step is done, and moves on by itself.
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "viewer/lessons/lesson.h"
#include "viewer/lessons/lesson_text.h"
#include "viewer/panels/ui_panel.h"

namespace hs::viewer {

enum class StepStage {
  Applying,    // the step's actions are going out, one per frame
  Predicting,  // the question is shown, the simulation paused
  Playing,     // the step's beats are playing
  Done,        // the result is shown; Next goes on
};

// The lesson panel's one-frame requests (lesson_panel.h).
struct LessonRequests {
  int answer = -1;  // a choice was clicked
  bool next = false, back = false;
  bool close = false;   // hide the lesson window
  bool reopen = false;  // show it again
};

// One beat a step played, for the table of a rhythm that varies: the interval before it (the
// filling time it had, the previous beat's length) and what it ejected.
struct PlayedBeat {
  int index = 0;               // the panel's beat number
  double intervalBeforeMs = 0;  // RR interval before the beat
  double strokeVolume = 0;      // in the panel's volume unit
  std::string volumeUnit;       // "mL"
};
// The beats worth a table: at least three, their intervals differing by more than 5%.
bool rhythmVaries(const std::vector<PlayedBeat>& beats);

class LessonPlayer {
 public:
  LessonPlayer(Lesson lesson, bool scripted);

  // Once a frame, before the app acts on the controls' requests: the panel's requests (cleared
  // here), the scripted run's own moves, the step's next action into `controls`, and the
  // beats and figures from `status` (the last frame's). `scenarios`: the panel's preset list,
  // whose index a scenario action selects.
  void frame(LessonRequests& requests, const ViewerStatus& status, const std::vector<ScenarioChoice>& scenarios,
             ViewerControls& controls);

  [[nodiscard]] const Lesson& lesson() const { return m_lesson; }
  [[nodiscard]] int stepIndex() const { return m_index; }  // 0-based
  [[nodiscard]] int stepCount() const { return int(m_lesson.steps.size()); }
  [[nodiscard]] const LessonStep& step() const { return m_lesson.steps[std::size_t(m_index)]; }
  [[nodiscard]] StepStage stage() const { return m_stage; }
  [[nodiscard]] std::optional<int> chosen() const { return m_chosen; }
  [[nodiscard]] int beatsPlayed() const { return m_beatsPlayed; }
  // The step's texts with their figures filled in (result and explanation once Done).
  [[nodiscard]] std::string text() const;
  [[nodiscard]] std::string result() const;
  [[nodiscard]] std::string explanation() const;
  [[nodiscard]] const LessonFigures& measured() const { return m_measured; }
  // The beats the finished step played (settled ones, whose interval before is known).
  [[nodiscard]] const std::vector<PlayedBeat>& playedBeats() const { return m_played; }
  // Predictions answered right so far, and answered at all (each step counted once).
  [[nodiscard]] int rightAnswers() const;
  [[nodiscard]] int answered() const { return int(m_answers.size()); }
  // The last step's Next was pressed (or, scripted, its screenshot taken).
  [[nodiscard]] bool finished() const { return m_finished; }
  [[nodiscard]] bool closed() const { return m_closed; }
  [[nodiscard]] bool scripted() const { return m_scripted; }
  // Scripted: the 1-based step to photograph once this frame is drawn; 0 for none.
  [[nodiscard]] int screenshotStep() const { return m_screenshotStep; }

  // The Back and Next buttons' states.
  [[nodiscard]] bool canGoBack() const { return m_index > 0 || m_finished; }
  [[nodiscard]] bool canGoOn() const { return m_stage == StepStage::Done && !m_finished; }

 private:
  struct Edit {
    enum class Kind { Scenario, ClearRegion, ToggleSegment, Settle, BloodColour } kind;
    int value = 0;  // scenario index, segment, or blood colour
  };
  // What the Settle edit writes.
  struct Settle {
    std::vector<SliderSetting> sliders;
    bool applyRegion = false;
  };

  void enter(int index, bool replay, const std::vector<ScenarioChoice>& scenarios);
  void queueActions(const std::optional<std::string>& scenario, const std::optional<std::vector<int>>& segments,
                    const std::vector<SliderSetting>& sliders, const std::vector<ScenarioChoice>& scenarios);
  void writeEdit(const Edit& edit, ViewerControls& controls) const;
  void begin(const ViewerStatus& status, ViewerControls& controls);
  void answer(int choice, const ViewerStatus& status, ViewerControls& controls);
  void finishStep(const ViewerStatus& status, ViewerControls& controls);
  void next(const std::vector<ScenarioChoice>& scenarios);

  Lesson m_lesson;
  bool m_scripted = false;
  int m_index = 0;
  StepStage m_stage = StepStage::Applying;
  std::deque<Edit> m_edits;
  Settle m_settle;
  int m_beatBase = 0;  // complete beats when the step's beats began
  int m_beatsPlayed = 0;
  std::optional<int> m_chosen;
  std::map<int, bool> m_answers;  // step -> answered right
  LessonFigures m_measured;
  std::vector<PlayedBeat> m_played;
  std::map<std::string, LessonFigures, std::less<>> m_marks;
  bool m_finished = false, m_closed = false;
  bool m_started = false;
  int m_screenshotStep = 0;
  int m_doneFrames = 0;  // frames drawn since the step was done
  static constexpr int kFramesBeforeScreenshot = 3;
};

// Where a scripted run saves step k's screenshot: "out.png" -> "out_step01.png" beside it.
std::string stepScreenshotPath(const std::string& screenshot, int step);

}  // namespace hs::viewer
