// The viewer's simulation thread, without a window: it steps a built-in scenario while the
// test thread reads it through access(), records one plot sample per step, pauses after a
// single step, starts over on a restart, keeps the running simulation when a restart is
// rejected, and stops cleanly when destroyed.
#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "io/scenario/scenario_file.h"
#include "runner_wait.h"
#include "viewer/app/simulation_runner.h"
#include "viewer/plots/plot_history.h"

namespace hs::viewer {
namespace {

// A shorter time-out than the default: these runs are small.
bool waitFor(SimulationRunner& runner, const std::function<bool(SimulationState&)>& done) {
  return test_support::waitFor(runner, done, 120);
}

TEST(ViewerSimulationRunner, StepsInItsThreadAndRecordsThePump) {
  const cardiac::Scenario scenario = io::loadScenario("paper-chamber-beating");
  const double dt = double(scenario.simulation.dt);
  SimulationRunner runner(1);
  runner.start(scenario);
  PlotHistory history(100);
  std::vector<PumpSample> samples;
  runner.access([](SimulationState& s) { s.speed = 4; });
  // Two thesis beats are 32 steps: a complete beat needs the next systole's start.
  ASSERT_TRUE(waitFor(runner, [&](SimulationState& s) {
    for (const PumpSample& p : s.newSamples) samples.push_back(p);
    s.newSamples.clear();
    return s.sim->stepCount() >= 40;
  }));
  runner.access([](SimulationState& s) { s.playing = false; });
  ASSERT_GE(samples.size(), 40u);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    EXPECT_NEAR(samples[i].time, double(i + 1) * dt, 1e-9) << "one sample per step, none lost";
    EXPECT_GT(samples[i].cavity, 1.0) << "thesis scale: m^3";
    history.push(samples[i]);
  }
  EXPECT_EQ(history.size(), samples.size());
  runner.access([](SimulationState& s) {
    ASSERT_TRUE(s.pump);
    EXPECT_GE(s.pump->readings().beatsCompleted, 1);
  });
}

TEST(ViewerSimulationRunner, StepPausesAndRestartStartsOver) {
  const cardiac::Scenario scenario = io::loadScenario("heart-only");
  SimulationRunner runner(1);
  runner.start(scenario);
  runner.access([](SimulationState& s) {
    s.playing = false;
    s.stepRequested = true;
  });
  ASSERT_TRUE(waitFor(runner, [](SimulationState& s) { return !s.stepRequested; }));
  // Paused after the one step: time stays.
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  runner.access([](SimulationState& s) {
    EXPECT_EQ(s.sim->stepCount(), 1);
    EXPECT_FALSE(s.playing);
    ASSERT_EQ(s.newSamples.size(), 1u);
    s.newSamples.clear();
    s.playing = true;
  });
  ASSERT_TRUE(waitFor(runner, [](SimulationState& s) { return s.sim->stepCount() >= 5; }));

  runner.start(scenario);  // Reset
  runner.access([](SimulationState& s) {
    EXPECT_LT(s.sim->stepCount(), 5);
    for (const PumpSample& p : s.newSamples) EXPECT_LT(p.time, 5 * double(s.sim->scenario().simulation.dt));
  });

  // A rejected restart keeps the simulation running.
  cardiac::Scenario bad = scenario;
  bad.cycle.vertices = {999999};  // no such vertex: the cycle rejects it
  EXPECT_THROW(runner.start(bad), std::invalid_argument);
  ASSERT_TRUE(waitFor(runner, [](SimulationState& s) { return s.sim && s.sim->stepCount() >= 3; }));
}

// The same health checks as `heartsim run` (cardiac::RunMonitor): a wall pushed 3 m per step
// folds at the first step, and the runner pauses with the monitor's one line.
TEST(ViewerSimulationRunner, InvalidSimulationPausesWithWhenAndWhere) {
  cardiac::Scenario scenario = io::loadScenario("heart-only");
  scenario.cycle.beatingDisplace = cardiac::Real(3);
  SimulationRunner runner(1);
  runner.start(scenario);
  std::string message;
  ASSERT_TRUE(waitFor(runner, [&](SimulationState& s) {
    message = s.message;
    return !s.message.empty();
  }));
  runner.access([](SimulationState& s) {
    EXPECT_FALSE(s.playing);
    EXPECT_EQ(s.sim->stepCount(), 1);
    EXPECT_TRUE(s.newSamples.empty()) << "a failed step is not plotted";
  });
  for (const char* part : {"simulation became invalid at step 1 ", "inverted", "tet ", "x = ", "; Reset"})
    EXPECT_NE(message.find(part), std::string::npos) << "missing '" << part << "' in: " << message;
}

}  // namespace
}  // namespace hs::viewer

namespace hs::viewer {
namespace {

// The preset list keeps the human-size hearts apart from the thesis's metre-scale models and
// from blood without a heart, each group under a title that says what it is.
TEST(ScenarioChoices, GroupTheHumanHeartsTheThesisModelsAndTheBloodAlone) {
  const std::vector<ScenarioChoice> choices = builtinScenarioChoices();
  const auto groupOf = [&](const std::string& name) {
    for (const ScenarioChoice& c : choices)
      if (c.name == name) return c.group;
    throw std::runtime_error("no scenario " + name);
  };
  for (const char* name : {"normal", "irregular", "inconsistent", "aortic-stenosis", "mitral-regurgitation"})
    EXPECT_EQ(groupOf(name), ScenarioGroup::HumanHeart) << name;
  for (const char* name : {"paper-chamber", "paper-chamber-beating", "paper-vessel", "paper-vessel-beating", "heart-only"})
    EXPECT_EQ(groupOf(name), ScenarioGroup::ThesisModel) << name;
  for (const char* name : {"dam-break", "fluid-at-rest"}) EXPECT_EQ(groupOf(name), ScenarioGroup::BloodOnly) << name;
  for (const ScenarioChoice& c : choices) EXPECT_FALSE(c.description.empty()) << c.name << " has no tooltip";
  EXPECT_NE(std::string(scenarioGroupTitle(ScenarioGroup::ThesisModel)).find("not a human heart"), std::string::npos);
}

}  // namespace
}  // namespace hs::viewer
