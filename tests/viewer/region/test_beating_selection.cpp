// The beating region being chosen: it starts as what the scenario's cycle makes beat, segment
// clicks fill and empty segments, painting takes the wall through its thickness and never the
// base plate, vessels or pinned ends, and written back into the cycle settings it selects
// exactly the same vertices (cardiac::selectBeatingVertices).
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "cardiac/anatomy/lv_model.h"
#include "cardiac/motion/cardiac_cycle.h"
#include "viewer/region/beating_selection.h"
#include "viewer/region/region_editor.h"

namespace hs::viewer {
namespace {

const cardiac::LvModel& model() {
  static const cardiac::LvModel m = cardiac::buildLvModel({});
  return m;
}

std::vector<std::uint8_t> flagsOf(const std::vector<cardiac::Index>& ids) {
  std::vector<std::uint8_t> flags(model().mesh.vertices.size(), 0);
  for (const cardiac::Index v : ids) flags[v] = 1;
  return flags;
}

// What the cycle would beat with the selection written into it.
std::vector<std::uint8_t> roundTrip(const BeatingSelection& selection) {
  cardiac::CycleSettings cycle;
  selection.writeTo(cycle);
  return flagsOf(cardiac::selectBeatingVertices(cycle, model()));
}

TEST(RegionSelection, StartsAsWhatTheScenarioBeats) {
  const BeatingSelection all(model(), {});
  EXPECT_TRUE(all.isAllMyocardium());
  EXPECT_EQ(all.flags(), flagsOf(cardiac::selectBeatingVertices({}, model())));
  for (int s = 1; s <= 17; ++s) EXPECT_EQ(all.segmentState(s), SegmentState::Full) << "segment " << s;

  cardiac::CycleSettings cycle;
  cycle.segments = {1, 2, 7};
  const BeatingSelection some(model(), cycle);
  EXPECT_EQ(some.flags(), flagsOf(cardiac::selectBeatingVertices(cycle, model())));
  EXPECT_EQ(some.segmentState(1), SegmentState::Full);
  EXPECT_EQ(some.segmentState(7), SegmentState::Full);
  EXPECT_EQ(some.segmentState(3), SegmentState::None);
  EXPECT_LT(some.count(), all.count());
}

TEST(RegionSelection, OnlyMyocardiumThatIsNotPinnedCanBeChosen) {
  const BeatingSelection selection(model(), {});
  for (std::size_t v = 0; v < model().mesh.vertices.size(); ++v)
    EXPECT_EQ(bool(selection.selectable()[v]), model().region[v] == cardiac::Region::Myocardium) << v;
  for (const cardiac::Index id : model().pinned) EXPECT_FALSE(selection.selectable()[id]);
  BeatingSelection painted(model(), {});
  painted.clear();
  std::vector<std::uint32_t> everything(model().mesh.vertices.size());
  for (std::size_t v = 0; v < everything.size(); ++v) everything[v] = std::uint32_t(v);
  painted.paint(everything, true);
  EXPECT_TRUE(painted.isAllMyocardium());
  EXPECT_EQ(painted.count(), selection.selectableCount());
}

TEST(RegionSelection, PaintingTakesTheWallThroughItsThickness) {
  // The shell's partners 2i (cavity side) and 2i+1 (outside) share region and segment, so a
  // painted vertex brings its partner along.
  for (std::size_t v = 0; v + 1 < model().mesh.vertices.size(); v += 2) {
    ASSERT_EQ(model().region[v], model().region[v + 1]) << v;
    ASSERT_EQ(model().segment[v], model().segment[v + 1]) << v;
  }
  BeatingSelection selection(model(), {});
  selection.clear();
  EXPECT_TRUE(selection.empty());
  std::uint32_t outside = 1;
  while (!selection.selectable()[outside]) outside += 2;
  selection.paint({outside}, true);
  EXPECT_EQ(selection.count(), 2u);
  EXPECT_TRUE(selection.flags()[outside - 1]);
  EXPECT_EQ(selection.segmentState(model().segment[outside]), SegmentState::Partial);
  selection.paint({outside - 1}, false);  // erasing the cavity side takes the outside too
  EXPECT_TRUE(selection.empty());
}

TEST(RegionSelection, SegmentClicksFillAndEmptySegments) {
  BeatingSelection selection(model(), {});
  selection.clear();
  selection.toggleSegment(7);
  EXPECT_EQ(selection.segmentState(7), SegmentState::Full);
  cardiac::CycleSettings only7;
  only7.segments = {7};
  EXPECT_EQ(selection.flags(), flagsOf(cardiac::selectBeatingVertices(only7, model())));
  selection.toggleSegment(7);
  EXPECT_TRUE(selection.empty());
  // A segment painted in part is filled by a click.
  std::uint32_t v = 0;
  while (model().segment[v] != 13 || !selection.selectable()[v]) ++v;
  selection.paint({v}, true);
  EXPECT_EQ(selection.segmentState(13), SegmentState::Partial);
  selection.toggleSegment(13);
  EXPECT_EQ(selection.segmentState(13), SegmentState::Full);
  selection.toggleSegment(0);  // out of range: nothing
  selection.toggleSegment(18);
  EXPECT_EQ(selection.segmentState(13), SegmentState::Full);
}

TEST(RegionSelection, WrittenIntoTheCycleItSelectsTheSameVertices) {
  BeatingSelection selection(model(), {});
  selection.clear();
  selection.toggleSegment(1);
  selection.toggleSegment(17);
  std::vector<std::uint32_t> painted;
  for (std::uint32_t v = 0; v < model().mesh.vertices.size() && painted.size() < 9; ++v)
    if (selection.selectable()[v] && model().segment[v] == 10) painted.push_back(v);
  selection.paint(painted, true);
  cardiac::CycleSettings cycle;
  cycle.sphereEnabled = true;
  selection.writeTo(cycle);
  EXPECT_EQ(cycle.segments, (std::vector<int>{1, 17}));
  EXPECT_FALSE(cycle.sphereEnabled);
  EXPECT_FALSE(cycle.vertices.empty());
  for (const cardiac::Index v : cycle.vertices) EXPECT_EQ(model().segment[v], 10);
  EXPECT_EQ(roundTrip(selection), selection.flags());
  selection.selectAllMyocardium();
  EXPECT_EQ(roundTrip(selection), selection.flags());
}

TEST(RegionSelection, TheEditorAppliesOnlyANonEmptyChangedSelection) {
  cardiac::Scenario scenario;
  const cardiac::HeartSimulation sim(scenario, 1);
  RegionEditor editor;
  RegionControls controls;
  editor.startScenario(sim, controls);
  EXPECT_FALSE(controls.showRegion) << "the whole myocardium beats: nothing singled out";
  controls.clearRequested = true;
  controls.applyRequested = true;
  EXPECT_FALSE(editor.handleRequests(controls)) << "an empty region is not applied";
  EXPECT_TRUE(controls.showRegion);
  EXPECT_FALSE(controls.clearRequested || controls.applyRequested);
  controls.segmentToggled = 4;
  EXPECT_FALSE(editor.handleRequests(controls));
  RegionStatus status;
  editor.fillStatus(status, true);
  EXPECT_TRUE(status.pending);
  EXPECT_EQ(status.segments[4], SegmentState::Full);
  controls.applyRequested = true;
  EXPECT_TRUE(editor.handleRequests(controls));
  cardiac::Scenario configured = scenario;
  editor.configure(configured);
  EXPECT_EQ(configured.cycle.segments, (std::vector<int>{4}));
  EXPECT_TRUE(configured.cycle.vertices.empty());
  editor.fillStatus(status, true);
  EXPECT_FALSE(status.pending);
  EXPECT_EQ(editor.highlight(controls), editor.selection().flags());
  controls.showRegion = false;
  EXPECT_TRUE(editor.highlight(controls).empty());
}

}  // namespace
}  // namespace hs::viewer
