// Lesson files: TOML text -> Lesson, with every key checked (lesson.h). Errors name the file,
// the line, the step and the key, as the scenario reader's do (src/io/scenario/scenario_file.cpp).
#include <toml++/toml.h>

#include "io/scenario/toml_text.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

#include "io/scenario/scenario_file.h"
#include "render/scene.h"
#include "viewer/lessons/lesson.h"
#include "viewer/lessons/lesson_internal.h"
#include "viewer/lessons/lesson_text.h"
#include "viewer/panels/circulation_controls.h"

namespace hs::viewer {
namespace {

// Messages are one line: newlines (e.g. from toml++'s description) become spaces.
[[noreturn]] void fail(std::string message) {
  std::replace(message.begin(), message.end(), '\n', ' ');
  std::replace(message.begin(), message.end(), '\r', ' ');
  throw LessonError(message);
}

std::string describe(const toml::node& node) {
  if (const auto* s = node.as_string()) return "\"" + s->get() + "\"";
  if (const auto* i = node.as_integer()) return std::to_string(i->get());
  if (const auto* f = node.as_floating_point()) {
    char number[32];
    std::snprintf(number, sizeof number, "%g", f->get());
    return number;
  }
  if (const auto* b = node.as_boolean()) return b->get() ? "true" : "false";
  if (node.is_array()) return "an array";
  if (node.is_table()) return "a table";
  return "a date/time";
}

std::string joined(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  return list;
}

struct SliderSpec {
  LessonSlider slider;
  const char* key;
  CirculationRange range;
  const char* unit;
};
constexpr SliderSpec kSliders[] = {
    {LessonSlider::Preload, "preload", kAtrialPressureRange, "mmHg"},
    {LessonSlider::Resistance, "resistance", kResistanceRange, "mmHg s/mL"},
    {LessonSlider::Compliance, "compliance", kComplianceRange, "mL/mmHg"},
    {LessonSlider::Contractility, "contractility", kContractilityRange, "mmHg/mL"},
    {LessonSlider::HeartRate, "heart_rate", {kLumpedHeartRateMin, kLumpedHeartRateMax}, "bpm"},
};

const std::vector<std::string> kLessonKeys = {"title", "description", "scenario"};
const std::vector<std::string> kStepKeys = {"title",      "text",    "scenario", "segments",    "rest_segments",
                                            "sliders",    "blood_colour", "play_beats", "predict", "result",
                                            "explanation", "mark"};
const std::vector<std::string> kPredictKeys = {"question", "choices", "answer", "scripted"};

// Reads one table of the file; every error names the file, line, step (when in one) and key.
class TableReader {
 public:
  TableReader(const std::string& source, std::string step, const toml::table& table, std::string prefix = "")
      : m_source(source), m_step(std::move(step)), m_table(table), m_prefix(std::move(prefix)) {
    m_line = table.source().begin.line;
    for (auto&& [k, v] : table)
      if (m_line == 0 || (k.source().begin.line != 0 && k.source().begin.line < m_line)) m_line = k.source().begin.line;
  }

  [[noreturn]] void error(std::string_view key, const std::string& message) const {
    std::uint32_t line = m_line;  // a missing key: where the table begins
    for (auto&& [k, v] : m_table)
      if (k.str() == key && k.source().begin.line != 0) line = k.source().begin.line;
    fail(m_source + (line != 0 ? ":" + std::to_string(line) : "") + ": " + m_step + "key '" + m_prefix +
         std::string(key) + "': " + message);
  }

  void onlyKeys(const std::vector<std::string>& allowed) const {
    for (auto&& [k, v] : m_table)
      if (std::find(allowed.begin(), allowed.end(), k.str()) == allowed.end())
        error(k.str(), "unknown key (expected one of: " + joined(allowed) + ")");
  }

  std::string text(std::string_view key, bool required) const {
    const toml::node* node = m_table.get(key);
    if (!node) {
      if (required) error(key, "required, got nothing");
      return "";
    }
    const auto* s = node->as_string();
    if (!s) error(key, "expected a string, got " + describe(*node));
    if (required && s->get().find_first_not_of(" \t\r\n") == std::string::npos) error(key, "expected text, got \"\"");
    return s->get();
  }

  std::optional<std::int64_t> integer(std::string_view key, std::int64_t lo, std::int64_t hi,
                                      const std::string& what) const {
    const toml::node* node = m_table.get(key);
    if (!node) return std::nullopt;
    const auto* i = node->as_integer();
    if (!i || i->get() < lo || i->get() > hi) error(key, "expected " + what + ", got " + describe(*node));
    return i->get();
  }

  const toml::node* get(std::string_view key) const { return m_table.get(key); }
  const std::string& step() const { return m_step; }

