// Lesson files: the built-in lessons load; every bad input is refused with one line naming the
// file, the line, the step and the key (docs/lessons.md); the figures' placeholders are checked
// and filled.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "viewer/lessons/lesson.h"
#include "viewer/lessons/lesson_text.h"

namespace hs::viewer {
namespace {

const std::string kHead = R"toml([lesson]
title = "Test"
scenario = "normal"
)toml";

// The error message of parsing `text` as "x.toml" ("" when it parses).
std::string errorOf(const std::string& text) {
  try {
    parseLesson(text, "x.toml");
  } catch (const LessonError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message;
  }
  return "";
}

TEST(LessonFile, BuiltinLessonsLoad) {
  const std::vector<std::string> names = builtinLessonNames();
  for (const char* expected : {"preload-afterload", "regional-wall-motion", "rhythm", "where-blood-goes"})
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  for (const std::string& name : names) {
    const Lesson lesson = loadLesson(name);
    EXPECT_EQ(lesson.name, name);
    EXPECT_EQ(lesson.source, "lessons/" + name + ".toml");
    EXPECT_FALSE(lesson.title.empty());
    EXPECT_GE(lesson.steps.size(), 3u) << name;
    for (const LessonStep& step : lesson.steps) EXPECT_LE(step.beats, 3) << name << ": keep the beats modest";
  }
}

TEST(LessonFile, RegionalWallMotionRestsTheLadTerritory) {
  const Lesson lesson = loadLesson("regional-wall-motion");
  ASSERT_GE(lesson.steps.size(), 2u);
  const LessonStep& lad = lesson.steps[1];
  ASSERT_TRUE(lad.beatingSegments.has_value());
  EXPECT_EQ(*lad.beatingSegments, (std::vector<int>{3, 4, 5, 6, 9, 10, 11, 12, 15, 16}));
  ASSERT_TRUE(lad.predict.has_value());
  EXPECT_EQ(lad.predict->answer, 2);  // "It falls", the third, counted from 0
  EXPECT_EQ(lesson.steps[0].mark, "normal");
}

TEST(LessonFile, ReadsEveryKey) {
  const Lesson lesson = parseLesson(kHead + R"toml(
[[step]]
title = "One"
text = "Read this."
scenario = "normal"
segments = [3, 4, 5]
sliders = { preload = 12, resistance = 1.5, heart_rate = 90 }
play_beats = 2
mark = "a"
result = "EF {ef}% (was {ef@a}%)"
explanation = "Because."
[step.predict]
question = "Which?"
choices = ["x", "y", "z"]
answer = 2
scripted = 3
)toml",
                                    "dir/my-lesson.toml");
  EXPECT_EQ(lesson.name, "my-lesson");
  EXPECT_EQ(lesson.scenario, "normal");
  ASSERT_EQ(lesson.steps.size(), 1u);
  const LessonStep& s = lesson.steps[0];
  EXPECT_EQ(s.title, "One");
  EXPECT_EQ(*s.scenario, "normal");
  EXPECT_EQ(*s.beatingSegments, (std::vector<int>{3, 4, 5}));
  ASSERT_EQ(s.sliders.size(), 3u);
  EXPECT_EQ(s.sliders[0].slider, LessonSlider::Preload);
  EXPECT_DOUBLE_EQ(s.sliders[0].value, 12);
  EXPECT_EQ(s.sliders[2].slider, LessonSlider::HeartRate);
  EXPECT_EQ(s.beats, 2);
  EXPECT_EQ(s.predict->choices.size(), 3u);
  EXPECT_EQ(s.predict->answer, 1);
  EXPECT_EQ(s.predict->scripted, 2);
  EXPECT_EQ(s.line, 5);
}

TEST(LessonFile, BadTomlNamesTheLine) {
  const std::string e = errorOf(kHead + "\n[[step]]\ntext = \"unclosed\n");
  EXPECT_NE(e.find("x.toml:6"), std::string::npos) << e;
  EXPECT_NE(e.find("TOML syntax error"), std::string::npos) << e;
}

TEST(LessonFile, UnknownKeysAreErrors) {
  std::string e = errorOf(kHead + "\n[[step]]\ntext = \"t\"\nplay_beat = 2\n");
  EXPECT_EQ(e.find("x.toml:7: step 1: key 'play_beat': unknown key"), 0u) << e;
  e = errorOf(kHead + "colour = 1\n[[step]]\ntext = \"t\"\n");
  EXPECT_EQ(e.find("x.toml:4: key 'lesson.colour': unknown key"), 0u) << e;
  e = errorOf(kHead + "[[step]]\ntext = \"t\"\n[step.predict]\nquestion = \"q\"\nchoices = [\"a\", \"b\"]\nanswer = 1\nhint = \"h\"\n");
  EXPECT_NE(e.find("step 1: key 'predict.hint': unknown key"), std::string::npos) << e;
}

