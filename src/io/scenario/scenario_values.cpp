// A scenario's exact values for checkpoints: the key table's fields as their bytes, each after
// its name, so that a checkpoint rebuilds the very scenario it was taken of (its TOML text
// gives clinical units and doubles back only to the printed digits).
#include <algorithm>

#include "io/scenario/scenario_file.h"
#include "io/scenario/scenario_internal.h"

namespace hs::io {

void saveScenarioValues(const cardiac::Scenario& scenario, pbd::StateWriter& w) {
  w.section("scenario values");
  w.put(std::uint64_t(detail::keyTable().size()));
  for (const detail::KeySpec& k : detail::keyTable()) {
    w.put(k.name);
    k.save(scenario, w);
  }
  // Set by the [cycle.sphere] table's presence rather than by a key.
  w.put(scenario.cycle.sphereEnabled);
}

void loadScenarioValues(cardiac::Scenario& scenario, pbd::StateReader& r) {
  r.section("scenario values");
  const std::size_t at = r.offset();
  std::uint64_t count = 0;
  r.get(count);
  if (count != detail::keyTable().size())
    throw pbd::StateError("scenario values: " + std::to_string(count) + " keys, this heartsim has " +
                              std::to_string(detail::keyTable().size()),
                          at);
  for (const detail::KeySpec& k : detail::keyTable()) {
    const std::size_t keyAt = r.offset();
    std::string name;
    r.get(name);
    if (name != k.name)
      throw pbd::StateError("scenario values: key '" + name.substr(0, 60) + "' where this heartsim has '" + k.name + "'",
                            keyAt);
    k.load(scenario, r);
  }
  r.get(scenario.cycle.sphereEnabled);
}

std::string firstDifferentKey(const cardiac::Scenario& a, const cardiac::Scenario& b,
                              const std::vector<std::string>& ignoredTables, const std::vector<std::string>& ignoredKeys) {
  for (const detail::KeySpec& k : detail::keyTable()) {
    const std::string table = k.name.substr(0, k.name.rfind('.'));
    if (std::find(ignoredTables.begin(), ignoredTables.end(), table) != ignoredTables.end()) continue;
    if (std::find(ignoredKeys.begin(), ignoredKeys.end(), k.name) != ignoredKeys.end()) continue;
    pbd::StateWriter left, right;
    k.save(a, left);
    k.save(b, right);
    if (left.bytes() != right.bytes()) return k.name + ": " + k.get(a) + " vs " + k.get(b);
  }
  if (a.cycle.sphereEnabled != b.cycle.sphereEnabled)
    return std::string("[cycle.sphere]: ") + (a.cycle.sphereEnabled ? "present" : "absent") + " vs " +
           (b.cycle.sphereEnabled ? "present" : "absent");
  return "";
}

}  // namespace hs::io
