// `heartsim view` under a virtual X server (Xvfb): scripted with --frames and --screenshot it
// opens its window, runs, and saves a PNG that shows the heart (the wall's red) or the blood;
// without a display it stops with exit 1 and one line pointing to `heartsim render`; a bad
// --size or scenario stops it with exit 2 before any window is opened.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "cli_runner.h"
#include "viz/image.h"
#include "xvfb_fixture.h"

namespace {

using hs::testing::CliResult;
using hs::testing::runHeartsim;
using hs::testing::scratchDir;
namespace fs = std::filesystem;

// One Xvfb server per test process (xvfb_fixture.h).
using ViewUnderXvfb = hs::testing::XvfbFixture;
using hs::testing::ScopedDisplay;

double variance(const hs::viz::Image& image) {
  double sum = 0, sumSq = 0;
  for (const std::uint8_t v : image.pixels()) {
    sum += v;
    sumSq += double(v) * v;
  }
  const double n = double(image.pixels().size());
  return sumSq / n - (sum / n) * (sum / n);
}

template <class Pred>
int countPixels(const hs::viz::Image& image, Pred pred) {
  int n = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) n += pred(image.at(x, y)) ? 1 : 0;
  return n;
}

bool wallRed(hs::viz::Rgb c) { return c.r > 110 && c.r > c.g + 60 && c.r > c.b + 50; }
bool bloodBlue(hs::viz::Rgb c) { return c.b > 120 && c.b > c.r + 60 && c.b > c.g + 30; }

