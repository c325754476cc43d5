// Keys as events: a tap (press and release between two frames) is seen once; held keys repeat
// only for stepping and the brush; a release alone does nothing; Esc quits.
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "viewer/app/viewer_keys.h"

namespace hs::viewer {
namespace {

TEST(ViewerKeys, ATapBetweenTwoFramesIsNotLost) {
  KeyEvents events;
  events.push(GLFW_KEY_SPACE, GLFW_PRESS, 0);
  events.push(GLFW_KEY_SPACE, GLFW_RELEASE, 0);  // released before the frame reads the keys
  ViewerControls controls;
  ASSERT_TRUE(controls.playing);
  const std::vector<KeyPress> presses = events.take();
  ASSERT_EQ(presses.size(), 1u);
  EXPECT_FALSE(applyKeys(presses, controls, true));
  EXPECT_FALSE(controls.playing);
  EXPECT_TRUE(events.take().empty()) << "a press is read by one frame only";
}

TEST(ViewerKeys, TwoTapsInOneFrameCountTwice) {
  KeyEvents events;
  for (int i = 0; i < 2; ++i) {
    events.push(GLFW_KEY_H, GLFW_PRESS, 0);
    events.push(GLFW_KEY_H, GLFW_RELEASE, 0);
  }
  ViewerControls controls;
  applyKeys(events.take(), controls, true);
  EXPECT_FALSE(controls.showHelp) << "opened and closed again";
}

TEST(ViewerKeys, HeldKeysRepeatOnlyWhereRepeatingMeansSomething) {
  KeyEvents events;
  events.push(GLFW_KEY_RIGHT_BRACKET, GLFW_PRESS, 0);
  events.push(GLFW_KEY_RIGHT_BRACKET, GLFW_REPEAT, 0);
  events.push(GLFW_KEY_N, GLFW_PRESS, 0);
  events.push(GLFW_KEY_N, GLFW_REPEAT, 0);  // a held N toggles once
  ViewerControls controls;
  const float brush = controls.region.brushRadiusPx;
  ASSERT_TRUE(controls.showLabels);
  applyKeys(events.take(), controls, true);
  EXPECT_FLOAT_EQ(controls.region.brushRadiusPx, brush * 1.25f * 1.25f);
  EXPECT_FALSE(controls.showLabels);
}

TEST(ViewerKeys, TheBrushStaysInItsRangeAndPaintNeedsAWall) {
  KeyEvents events;
  for (int i = 0; i < 40; ++i) events.push(GLFW_KEY_LEFT_BRACKET, GLFW_PRESS, 0);
  events.push(GLFW_KEY_B, GLFW_PRESS, 0);
  ViewerControls controls;
  applyKeys(events.take(), controls, /*paintAvailable=*/false);
  EXPECT_FLOAT_EQ(controls.region.brushRadiusPx, RegionControls::kMinBrushPx);
  EXPECT_FALSE(controls.region.paintMode);
}

TEST(ViewerKeys, EscapeQuitsAndEnterApplies) {
  ViewerControls controls;
  const KeyPress enter{GLFW_KEY_ENTER, false, false}, escape{GLFW_KEY_ESCAPE, false, false};
  EXPECT_FALSE(applyKeys(std::vector{enter}, controls, true));
  EXPECT_TRUE(controls.region.applyRequested);
  EXPECT_TRUE(applyKeys(std::vector{escape}, controls, true));
}

TEST(ViewerKeys, F5SavesTheState) {
  ViewerControls controls;
  EXPECT_FALSE(applyKeys(std::vector{KeyPress{GLFW_KEY_F5, false, false}}, controls, true));
  EXPECT_TRUE(controls.saveStateRequested);
  controls.saveStateRequested = false;
  applyKeys(std::vector{KeyPress{GLFW_KEY_F5, true, false}}, controls, true);
  EXPECT_FALSE(controls.saveStateRequested) << "a held F5 writes one checkpoint, not one per repeat";
}

TEST(ViewerKeys, EscapeClosesAnOpenWindowBeforeItQuits) {
  ViewerControls controls;
  controls.showHelp = controls.pump.showCompare = true;
  const KeyPress escape{GLFW_KEY_ESCAPE, false, false};
  EXPECT_FALSE(applyKeys(std::vector{escape}, controls, true));
  EXPECT_FALSE(controls.showHelp);
  EXPECT_TRUE(controls.pump.showCompare);
  EXPECT_FALSE(applyKeys(std::vector{escape}, controls, true));
  EXPECT_FALSE(controls.pump.showCompare);
  EXPECT_TRUE(applyKeys(std::vector{escape}, controls, true));
}

TEST(ViewerKeys, AQueueNoFrameReadsStaysBounded) {
  KeyEvents events;
  for (int i = 0; i < 10000; ++i) events.push(GLFW_KEY_S, GLFW_REPEAT, 0);
  EXPECT_LE(events.take().size(), 256u);
}

}  // namespace
}  // namespace hs::viewer