TEST(LessonFile, MissingTextNamesTheStep) {
  const std::string e = errorOf(kHead + "[[step]]\ntext = \"first\"\n[[step]]\ntitle = \"no text\"\n");
  EXPECT_EQ(e, "x.toml:6: step 2: key 'text': required, got nothing");  // the step's [[step]] line
}

TEST(LessonFile, BadSegmentIsNamed) {
  const std::string e = errorOf(kHead + "[[step]]\ntext = \"t\"\n\n\nsegments = [1, 19]\n");
  EXPECT_EQ(e, "x.toml:8: step 1: key 'segments': expected AHA segment numbers 1-17, got 19");
  EXPECT_NE(errorOf(kHead + "[[step]]\ntext = \"t\"\nrest_segments = [0]\n").find("got 0"), std::string::npos);
  EXPECT_NE(errorOf(kHead + "[[step]]\ntext = \"t\"\nsegments = [2, 2]\n").find("listed twice"), std::string::npos);
  EXPECT_NE(errorOf(kHead + "[[step]]\ntext = \"t\"\nsegments = []\n").find("no segment beating"), std::string::npos);
}

TEST(LessonFile, BloodColourIsReadAndABadOneIsNamed) {
  const Lesson lesson = parseLesson(kHead + "[[step]]\ntext = \"t\"\nblood_colour = \"components\"\n", "x.toml");
  ASSERT_TRUE(lesson.steps[0].bloodColour.has_value());
  EXPECT_EQ(*lesson.steps[0].bloodColour, 3);  // render::BloodColour::Components, as the panel counts
  std::string e = errorOf(kHead + "[[step]]\ntext = \"t\"\nblood_colour = \"rainbow\"\n");
  EXPECT_EQ(e, "x.toml:6: step 1: key 'blood_colour': unknown colour 'rainbow' (colours: speed, pressure, origin, "
               "components, stay)");
  e = errorOf(kHead + "[[step]]\ntext = \"t\"\nblood_colour = 3\n");
  EXPECT_NE(e.find("step 1: key 'blood_colour': expected a string"), std::string::npos) << e;
}

TEST(LessonFile, WhereBloodGoesShowsTheComponentsThenTheStays) {
  const Lesson lesson = loadLesson("where-blood-goes");
  ASSERT_EQ(lesson.steps.size(), 3u);
  EXPECT_EQ(lesson.steps[0].bloodColour, std::optional<int>(3));
  EXPECT_EQ(lesson.steps[1].scenario, std::optional<std::string>("dilated-cardiomyopathy"));
  ASSERT_TRUE(lesson.steps[1].predict.has_value());
  EXPECT_EQ(lesson.steps[1].predict->answer, 1);  // the dilated heart keeps its blood longest
  EXPECT_EQ(lesson.steps[2].bloodColour, std::optional<int>(4));
}

TEST(LessonFile, UnknownScenarioIsNamed) {
  std::string e = errorOf(kHead + "[[step]]\ntext = \"t\"\nscenario = \"no-such\"\n");
  EXPECT_EQ(e.find("x.toml:6: step 1: key 'scenario': unknown scenario 'no-such' (built-ins: "), 0u) << e;
  e = errorOf("[lesson]\ntitle = \"T\"\nscenario = \"nope\"\n[[step]]\ntext = \"t\"\n");
  EXPECT_EQ(e.find("x.toml:3: key 'lesson.scenario': unknown scenario 'nope'"), 0u) << e;
}

TEST(LessonFile, BadSliderNameOrValueIsNamed) {
  std::string e = errorOf(kHead + "[[step]]\ntext = \"t\"\nsliders = { afterload = 2 }\n");
  EXPECT_EQ(e.find("x.toml:6: step 1: key 'sliders.afterload': unknown key (expected one of: preload, "), 0u) << e;
  e = errorOf(kHead + "[[step]]\ntext = \"t\"\nsliders = { preload = 45 }\n");
  EXPECT_EQ(e, "x.toml:6: step 1: key 'sliders.preload': expected a number from 0 to 30 (mmHg), got 45");
  e = errorOf(kHead + "[[step]]\ntext = \"t\"\nsliders = { resistance = \"high\" }\n");
  EXPECT_NE(e.find("key 'sliders.resistance': expected a number"), std::string::npos) << e;
  // heart-only has no lumped circulation: no Circulation section, no sliders.
  e = errorOf("[lesson]\ntitle = \"T\"\nscenario = \"heart-only\"\n[[step]]\ntext = \"t\"\nsliders = { preload = 10 }\n");
  EXPECT_NE(e.find("has no lumped circulation"), std::string::npos) << e;
}