TEST_F(ViewUnderXvfb, HeartOnlyScreenshotShowsTheWall) {
  const fs::path dir = scratchDir("view_heart");
  const CliResult r = view("heart-only --frames 60 --screenshot s.png --size 640x480", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  ASSERT_TRUE(fs::exists(dir / "s.png")) << r.err;
  const hs::viz::Image image = hs::viz::Image::loadPng((dir / "s.png").string());
  EXPECT_EQ(image.width(), 640);
  EXPECT_EQ(image.height(), 480);
  EXPECT_GT(variance(image), 200.0);
  // The wall covers a good part of the scene beside the panel.
  EXPECT_GT(countPixels(image, wallRed), 640 * 480 / 20);
}

// A checkpoint written by `heartsim run` opens in the viewer, which goes on from its state.
TEST_F(ViewUnderXvfb, ResumedCheckpointShowsTheWall) {
  const fs::path dir = scratchDir("view_resume");
  const CliResult made = runHeartsim("run heart-only --duration 0.1 --checkpoint-every 0.1 --out made", dir);
  ASSERT_EQ(made.exitCode, 0) << made.err;
  const CliResult r = view("--resume made/checkpoint_0000.100s.hsck --frames 30 --screenshot s.png --size 640x480", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const hs::viz::Image image = hs::viz::Image::loadPng((dir / "s.png").string());
  EXPECT_GT(countPixels(image, wallRed), 640 * 480 / 20);
}

// A bad checkpoint stops the viewer with exit 2 and one line before any window is opened.
TEST(ViewCommand, BadCheckpointExitsTwoWithoutAWindow) {
  const fs::path dir = scratchDir("view_bad_resume");
  std::ofstream(dir / "bad.hsck") << "not a checkpoint";
  const CliResult r = runHeartsim("view --resume bad.hsck --frames 1", dir);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("bad.hsck: bad magic"), std::string::npos) << r.err;
}

TEST_F(ViewUnderXvfb, FluidAtRestScreenshotShowsTheBlood) {
  const fs::path dir = scratchDir("view_fluid");
  const CliResult r = view("fluid-at-rest --frames 20 --screenshot s.png --size 640x480", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const hs::viz::Image image = hs::viz::Image::loadPng((dir / "s.png").string());
  EXPECT_GT(variance(image), 200.0);
  EXPECT_GT(countPixels(image, bloodBlue), 640 * 480 / 20);
  // No heart in this scenario: only the panel's few orange or red letters.
  EXPECT_LT(countPixels(image, wallRed), 640 * 480 / 200);
}

// Blood in the speed palette (blue through cyan and green to yellow), not the grey-blue
// background or the red wall.
bool bloodPalette(hs::viz::Rgb c) {
  const bool blueOrCyan = c.b > 120 && c.b > c.r + 60;
  const bool green = c.g > c.r + 40 && c.g > c.b + 40;
  const bool yellow = c.r > 180 && c.g > 180 && c.b < 100;
  return blueOrCyan || green || yellow;
}

// The issue's own check: the physiological scenario after 120 frames shows heart and blood.
TEST_F(ViewUnderXvfb, NormalScreenshotShowsHeartAndBlood) {
  const fs::path dir = scratchDir("view_normal");
  const CliResult r = view("normal --frames 120 --screenshot s.png --size 1280x800", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const hs::viz::Image image = hs::viz::Image::loadPng((dir / "s.png").string());
  EXPECT_GT(variance(image), 200.0);
  EXPECT_GT(countPixels(image, wallRed), 1280 * 800 / 50);
  // The panels' light-blue buttons alone are about 2% of the window; `normal` has the lumped
  // circulation, whose pressure-volume strip takes the lower third of the 3D view, and its
  // blood covers about 5%.
  EXPECT_GT(countPixels(image, bloodPalette), 1280 * 800 / 25);
}

TEST_F(ViewUnderXvfb, BadSizeAndUnknownScenarioAreRejectedWithOneLine) {
  const fs::path dir = scratchDir("view_bad");
  for (const std::string args :
       {"heart-only --size 12x9000", "heart-only --size big", "no-such-scenario --frames 1"}) {
    const CliResult r = view(args, dir);
    EXPECT_EQ(r.exitCode, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

// --resolution takes a level or auto; anything else is one line and exit 2, before a window.
TEST(ViewWithoutDisplay, BadResolutionIsExitTwoWithOneLine) {
  const fs::path dir = scratchDir("view_bad_resolution");
  ScopedDisplay none(std::nullopt);
  for (const std::string bad : {"ultra", "Fine", "0"}) {
    const CliResult r = runHeartsim("view normal --frames 1 --resolution " + bad, dir);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("--resolution: '" + bad + "'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("coarse, medium, fine, finest or auto"), std::string::npos) << r.err;
  }
}

// --blood-look, --flow and --labels name their valid values; checked before any window.
TEST(ViewWithoutDisplay, UnknownLookFlowViewAndLabelSetAreExitTwoWithOneLine) {
  const fs::path dir = scratchDir("view_bad_display_options");
  ScopedDisplay none(std::nullopt);
  struct Case {
    std::string args, message;
  };
  for (const Case& c : {Case{"--blood-look glass", "--blood-look: unknown look 'glass'; valid: liquid, spheres"},
                        Case{"--flow vortices", "--flow: unknown flow view 'vortices'; valid: off, streaks, arrows"},
                        Case{"--labels all", "--labels: unknown label set 'all'; valid: off, anatomy"}}) {
    const CliResult r = runHeartsim("view normal --frames 1 " + c.args, dir);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
  }
}

// A level given runs at once (no start-up measurement): the last line counts its particles.
TEST_F(ViewUnderXvfb, ResolutionCoarseRunsNormalWithAQuarterOfItsParticles) {
  const fs::path dir = scratchDir("view_coarse");
  const CliResult r = view("normal --frames 20 --size 640x480 --resolution coarse", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("real time (stepping"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(", 1,150 particles\n"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("blood resolution:"), std::string::npos) << r.err;  // nothing measured
}

TEST(ViewWithoutDisplay, ExitsOneSayingADisplayIsNeededAndRenderWorksWithout) {
  const fs::path dir = scratchDir("view_no_display");
  ScopedDisplay none(std::nullopt);
  const CliResult r = runHeartsim("view heart-only --frames 1", dir);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("display"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("heartsim render"), std::string::npos) << r.err;
}

TEST(ViewWithoutDisplay, BadSizeIsStillExitTwo) {
  const fs::path dir = scratchDir("view_no_display_size");
  ScopedDisplay none(std::nullopt);
  const CliResult r = runHeartsim("view heart-only --size 0x0", dir);
  EXPECT_EQ(r.exitCode, 2) << r.err;
}

}  // namespace
