// The liquid look's pacer (viewer/app/liquid_pacer.h): fast frames keep full resolution; slow ones
// lower it a step per judged window, to a third at most, and the note says what and why.
#include <gtest/gtest.h>

#include "viewer/app/liquid_pacer.h"

namespace hs::viewer {
namespace {

void frames(LiquidPacer& pacer, int count, double ms, bool liquid = true) {
  for (int i = 0; i < count; ++i) pacer.observe(ms, liquid);
}

TEST(LiquidPacer, FastFramesKeepFullResolution) {
  LiquidPacer pacer;
  EXPECT_TRUE(pacer.note().empty());
  frames(pacer, LiquidPacer::kSkipFrames + 3 * LiquidPacer::kWindow, 30);
  EXPECT_EQ(pacer.downsample(), 1);
  EXPECT_EQ(pacer.note(), "liquid look: full resolution; now 30 ms");
}

TEST(LiquidPacer, SlowFramesLowerTheResolutionAndSayWhy) {
  LiquidPacer pacer;
  frames(pacer, LiquidPacer::kSkipFrames, 500);  // start-up: not judged
  EXPECT_EQ(pacer.downsample(), 1);
  frames(pacer, LiquidPacer::kWindow, 60);
  EXPECT_EQ(pacer.downsample(), 2);
  EXPECT_EQ(pacer.note(), "liquid look: 1/2 resolution for 25 fps (60 ms a frame at full)");
  frames(pacer, LiquidPacer::kWindow, 35);  // fast enough now: stays
  EXPECT_EQ(pacer.downsample(), 2);
  EXPECT_EQ(pacer.note(), "liquid look: 1/2 resolution for 25 fps (60 ms a frame at full); now 35 ms");
  frames(pacer, LiquidPacer::kWindow, 45);
  frames(pacer, LiquidPacer::kWindow, 45);
  frames(pacer, LiquidPacer::kWindow, 45);
  EXPECT_EQ(pacer.downsample(), LiquidPacer::kCoarsest);
  EXPECT_EQ(pacer.note(), "liquid look: 1/3 resolution for 25 fps (45 ms a frame at 1/2); now 45 ms");
}

TEST(LiquidPacer, AMedianNotAMeanAndSpheresFramesDoNotCount) {
  LiquidPacer pacer;
  frames(pacer, LiquidPacer::kSkipFrames, 20);
  // A few very slow frames (a restart, a screenshot) among fast ones do not lower it.
  frames(pacer, LiquidPacer::kWindow - 3, 20);
  frames(pacer, 3, 400);
  EXPECT_EQ(pacer.downsample(), 1);
  // Slow frames drawn with spheres say nothing about the liquid.
  frames(pacer, 3 * LiquidPacer::kWindow, 90, false);
  EXPECT_EQ(pacer.downsample(), 1);
}

}  // namespace
}  // namespace hs::viewer
