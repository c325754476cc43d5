// The circulation panel fed from a running lumped circulation, without a window: the viewer's
// thread records the lumped samples (bounded), the status carries the relations and the last
// beat's figures, and the last complete beat's valve events come in the textbook's order.
#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <thread>

#include "cardiac/circulation/clinical_units.h"
#include "io/scenario/scenario_file.h"
#include "runner_wait.h"
#include "viewer/app/simulation_runner.h"
#include "viewer/plots/circulation_history.h"

namespace hs::viewer {
namespace {

using test_support::waitFor;

// The normal heart with the lumped circulation and no blood: the wall alone steps quickly.
cardiac::Scenario lumpedWall() {
  cardiac::Scenario s = io::loadScenario("normal");
  s.circulation.lumped = true;
  s.blood.enabled = false;
  return s;
}

TEST(ViewerCirculationStatus, ALumpedRunFillsThePanel) {
  SimulationRunner runner(1);
  runner.start(lumpedWall());
  runner.access([](SimulationState& s) { s.speed = 4; });
  // Two beats start: the first is complete.
  ASSERT_TRUE(waitFor(runner, [](SimulationState& s) {
    const cardiac::CirculationRecorder* recorder = s.monitor->circulation();
    return recorder && recorder->beatStarts().size() >= 2;
  }));
  runner.access([](SimulationState& s) { s.playing = false; });
  ViewerStatus status;
  CirculationHistory history;
  runner.access([&](SimulationState& s) {
    readStatus(s, status);
    const cardiac::CirculationRecorder* recorder = s.monitor->circulation();
    history.update(recorder->samples(), recorder->beatStarts());
  });
  const CirculationStatus& c = status.circulation;
  ASSERT_TRUE(c.lumped);
  EXPECT_GT(c.relations.endSystolicElastance, 0);
  EXPECT_GT(c.relations.diastolicScale, 0);
  ASSERT_TRUE(c.lastBeat);
  const double systolic = c.lastBeat->aorticSystolic / cardiac::kPascalPerMmHg;
  const double diastolic = c.lastBeat->aorticDiastolic / cardiac::kPascalPerMmHg;
  EXPECT_GT(systolic, diastolic);
  EXPECT_GT(diastolic, 20);
  EXPECT_LT(systolic, 250);

  const std::optional<BeatSpan> beat = lastCompleteBeat(history.samples(), history.beatStarts());
  ASSERT_TRUE(beat);
  const ValveEvents e =
      valveEvents(std::span(history.samples()).subspan(beat->begin, beat->size()), beat->start);
  ASSERT_TRUE(e.mitralClose && e.aorticOpen && e.aorticClose && e.mitralOpen);
  EXPECT_LE(beat->start, *e.mitralClose);
  EXPECT_LT(*e.mitralClose, *e.aorticOpen);
  EXPECT_LT(*e.aorticOpen, *e.aorticClose);
  EXPECT_LT(*e.aorticClose, *e.mitralOpen);
}

TEST(ViewerCirculationStatus, WithoutTheLumpedCirculationThereIsNoPanel) {
  SimulationRunner runner(1);
  runner.start(io::loadScenario("heart-only"));
  ViewerStatus status;
  status.circulation.lumped = true;  // from a scenario before
  runner.access([&](SimulationState& s) {
    readStatus(s, status);
    EXPECT_EQ(s.monitor->circulation(), nullptr);
  });
  EXPECT_FALSE(status.circulation.lumped);
  EXPECT_FALSE(status.circulation.lastBeat);
}

}  // namespace
}  // namespace hs::viewer
