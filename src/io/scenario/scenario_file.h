#pragma once
// Scenario files: TOML text -> hs::cardiac::Scenario, with strict validation.
//
// A scenario is either a built-in (scenarios/*.toml, embedded into the executable at build
// time, so a run needs no files) or a path to a .toml file. Every key is described in
// docs/scenarios.md; the key table in scenario_keys.cpp is the single source of truth (one
// row per key: dotted name, type, unit, range, field, doc text).
//
// Overrides ("KEY=VALUE", from --set) are applied after the file, with the same validation.
// VALUE is parsed as a TOML value (`cycle.segments=[1,2,3]`, `cycle.mode="physiological"`);
// for string keys a VALUE that is not a TOML string is taken literally (`cycle.mode=thesis`).
//
// Every error is a ScenarioError whose message is one line naming the file (or "--set ..."),
// the line number where known, the key, what was expected and what was got, e.g.
//   scenarios/x.toml:12: simulation.dt: must be a finite number > 0 and <= 0.1 (s), got -0.01
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "cardiac/scenario.h"
#include "pbd/core/state_stream.h"

namespace hs::io {

struct ScenarioError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// nameOrPath: a built-in name ("heart-only") or a path to a .toml file. A built-in name wins
// over a file of the same name in the working directory; write "./heart-only" for the file.
cardiac::Scenario loadScenario(const std::string& nameOrPath, const std::vector<std::string>& overrides = {});

// sourceName is used in error messages and, by its stem, as the default scenario.name.
cardiac::Scenario parseScenario(std::string_view tomlText, const std::string& sourceName,
                                const std::vector<std::string>& overrides = {});

// Sorted names of the embedded scenarios.
std::vector<std::string> builtinScenarioNames();
// The embedded file text; throws ScenarioError if the name is unknown.
std::string builtinScenarioText(const std::string& name);

// The interval a number key accepts (for an array of numbers, each of its `components`), so that
// a test can try every key at its extremes; the table's single source (scenario_keys.cpp).
struct ScenarioKeyBounds {
  double lo = 0;
  double hi = 0;
  bool loOpen = false;  // "> lo" rather than ">= lo"
  bool hiOpen = false;
  bool integer = false;  // whole numbers only
  int components = 1;    // 3: an array of 3 numbers, each within [lo, hi]
};

// The key table, for documentation and `--help`-style listings. One entry per key, in file
// order.
struct ScenarioKeyInfo {
  std::string name;          // dotted, e.g. "simulation.dt"
  std::string type;          // "number", "integer", "boolean", "string", "array of ..."
  std::string unit;          // SI unit, "" if none
  std::string range;         // allowed values in words, e.g. "> 0 and <= 0.1"
  std::string defaultValue;  // TOML text of the default-constructed Scenario's value
  std::string doc;           // one-sentence meaning
  std::optional<ScenarioKeyBounds> bounds;  // numbers, integers and arrays of 3 numbers only
};
std::vector<ScenarioKeyInfo> scenarioKeys();

// A complete TOML file with every key (the [cycle.sphere] table only when it is enabled);
// parseScenario(scenarioToToml(s), ...) gives back s. Useful to record the resolved scenario
// of a run.
std::string scenarioToToml(const cardiac::Scenario& scenario);

// Every key's exact value, by name (checkpoints, io/output/checkpoint.h: the TOML text rounds a
// clinical unit's conversion). loadScenarioValues expects the same keys in the same order and
// throws pbd::StateError naming the first that is not.
void saveScenarioValues(const cardiac::Scenario& scenario, pbd::StateWriter& w);
void loadScenarioValues(cardiac::Scenario& scenario, pbd::StateReader& r);
// The first key, outside the tables named in `ignoredTables` (e.g. "output") and the keys in
// `ignoredKeys`, whose exact value differs between a and b, as "KEY: A-TEXT vs B-TEXT"; "" when
// none does.
std::string firstDifferentKey(const cardiac::Scenario& a, const cardiac::Scenario& b,
                              const std::vector<std::string>& ignoredTables, const std::vector<std::string>& ignoredKeys);

}  // namespace hs::io