 private:
  const std::string& m_source;
  std::string m_step;  // "step 3: " or ""
  const toml::table& m_table;
  std::string m_prefix;  // "predict." for a sub-table's keys
  std::uint32_t m_line = 0;
};

std::vector<int> segmentList(const TableReader& r, std::string_view key) {
  const toml::node* node = r.get(key);
  const auto* array = node->as_array();
  if (!array) r.error(key, "expected an array of AHA segment numbers 1-17, got " + describe(*node));
  std::vector<int> segments;
  for (const toml::node& e : *array) {
    const auto* i = e.as_integer();
    if (!i || i->get() < 1 || i->get() > 17)
      r.error(key, "expected AHA segment numbers 1-17, got " + describe(e));
    if (std::find(segments.begin(), segments.end(), int(i->get())) != segments.end())
      r.error(key, "segment " + std::to_string(i->get()) + " is listed twice");
    segments.push_back(int(i->get()));
  }
  return segments;
}

// What a scenario offers to a lesson's actions.
struct ScenarioTraits {
  bool heart = false, lumped = false;
};

class LessonReader {
 public:
  explicit LessonReader(std::string source) : m_source(std::move(source)) {}

  Lesson read(const toml::table& root) {
    Lesson lesson;
    lesson.source = m_source;
    lesson.name = std::filesystem::path(m_source).stem().string();
    TableReader top(m_source, "", root);
    top.onlyKeys({"lesson", "step"});
    const toml::node* head = root.get("lesson");
    if (!head || !head->is_table()) top.error("lesson", "expected a [lesson] table with title and scenario");
    TableReader info(m_source, "", *head->as_table(), "lesson.");
    info.onlyKeys(kLessonKeys);
    lesson.title = info.text("title", true);
    lesson.description = info.text("description", false);
    lesson.scenario = scenarioName(info, "scenario", true);
    m_current = lesson.scenario;
    const toml::node* steps = root.get("step");
    if (!steps) top.error("step", "a lesson needs at least one [[step]], got none");
    const auto* array = steps->as_array();
    if (!array || !array->is_array_of_tables()) top.error("step", "expected [[step]] tables, got " + describe(*steps));
    for (const toml::node& s : *array)
      lesson.steps.push_back(readStep(*s.as_table(), int(lesson.steps.size()) + 1));
    return lesson;
  }

 private:
  std::string m_source;
  std::string m_current;                   // the scenario in effect at the step being read
  std::vector<std::string> m_marks;        // of the steps read so far
  std::map<std::string, ScenarioTraits> m_traits;

  std::string scenarioName(const TableReader& r, std::string_view key, bool required) {
    const std::string name = r.text(key, required);
    if (name.empty() && !required) return name;
    const std::vector<std::string> builtins = io::builtinScenarioNames();
    if (std::find(builtins.begin(), builtins.end(), name) == builtins.end())
      r.error(key, "unknown scenario '" + name + "' (built-ins: " + joined(builtins) + ")");
    return name;
  }

  ScenarioTraits traits(const std::string& name) {
    if (const auto found = m_traits.find(name); found != m_traits.end()) return found->second;
    const cardiac::Scenario s = io::loadScenario(name);
    return m_traits[name] = {s.heart && s.cycle.enabled, s.heart && s.circulation.lumped};
  }

  LessonStep readStep(const toml::table& table, int index) {
    LessonStep step;
    TableReader r(m_source, "step " + std::to_string(index) + ": ", table);
    step.line = int(table.source().begin.line);
    r.onlyKeys(kStepKeys);
    step.title = r.text("title", false);
    step.text = r.text("text", true);
    if (r.get("scenario")) step.scenario = m_current = scenarioName(r, "scenario", true);
    readSegments(r, step);
    if (const toml::node* sliders = r.get("sliders")) readSliders(r, *sliders, step);
    if (r.get("blood_colour")) readBloodColour(r, step);
    step.beats = int(r.integer("play_beats", 0, 20, "a whole number of beats 0-20").value_or(0));
    if (const toml::node* predict = r.get("predict")) step.predict = readPredict(r, *predict);
    step.result = r.text("result", false);
    step.explanation = r.text("explanation", false);
    checkFigures(r, "text", step.text, m_marks);
    step.mark = r.text("mark", false);
    if (r.get("mark")) {
      if (step.mark.empty() || step.mark.find_first_of("{}@ \t") != std::string::npos)
        r.error("mark", "expected a name without spaces, braces or '@', got \"" + step.mark + "\"");
      if (std::find(m_marks.begin(), m_marks.end(), step.mark) != m_marks.end())
        r.error("mark", "\"" + step.mark + "\" is already the mark of an earlier step");
      m_marks.push_back(step.mark);
    }
    checkFigures(r, "result", step.result, m_marks);
    checkFigures(r, "explanation", step.explanation, m_marks);
    return step;
  }

  static void checkFigures(const TableReader& r, std::string_view key, const std::string& text,
                           const std::vector<std::string>& marks) {
    if (const std::string problem = checkPlaceholders(text, marks); !problem.empty()) r.error(key, problem);
  }

