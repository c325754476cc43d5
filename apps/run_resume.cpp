#include "run_resume.h"

#include <cmath>
#include <iostream>

#include "io/scenario/scenario_file.h"
#include "simulation_setup.h"

namespace hs::app {
namespace {

// What may differ between a checkpoint's scenario and the one a resumed run is given: how
// long it runs and what it writes, never what it simulates.
const std::vector<std::string> kFreeTables{"output"};
const std::vector<std::string> kFreeKeys{"simulation.duration"};

// The scenario the command gives beside --resume: its scenario argument, or the checkpoint's
// own with --set applied; nullopt after printing the error.
std::optional<cardiac::Scenario> givenScenario(const RunOptions& options, const io::Checkpoint& checkpoint,
                                               const cardiac::Scenario& saved) {
  if (!options.scenario.empty()) return loadScenarioOrReport(options.scenario, options.overrides);
  if (options.overrides.empty()) return saved;
  try {
    // The text with and without the overrides: what --set changed is what differs.
    const cardiac::Scenario plain = io::parseScenario(checkpoint.scenarioToml, options.resume);
    const cardiac::Scenario changed = io::parseScenario(checkpoint.scenarioToml, options.resume, options.overrides);
    const std::string change = io::firstDifferentKey(plain, changed, kFreeTables, kFreeKeys);
    if (!change.empty()) {
      std::cerr << "heartsim: error: " << options.resume << ": scenario mismatch: --set changes the simulation ("
                << change << "); a resumed run may change only simulation.duration and output.*\n";
      return std::nullopt;
    }
    cardiac::Scenario given = saved;
    given.output = changed.output;
    given.simulation.duration = changed.simulation.duration;
    return given;
  } catch (const io::ScenarioError& e) {
    std::cerr << "heartsim: error: " << e.what() << '\n';
    return std::nullopt;
  }
}

}  // namespace

std::optional<ResumedRun> readResumedRun(const RunOptions& options) {
  ResumedRun run;
  try {
    run.checkpoint = io::readCheckpointFile(options.resume);
    run.scenario = io::checkpointScenario(run.checkpoint, options.resume);
  } catch (const io::CheckpointError& e) {
    std::cerr << "heartsim: error: " << e.what() << '\n';
    return std::nullopt;
  }
  const std::optional<cardiac::Scenario> given = givenScenario(options, run.checkpoint, run.scenario);
  if (!given) return std::nullopt;
  const std::string change = io::firstDifferentKey(run.scenario, *given, kFreeTables, kFreeKeys);
  if (!change.empty()) {
    std::cerr << "heartsim: error: " << options.resume << ": scenario mismatch: the checkpoint is of '"
              << run.scenario.name << "', the command gives '" << given->name << "' (" << change
              << "); resume with no scenario argument to use the checkpoint's\n";
    return std::nullopt;
  }
  run.scenario.output = given->output;
  if (options.duration) {
    if (!std::isfinite(*options.duration) || *options.duration < 0) {
      std::cerr << "heartsim: error: --duration: must be a finite number >= 0 (s), got " << *options.duration << '\n';
      return std::nullopt;
    }
    run.scenario.simulation.duration = static_cast<pbd::Real>(*options.duration);
  } else {
    run.scenario.simulation.duration = given->simulation.duration;
  }
  const double end = std::round(double(run.scenario.simulation.duration) / double(run.scenario.simulation.dt));
  if (end < double(run.checkpoint.step)) {
    std::cerr << "heartsim: error: --duration: " << run.scenario.simulation.duration << " s ends before the checkpoint "
              << options.resume << " at t = " << run.checkpoint.time << " s\n";
    return std::nullopt;
  }
  return run;
}

std::optional<std::int64_t> checkpointIntervalOrReport(const RunOptions& options, const cardiac::Scenario& scenario) {
  if (!options.checkpointEvery) return std::int64_t(0);
  const double every = *options.checkpointEvery;
  const double steps = std::round(every / double(scenario.simulation.dt));
  if (!std::isfinite(every) || every <= 0 || steps < 1 || steps > 1e9) {
    std::cerr << "heartsim: error: --checkpoint-every: must be a number of seconds of at least one step (simulation.dt = "
              << scenario.simulation.dt << " s), got " << every << '\n';
    return std::nullopt;
  }
  return static_cast<std::int64_t>(steps);
}

}  // namespace hs::app
