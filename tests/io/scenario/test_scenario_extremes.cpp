// Every accepted value runs (issue 41, item 2): each number key of each built-in scenario, at the
// lowest and the highest value the reader accepts (each component of an array of 3 numbers in
// turn, the others as the scenario has them), given as `--set KEY=VALUE` is, then 20 steps checked
// as `heartsim run` checks them. A value is either refused before the first step with one line
// that names a key (exit 2) or runs its 20 steps healthy (exit 0); a run that goes invalid (exit 3)
// fails the test. The keys come from the key table, so a new key is swept without a line here.
//
// The keys of [blood], [simulation] and [container] run on the scenario as written; the others
// (the wall, its beat, the circulation) on its blood at `--resolution coarse`, a quarter of the
// particles, as `heartsim run --resolution coarse` would: their extremes act on the wall, and the
// sweep then takes minutes rather than an hour on 2 cores. Labelled `long` (tests/long_tests.cmake).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cardiac/blood_resolution.h"
#include "cardiac/heart_simulation.h"
#include "cardiac/run_monitor.h"
#include "io/scenario/scenario_file.h"

namespace hs::io {
namespace {

using cardiac::Scenario;
using pbd::Real;

constexpr int kSteps = 20;

// TOML text that reads back to exactly `value` (a double; a whole number for integer keys).
std::string numberText(double value, bool integer) {
  if (integer) return std::to_string(static_cast<std::int64_t>(value));
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

// The value nearest `bound` that the bounds accept, as the build's Real holds it: the bound
// itself, or for an open bound the first Real beyond it toward the inside.
double inside(double bound, bool open, bool upward) {
  if (!open) return bound;
  const Real toward = upward ? std::numeric_limits<Real>::max() : std::numeric_limits<Real>::lowest();
  auto r = static_cast<Real>(bound);
  while (upward ? double(r) <= bound : double(r) >= bound) r = std::nextafter(r, toward);
  return double(r);
}

std::vector<double> extremesOf(const ScenarioKeyBounds& b) {
  return {inside(b.lo, b.loOpen, true), inside(b.hi, b.hiOpen, false)};
}

// The three numbers of an array key as the scenario has them, from its TOML text ("key = [x, y, z]").
std::vector<std::string> componentsIn(const Scenario& scenario, const std::string& dotted) {
  const std::string toml = scenarioToToml(scenario);
  const auto dot = dotted.rfind('.');
  const std::string header = "[" + dotted.substr(0, dot) + "]\n",
                    line = "\n" + dotted.substr(dot + 1) + " = [";
  const auto table = toml.find(header);
  const auto at = table == std::string::npos ? table : toml.find(line, table);
  if (at == std::string::npos) return {"0", "0", "0"};  // a table the scenario leaves out ([cycle.sphere])
  const auto from = at + line.size(), to = toml.find(']', from);
  std::vector<std::string> parts;
  std::string rest = toml.substr(from, to - from);
  for (std::size_t comma; (comma = rest.find(',')) != std::string::npos; rest = rest.substr(comma + 1))
    parts.push_back(rest.substr(0, comma));
  parts.push_back(rest);
  return parts;
}

struct Case {
  std::string key, value;
};

// Every number key at its extremes, in the key table's order.
std::vector<Case> extremeCases(const Scenario& scenario) {
  std::vector<Case> cases;
  for (const ScenarioKeyInfo& k : scenarioKeys()) {
    if (!k.bounds) continue;
    for (const double v : extremesOf(*k.bounds)) {
      const std::string text = numberText(v, k.bounds->integer);
      if (k.bounds->components == 1) {
        cases.push_back({k.name, text});
        continue;
      }
      for (std::size_t i = 0; i < std::size_t(k.bounds->components); ++i) {
        std::vector<std::string> parts = componentsIn(scenario, k.name);
        parts.at(i) = text;
        cases.push_back({k.name, "[" + parts[0] + ", " + parts[1] + ", " + parts[2] + "]"});
      }
    }
  }
  return cases;
}

// A refusal is one line naming a key of the table ("... model.resolution: ...", "... (cycle.segments,
// ...)"), not only its table ("model: these parameters give no valid mesh").
void expectNamesAKey(const std::string& message, const Case& c) {
  EXPECT_EQ(message.find('\n'), std::string::npos) << c.key << " = " << c.value << ": " << message;
  bool named = false;
  for (const ScenarioKeyInfo& k : scenarioKeys()) named = named || message.find(k.name) != std::string::npos;
  EXPECT_TRUE(named) << c.key << " = " << c.value << " was refused without naming a key: " << message;
}

// Outcome of one case, as `heartsim run` would end: 2 refused (the message checked), 0 ran, 3
// became invalid (a failure of the test).
int runCase(const std::string& scenarioName, const Case& c) {
  Scenario scenario;
  try {
    scenario = loadScenario(scenarioName, {c.key + "=" + c.value});
  } catch (const ScenarioError& e) {
    expectNamesAKey(e.what(), c);
    return 2;
  }
  const std::string table = c.key.substr(0, c.key.find('.'));
  if (table != "blood" && table != "simulation" && table != "container")
    cardiac::applyResolution(cardiac::BloodResolution::Coarse, scenario);
  std::unique_ptr<cardiac::HeartSimulation> sim;
  try {
    sim = std::make_unique<cardiac::HeartSimulation>(scenario, 1);
  } catch (const std::invalid_argument& e) {  // the model's own checks: exit 2 as well
    expectNamesAKey(e.what(), c);
    return 2;
  }
  cardiac::MonitorSettings settings;  // as heartsim run watches a run
  settings.everyColumn = true;
  settings.endTime = kSteps * double(scenario.simulation.dt);
  settings.limits.bloodLost = std::size_t(scenario.blood.lossAllowed);
  cardiac::RunMonitor monitor(*sim, settings);
  for (int s = 0; s < kSteps; ++s) {
    sim->step();
    if (const cardiac::Verdict& verdict = monitor.observe(); !verdict.healthy()) {
      ADD_FAILURE() << scenarioName << ": --set " << c.key << "=" << c.value
                    << " was accepted but the run became invalid: " << verdict.message();
      return 3;
    }
  }
  return 0;
}

class ScenarioExtremes : public testing::TestWithParam<std::string> {};

TEST_P(ScenarioExtremes, EveryNumberKeyRunsOrIsRefusedByName) {
  const std::string name = GetParam();
  const std::vector<Case> cases = extremeCases(loadScenario(name));
  int ran = 0, refused = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE(name + ": --set " + c.key + "=" + c.value);
    (runCase(name, c) == 0 ? ran : refused) += 1;
  }
  // The sweep reached the keys (two extremes of each number, six of each array of 3) and some ran.
  EXPECT_GT(cases.size(), 150u);
  EXPECT_GT(ran, 0);
  std::printf("%s: %zu extremes, %d ran 20 steps, %d refused by name\n", name.c_str(), cases.size(), ran,
              refused);
}

std::string testName(const testing::TestParamInfo<std::string>& info) {
  std::string n = info.param;
  for (char& ch : n)
    if (ch == '-') ch = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(Builtins, ScenarioExtremes, testing::ValuesIn(builtinScenarioNames()), testName);

// The sweep's premise: every number key has finite bounds (an unbounded side has no extreme a
// run could try), and docs/scenarios.md gives each key's range as the reader checks it.
TEST(ScenarioKeyBounds, EveryNumberKeyIsBoundedOnBothSidesAndDocumented) {
  const std::vector<ScenarioKeyInfo> keys = scenarioKeys();
  std::FILE* f = std::fopen((std::string(HS_SOURCE_DIR) + "/docs/scenarios.md").c_str(), "rb");
  ASSERT_NE(f, nullptr);
  std::string docs;
  for (int ch; (ch = std::fgetc(f)) != EOF;) docs += char(ch);
  std::fclose(f);
  for (const ScenarioKeyInfo& k : keys) {
    const bool numeric = k.type == "number" || k.type == "integer" || k.type == "array of 3 numbers";
    EXPECT_EQ(numeric, k.bounds.has_value()) << k.name;
    if (!k.bounds) continue;
    EXPECT_TRUE(std::isfinite(k.bounds->lo) && std::isfinite(k.bounds->hi)) << k.name;
    const auto row = docs.find("| `" + k.name + "` |");
    ASSERT_NE(row, std::string::npos) << k.name << " has no row in docs/scenarios.md";
    const std::string line = docs.substr(row, docs.find('\n', row) - row);
    EXPECT_NE(line.find("| " + k.range), std::string::npos)
        << k.name << ": docs/scenarios.md's Allowed column does not start with the reader's range '"
        << k.range << "': " << line;
  }
}

}  // namespace
}  // namespace hs::io