TEST(LessonFile, NegativeBeatsAreRefused) {
  const std::string e = errorOf(kHead + "[[step]]\ntext = \"t\"\nplay_beats = -1\n");
  EXPECT_EQ(e, "x.toml:6: step 1: key 'play_beats': expected a whole number of beats 0-20, got -1");
  EXPECT_NE(errorOf(kHead + "[[step]]\ntext = \"t\"\nplay_beats = 1.5\n").find("got 1.5"), std::string::npos);
}

TEST(LessonFile, PredictionMustBeComplete) {
  const std::string step = kHead + "[[step]]\ntext = \"t\"\n[step.predict]\nquestion = \"q\"\n";
  EXPECT_NE(errorOf(step + "answer = 1\n").find("key 'predict.choices': required"), std::string::npos);
  EXPECT_NE(errorOf(step + "choices = [\"a\"]\nanswer = 1\n").find("expected 2 to 6 strings"), std::string::npos);
  EXPECT_NE(errorOf(step + "choices = [\"a\", \"b\"]\n").find("key 'predict.answer': required"), std::string::npos);
  EXPECT_NE(errorOf(step + "choices = [\"a\", \"b\"]\nanswer = 3\n").find("a choice number 1-2, got 3"),
            std::string::npos);
}

TEST(LessonFile, PlaceholdersAreChecked) {
  std::string e = errorOf(kHead + "[[step]]\ntext = \"t\"\nresult = \"EF {eff}\"\n");
  EXPECT_NE(e.find("step 1: key 'result': unknown figure 'eff'"), std::string::npos) << e;
  e = errorOf(kHead + "[[step]]\ntext = \"t\"\nresult = \"EF {ef@later}\"\n[[step]]\ntext = \"u\"\nmark = \"later\"\n");
  EXPECT_NE(e.find("no earlier step has mark = \"later\""), std::string::npos) << e;
  e = errorOf(kHead + "[[step]]\ntext = \"EF {ef\"\n");
  EXPECT_NE(e.find("key 'text': a '{' without its '}'"), std::string::npos) << e;
}

TEST(LessonFile, MissingLessonTableOrStepsAreErrors) {
  EXPECT_NE(errorOf("[[step]]\ntext = \"t\"\n").find("key 'lesson': expected a [lesson] table"), std::string::npos);
  EXPECT_NE(errorOf(kHead).find("key 'step': a lesson needs at least one [[step]]"), std::string::npos);
  EXPECT_NE(errorOf(kHead + "[step]\ntext = \"t\"\n").find("expected [[step]] tables"), std::string::npos);
}

TEST(LessonFile, UnknownLessonNameListsTheBuiltins) {
  try {
    loadLesson("no-such-lesson");
    FAIL() << "loaded";
  } catch (const LessonError& e) {
    EXPECT_NE(std::string(e.what()).find("regional-wall-motion"), std::string::npos) << e.what();
  }
}

TEST(LessonText, FillsFiguresNowAndMarked) {
  LessonFigures now, before;
  now.values[std::size_t(LessonFigure::Ef)] = 38.4;
  now.values[std::size_t(LessonFigure::Co)] = 4.26;
  before.values[std::size_t(LessonFigure::Ef)] = 61.2;
  const std::map<std::string, LessonFigures, std::less<>> marks = {{"normal", before}};
  EXPECT_EQ(fillFigures("EF now {ef}% (was {ef@normal}%), CO {co}", now, marks), "EF now 38% (was 61%), CO 4.3");
  // Not measured: a dash, not a zero.
  EXPECT_EQ(fillFigures("SBP {sbp}", now, marks), "SBP --");
}

}  // namespace
}  // namespace hs::viewer

namespace hs::viewer {
namespace {

// Found by fuzz_lesson: a carriage return after a bad number came back inside the message.
TEST(LessonFile, AControlCharacterInABadValueStillGivesOneLine) {
  try {
    (void)parseLesson("# a lesson\nsegments = [[i\r-\x04ystolic \x08r", "fuzz.toml");
    FAIL() << "accepted";
  } catch (const LessonError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\r'), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.rfind("fuzz.toml:2:", 0), 0u) << message;
  }
}

}  // namespace
}  // namespace hs::viewer
