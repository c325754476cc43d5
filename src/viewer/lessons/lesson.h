#pragma once
// Lessons for the viewer (`heartsim view --lesson NAME|FILE`, docs/lessons.md): a commented TOML
// file of steps. Each step has text to read, actions (start a built-in scenario, choose the
// AHA segments that beat, set the Circulation section's sliders, play N beats), an optional
// question to predict the outcome before it is shown, and the result with its explanation,
// which may quote the measured figures ("EF now {ef}% (was {ef@normal}%)", lesson_text.h).
//
// A lesson is either a built-in (lessons/*.toml, embedded into the executable at build time as
// the scenarios are) or a path to a .toml file. Every error is a LessonError whose message is
// one line naming the file, the line, the step and the key, e.g.
//   lessons/x.toml:12: step 3: key 'segments': expected AHA segment numbers 1-17, got 19
// No ImGui here: the parser is unit-tested.
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace hs::viewer {

struct LessonError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The Circulation section's sliders and the heart rate (circulation_controls.h), in the units
// the panel shows: mmHg, mmHg s/mL, mL/mmHg, mmHg/mL, bpm.
enum class LessonSlider { Preload, Resistance, Compliance, Contractility, HeartRate };

struct SliderSetting {
  LessonSlider slider = LessonSlider::Preload;
  double value = 0;
};

// The key naming a slider in a lesson file ("preload", ..., "heart_rate").
const char* sliderKey(LessonSlider slider);

struct LessonPredict {
  std::string question;
  std::vector<std::string> choices;
  int answer = 0;    // index of the right choice (the file counts from 1)
  int scripted = 0;  // index of the choice a scripted run takes (default: the first)
};

struct LessonStep {
  std::string title;  // may be empty
  std::string text;   // read on entering the step
  // Actions on entering the step, in this order: the scenario (a restart with its own
  // settings), then the beating segments and the sliders (one restart together).
  std::optional<std::string> scenario;           // a built-in scenario name
  std::optional<std::vector<int>> beatingSegments;  // AHA 1-17 that beat (from segments or rest_segments)
  std::vector<SliderSetting> sliders;
  // The blood's colour from this step on (render::BloodColour as the control panel counts it:
  // speed 0, pressure 1, origin 2, components 3, stay 4); a display setting, no restart.
  std::optional<int> bloodColour;
  int beats = 0;  // complete beats to play before the result is shown
  std::optional<LessonPredict> predict;
  std::string result;       // shown once the beats are played; may quote figures
  std::string explanation;  // why, shown with the result
  std::string mark;         // non-empty: the figures measured at the step's end are kept under it
  int line = 0;             // where the step begins in the file
};

struct Lesson {
  std::string name;         // file stem or built-in name
  std::string source;       // "lessons/rhythm.toml" or the path given
  std::string title;
  std::string description;  // one sentence, for listings
  std::string scenario;     // the built-in scenario the lesson starts with
  std::vector<LessonStep> steps;
};

// nameOrPath: a built-in name ("rhythm") or a path to a .toml file; a built-in name wins.
Lesson loadLesson(const std::string& nameOrPath);
// sourceName is used in error messages and, by its stem, as the lesson's name.
Lesson parseLesson(std::string_view tomlText, const std::string& sourceName);
// Sorted names of the embedded lessons.
std::vector<std::string> builtinLessonNames();

}  // namespace hs::viewer
