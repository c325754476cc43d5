// The lesson's step machine: a step's actions go into the viewer's controls one per frame as the
// panel's clicks would (scenario, Clear, one toggle per segment, then Apply with the sliders);
// a question pauses the simulation until answered; the beats are counted from the step's start;
// the result quotes the figures measured then; Back replays the settings reached; a scripted
// run answers, photographs each step and moves on by itself.
#include <gtest/gtest.h>

#include "lessons/beat_summary.h"
#include "viewer/lessons/lesson_player.h"

namespace hs::viewer {
namespace {

const std::vector<ScenarioChoice> kScenarios = {{"heart-only", ""}, {"irregular", ""}, {"normal", ""}};

Lesson twoStepLesson() {
  Lesson lesson;
  lesson.title = "Test";
  lesson.scenario = "normal";
  LessonStep intro;
  intro.text = "Watch.";
  intro.beats = 2;
  intro.mark = "before";
  intro.result = "EF {ef}%";
  LessonStep change;
  change.text = "Change.";
  change.beatingSegments = std::vector<int>{3, 4};
  change.sliders = {{LessonSlider::Preload, 16}, {LessonSlider::HeartRate, 90}};
  change.beats = 1;
  change.predict = LessonPredict{"What?", {"up", "down"}, 1, 0};
  change.result = "EF {ef}% (was {ef@before}%)";
  lesson.steps = {intro, change};
  return lesson;
}

// A status after `beats` complete beats with the given EF (from the lumped circulation's beat).
ViewerStatus statusWith(int beats, double ef = 60) {
  ViewerStatus status;
  status.pump.beats.beatsCompleted = beats;
  status.circulation.lumped = true;
  cardiac::LumpedBeatFigures beat;
  beat.edv = 120e-6;
  beat.esv = beat.edv * (1 - ef / 100);
  status.circulation.lastBeat = beat;
  return status;
}

// One frame with no panel requests; the controls' one-frame requests are cleared after it, as
// the app's applyRequests does.
void frame(LessonPlayer& player, const ViewerStatus& status, ViewerControls& controls) {
  LessonRequests none;
  player.frame(none, status, kScenarios, controls);
}

TEST(LessonPlayer, StepWithoutActionsPlaysItsBeatsThenShowsTheResult) {
  LessonPlayer player(twoStepLesson(), false);
  ViewerControls controls;
  controls.playing = false;
  frame(player, statusWith(5), controls);
  // No actions in step 1: it begins at once, playing, counting from the 5 beats already done.
  EXPECT_EQ(player.stage(), StepStage::Playing);
  EXPECT_TRUE(controls.playing);
  frame(player, statusWith(6), controls);
  EXPECT_EQ(player.stage(), StepStage::Playing);
  EXPECT_EQ(player.beatsPlayed(), 1);
  EXPECT_FALSE(player.canGoOn());
  frame(player, statusWith(7, 58), controls);
  EXPECT_EQ(player.stage(), StepStage::Done);
  EXPECT_EQ(player.result(), "EF 58%");
  EXPECT_TRUE(player.canGoOn());
  EXPECT_EQ(player.screenshotStep(), 0);  // not scripted
}

TEST(LessonPlayer, ActionsGoOutOneAFrameAsThePanelsWould) {
  LessonPlayer player(twoStepLesson(), false);
  ViewerControls controls;
  frame(player, statusWith(0), controls);
  frame(player, statusWith(2), controls);
  ASSERT_EQ(player.stage(), StepStage::Done);
  LessonRequests next;
  next.next = true;
  player.frame(next, statusWith(2), kScenarios, controls);
  EXPECT_FALSE(next.next);  // taken
  EXPECT_EQ(player.stepIndex(), 1);
  EXPECT_TRUE(controls.region.clearRequested);  // the first action: Clear
  controls.region.clearRequested = false;
  frame(player, statusWith(2), controls);
  EXPECT_EQ(controls.region.segmentToggled, 3);
  frame(player, statusWith(2), controls);
  EXPECT_EQ(controls.region.segmentToggled, 4);
  controls.region.segmentToggled = 0;
  frame(player, statusWith(2), controls);
  // Apply with the sliders: one restart.
  EXPECT_TRUE(controls.region.applyRequested);
  EXPECT_TRUE(controls.circulation.changed);
  EXPECT_DOUBLE_EQ(controls.circulation.atrialPressureMmHg, 16);
  EXPECT_FLOAT_EQ(controls.heartRateBpm, 90);
  EXPECT_TRUE(controls.cycleChanged);
  EXPECT_EQ(player.stage(), StepStage::Applying);
  // The next frame sees the restarted simulation (0 beats) and asks the question, paused.
  controls.playing = true;
  frame(player, statusWith(0), controls);
  EXPECT_EQ(player.stage(), StepStage::Predicting);
  EXPECT_FALSE(controls.playing);
}

// The blood's colour is a display setting: set on entering the step that chooses it, kept by
// the steps after, and put back on Back to a step before any chose one.
TEST(LessonPlayer, BloodColourIsSetByItsStepAndRestoredOnBack) {
  Lesson lesson = twoStepLesson();
  lesson.steps[1].bloodColour = 3;
  LessonPlayer player(lesson, false);
  ViewerControls controls;
  frame(player, statusWith(0), controls);
  EXPECT_EQ(controls.bloodColour, 0) << "step 1 chooses none";
  frame(player, statusWith(2), controls);
  ASSERT_EQ(player.stage(), StepStage::Done);
  LessonRequests next;
  next.next = true;
  player.frame(next, statusWith(2), kScenarios, controls);
  EXPECT_EQ(controls.bloodColour, 3) << "the first action of step 2";
  LessonRequests back;
  back.back = true;
  player.frame(back, statusWith(0), kScenarios, controls);
  EXPECT_EQ(player.stepIndex(), 0);
  EXPECT_EQ(controls.bloodColour, 0) << "back before any step chose a colour: speed";
}

TEST(LessonPlayer, AnswerPlaysTheBeatsAndTheResultQuotesTheMark) {
  LessonPlayer player(twoStepLesson(), false);
  ViewerControls controls;
  frame(player, statusWith(0), controls);
  frame(player, statusWith(2, 61), controls);  // step 1 done, marked "before": EF 61
  LessonRequests request;
  request.next = true;
  player.frame(request, statusWith(2), kScenarios, controls);
  for (int i = 0; i < 4; ++i) frame(player, statusWith(0), controls);
  ASSERT_EQ(player.stage(), StepStage::Predicting);
  EXPECT_EQ(player.result(), "");  // nothing shown before the answer
  request = {};
  request.answer = 0;  // "up": wrong
  player.frame(request, statusWith(0), kScenarios, controls);
  EXPECT_EQ(player.stage(), StepStage::Playing);
  EXPECT_TRUE(controls.playing);
  EXPECT_EQ(player.chosen(), 0);
  frame(player, statusWith(1, 38), controls);
  ASSERT_EQ(player.stage(), StepStage::Done);
  EXPECT_EQ(player.result(), "EF 38% (was 61%)");
  EXPECT_EQ(player.rightAnswers(), 0);
  EXPECT_EQ(player.answered(), 1);
  request = {};
  request.next = true;  // the last step: the lesson ends
  player.frame(request, statusWith(1), kScenarios, controls);
  EXPECT_TRUE(player.finished());
}

TEST(LessonPlayer, BackReplaysTheSettingsTheLessonHadReached) {
  Lesson lesson = twoStepLesson();
  lesson.steps[0].scenario = "irregular";
  LessonStep third;
  third.text = "Third.";
  lesson.steps.push_back(third);
  LessonPlayer player(lesson, true);
  ViewerControls controls;
  // Scripted: through step 1 and 2 by itself.
  for (int i = 0; i < 40 && player.stepIndex() < 2; ++i) frame(player, statusWith(i), controls);
  ASSERT_EQ(player.stepIndex(), 2);
  controls = {};
  LessonRequests back;
  back.back = true;
  player.frame(back, statusWith(0), kScenarios, controls);
  EXPECT_EQ(player.stepIndex(), 1);
  // From the last scenario on: irregular, then its segments and sliders.
  EXPECT_TRUE(controls.scenarioChanged);
  EXPECT_EQ(controls.scenarioIndex, 1);
}

TEST(LessonPlayer, ScriptedRunAnswersPhotographsEachStepAndFinishes) {
  LessonPlayer player(twoStepLesson(), true);
  ViewerControls controls;
  std::vector<int> shots;
  int beats = 0;
  for (int i = 0; i < 100 && !player.finished(); ++i) {
    frame(player, statusWith(beats), controls);
    if (player.screenshotStep() > 0) shots.push_back(player.screenshotStep());
    ++beats;
  }
  EXPECT_TRUE(player.finished());
  EXPECT_EQ(shots, (std::vector<int>{1, 2}));
  EXPECT_EQ(player.chosen(), 0);  // the lesson's scripted choice
  EXPECT_EQ(player.answered(), 1);
}

TEST(LessonPlayer, CountsFromARestartByTheStudent) {
  LessonPlayer player(twoStepLesson(), false);
  ViewerControls controls;
  frame(player, statusWith(4), controls);
  frame(player, statusWith(5), controls);
  EXPECT_EQ(player.beatsPlayed(), 1);
  frame(player, statusWith(0), controls);  // Reset pressed: a new simulation
  EXPECT_EQ(player.beatsPlayed(), 0);
  frame(player, statusWith(1), controls);
  EXPECT_EQ(player.stage(), StepStage::Playing);
  frame(player, statusWith(2), controls);
  EXPECT_EQ(player.stage(), StepStage::Done);
}

TEST(LessonPlayer, StepScreenshotsSitBesideTheFinalOne) {
  EXPECT_EQ(stepScreenshotPath("out/slides.png", 3), "out/slides_step03.png");
  EXPECT_EQ(stepScreenshotPath("s.png", 12), "s_step12.png");
}

}  // namespace
}  // namespace hs::viewer