  void readSegments(const TableReader& r, LessonStep& step) {
    const bool beat = r.get("segments") != nullptr, rest = r.get("rest_segments") != nullptr;
    if (!beat && !rest) return;
    const std::string_view key = beat ? "segments" : "rest_segments";
    if (beat && rest) r.error("rest_segments", "give segments (those that beat) or rest_segments, not both");
    const std::vector<int> listed = segmentList(r, key);
    if (!traits(m_current).heart)
      r.error(key, "the scenario '" + m_current + "' has no beating heart to choose segments of");
    std::vector<int> beating;
    for (int s = 1; s <= 17; ++s)
      if ((std::find(listed.begin(), listed.end(), s) != listed.end()) == beat) beating.push_back(s);
    if (beating.empty()) r.error(key, "leaves no segment beating: the heart would not beat at all");
    step.beatingSegments = beating;
  }

  void readBloodColour(const TableReader& r, LessonStep& step) {
    const std::string name = r.text("blood_colour", true);
    const std::optional<render::BloodColour> colour = render::parseBloodColour(name);
    if (!colour) r.error("blood_colour", "unknown colour '" + name + "' (colours: speed, pressure, origin, components, stay)");
    step.bloodColour = int(*colour);
  }

  void readSliders(const TableReader& r, const toml::node& node, LessonStep& step) {
    const auto* table = node.as_table();
    if (!table) r.error("sliders", "expected a table such as { preload = 15 }, got " + describe(node));
    std::vector<std::string> names;
    for (const SliderSpec& s : kSliders) names.emplace_back(s.key);
    TableReader sliders(m_source, r.step(), *table, "sliders.");
    sliders.onlyKeys(names);
    for (const SliderSpec& spec : kSliders) {
      const toml::node* value = sliders.get(spec.key);
      if (!value) continue;
      const std::optional<double> number = value->value<double>();
      char range[96];
      std::snprintf(range, sizeof range, "a number from %g to %g (%s)", spec.range.lo, spec.range.hi, spec.unit);
      if (!number || *number < spec.range.lo || *number > spec.range.hi)
        sliders.error(spec.key, std::string("expected ") + range + ", got " + describe(*value));
      if (!traits(m_current).lumped)
        sliders.error(spec.key, "the scenario '" + m_current +
                                    "' has no lumped circulation (circulation.lumped), so no Circulation sliders");
      step.sliders.push_back({spec.slider, *number});
    }
  }

  LessonPredict readPredict(const TableReader& r, const toml::node& node) const {
    const auto* table = node.as_table();
    if (!table) r.error("predict", "expected a table with question, choices and answer, got " + describe(node));
    TableReader p(m_source, r.step(), *table, "predict.");
    p.onlyKeys(kPredictKeys);
    LessonPredict predict;
    predict.question = p.text("question", true);
    const toml::node* choices = p.get("choices");
    if (!choices) p.error("choices", "required, got nothing");
    const auto* array = choices->as_array();
    if (!array || array->size() < 2 || array->size() > 6)
      p.error("choices", "expected 2 to 6 strings, got " + describe(*choices));
    for (const toml::node& c : *array) {
      const auto* s = c.as_string();
      if (!s || s->get().empty()) p.error("choices", "expected 2 to 6 strings, got " + describe(c));
      predict.choices.push_back(s->get());
    }
    const auto n = std::int64_t(predict.choices.size());
    const std::string which = "a choice number 1-" + std::to_string(n);
    const std::optional<std::int64_t> answer = p.integer("answer", 1, n, which);
    if (!answer) p.error("answer", "required (the right choice, " + which + "), got nothing");
    predict.answer = int(*answer - 1);
    predict.scripted = int(p.integer("scripted", 1, n, which).value_or(1) - 1);
    return predict;
  }
};

std::string builtinList() { return joined(builtinLessonNames()); }

}  // namespace

const char* sliderKey(LessonSlider slider) {
  for (const SliderSpec& s : kSliders)
    if (s.slider == slider) return s.key;
  return "";
}

Lesson parseLesson(std::string_view tomlText, const std::string& sourceName) {
  io::TomlText parsed = io::parseTomlText(tomlText, sourceName);
  if (!parsed.error.empty()) fail(parsed.error);
  const toml::table& root = parsed.table;
  return LessonReader(sourceName).read(root);
}

std::vector<std::string> builtinLessonNames() {
  std::vector<std::string> names;
  for (const auto& e : detail::embeddedLessons()) names.emplace_back(e.name);
  std::sort(names.begin(), names.end());
  return names;
}

Lesson loadLesson(const std::string& nameOrPath) {
  for (const auto& e : detail::embeddedLessons())
    if (e.name == nameOrPath) return parseLesson(e.text, "lessons/" + nameOrPath + ".toml");
  std::error_code ec;
  const std::filesystem::path path(nameOrPath);
  if (nameOrPath.empty() || !std::filesystem::exists(path, ec))
    fail("no such lesson file or built-in lesson: '" + nameOrPath + "' (built-ins: " + builtinList() + ")");
  if (!std::filesystem::is_regular_file(path, ec)) fail(nameOrPath + ": not a regular file");
  std::ifstream in(path, std::ios::binary);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (!in.good() && !in.eof()) fail(nameOrPath + ": cannot read the file");
  return parseLesson(text, nameOrPath);
}

}  // namespace hs::viewer