namespace hs::viewer {
namespace {

using testing::completeBeat;

// The step waits for the circulation to settle, then pauses on the beat its result quotes (the
// panels beside it show the same beat), and keeps the beats it played with the interval before
// each: atrial fibrillation's table of short intervals and small stroke volumes.
TEST(LessonPlayer, AStepEndsOnASettledBeatPausedAndKeepsTheBeatsItPlayed) {
  LessonPlayer player(twoStepLesson(), false);
  ViewerControls controls;
  ViewerStatus status = statusWith(5);
  status.pump.hasHeart = true;
  frame(player, status, controls);
  ASSERT_EQ(player.stage(), StepStage::Playing);
  status.pump.beats.beatsCompleted = 7;  // two beats played, but the circulation still settles
  frame(player, status, controls);
  EXPECT_EQ(player.stage(), StepStage::Playing) << "no result from unsettled beats";
  status.pump.beats.beatsCompleted = 8;
  status.pump.beats.settled = true;
  status.pump.scale = volumeScaleFor(120e-6);
  status.pump.beats.played = {completeBeat(5, 0.83, 120, 50), completeBeat(6, 0.55, 118, 48),
                              completeBeat(7, 1.10, 100, 45), completeBeat(8, 0.70, 125, 48)};
  frame(player, status, controls);
  ASSERT_EQ(player.stage(), StepStage::Done);
  EXPECT_FALSE(controls.playing) << "paused on the beat the result quotes";
  const std::vector<PlayedBeat>& played = player.playedBeats();
  ASSERT_EQ(played.size(), 3u) << "beats 6, 7 and 8: played in this step, the interval before each known";
  EXPECT_EQ(played[0].index, 6);
  EXPECT_DOUBLE_EQ(played[0].intervalBeforeMs, 830);
  EXPECT_DOUBLE_EQ(played[1].intervalBeforeMs, 550);
  EXPECT_NEAR(played[1].strokeVolume, 55, 1e-9) << "the beat after the short interval ejects little";
  EXPECT_TRUE(rhythmVaries(played));
  EXPECT_FALSE(rhythmVaries({{1, 830, 70, "mL"}, {2, 833, 70, "mL"}, {3, 831, 70, "mL"}})) << "a regular rhythm";
}

}  // namespace
}  // namespace hs::viewer
