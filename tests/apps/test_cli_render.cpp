// `heartsim render` with no display at all: every requested view and the contact sheet are
// written, are not blank and show the wall's or the blood's colour; bad views, times, sizes
// and output folders stop it with exit 2 and one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "viz/image.h"

namespace {

using hs::testing::CliResult;
using hs::testing::runHeartsim;
using hs::testing::scratchDir;
namespace fs = std::filesystem;

CliResult renderNoDisplay(const std::string& args, const fs::path& dir) {
  return runHeartsim("render " + args, dir);  // the test process itself runs without DISPLAY
}

double variance(const hs::viz::Image& image) {
  double sum = 0, sumSq = 0;
  const auto& p = image.pixels();
  for (std::uint8_t v : p) {
    sum += v;
    sumSq += double(v) * v;
  }
  const double n = double(p.size());
  return sumSq / n - (sum / n) * (sum / n);
}

template <class Pred>
int countPixels(const hs::viz::Image& image, Pred pred) {
  int n = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) n += pred(image.at(x, y));
  return n;
}

bool wallRed(hs::viz::Rgb c) { return c.r > 120 && c.r > c.g + 60 && c.r > c.b + 50; }
bool bloodBlue(hs::viz::Rgb c) { return c.b > 120 && c.b > c.r + 60; }

void expectImages(const fs::path& out, const std::vector<std::string>& names, bool (*colour)(hs::viz::Rgb),
                  int w, int h) {
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(fs::exists(out / name));
    const hs::viz::Image image = hs::viz::Image::loadPng((out / name).string());
    if (name != "contact_sheet.png") {
      EXPECT_EQ(image.width(), w);
      EXPECT_EQ(image.height(), h);
    }
    EXPECT_GT(variance(image), 100.0);
    EXPECT_GT(countPixels(image, colour), 200);
  }
}

void expectBadInput(const std::string& args, const std::string& mustMention) {
  // One folder per test: ctest runs tests in parallel processes.
  const auto dir = scratchDir(std::string("render_bad_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  const CliResult r = renderNoDisplay(args, dir);
  EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(mustMention), std::string::npos) << "missing '" << mustMention << "' in: " << r.err;
}

class CliRender : public ::testing::Test {
 protected:
  void SetUp() override { unsetenv("DISPLAY"); }
};

TEST_F(CliRender, HeartOnlyWritesEveryViewAndTheContactSheetWithoutADisplay) {
  const auto dir = scratchDir("render_heart");
  const CliResult r = renderNoDisplay("heart-only --times 0.08,0 --views front,top --out D --size 320x240", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  expectImages(dir / "D", {"t0_front.png", "t0_top.png", "t0.08_front.png", "t0.08_top.png", "contact_sheet.png"},
               wallRed, 320, 240);
  const hs::viz::Image sheet = hs::viz::Image::loadPng((dir / "D" / "contact_sheet.png").string());
  EXPECT_GT(sheet.width(), 2 * 320);   // two columns
  EXPECT_GT(sheet.height(), 2 * 240);  // two rows
}

// The default times are 0 and the end; a duration single precision holds a little short (0.03 s is 0.029999999)
// still has its end drawn, and the blood at --resolution coarse is drawn too.
TEST_F(CliRender, TheDefaultTimesHoldForAnyDurationAndAResolution) {
  const auto dir = scratchDir("render_duration");
  const CliResult r = renderNoDisplay(
      "fluid-at-rest --set simulation.duration=0.03 --views front --out D --size 160x120 --resolution coarse", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  expectImages(dir / "D", {"t0_front.png", "t0.03_front.png"}, bloodBlue, 160, 120);
}

TEST_F(CliRender, FluidAtRestShowsTheBlood) {
  const auto dir = scratchDir("render_fluid");
  const CliResult r = renderNoDisplay("fluid-at-rest --times 0,0.01 --views front,left --out D --size 320x240", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  expectImages(dir / "D",
               {"t0_front.png", "t0_left.png", "t0.01_front.png", "t0.01_left.png", "contact_sheet.png"},
               bloodBlue, 320, 240);
}

// Origin colours (render/scene.h): violet for blood that started in the ventricle, blue in
// the inflow vessel; the key names them.
bool ventricleViolet(hs::viz::Rgb c) { return c.r > 110 && c.b > 150 && c.g + 50 < c.r && c.g + 50 < c.b; }

TEST_F(CliRender, BloodColouredByOriginOrPressure) {
  const auto dir = scratchDir("render_origin");
  CliResult r = renderNoDisplay("normal --times 0 --views front --blood-colour origin --out O --size 320x240", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  expectImages(dir / "O", {"t0_front.png", "contact_sheet.png"}, ventricleViolet, 320, 240);
  r = renderNoDisplay("normal --times 0.05 --views front --blood-colour pressure --pressure-max 15 --out P --size 320x240",
                      dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  // Blood at 0 mmHg is the bar's blue; the ventricle's systolic pressure paints some of it toward yellow.
  expectImages(dir / "P", {"t0.05_front.png"}, bloodBlue, 320, 240);
  const hs::viz::Image image = hs::viz::Image::loadPng((dir / "P" / "t0.05_front.png").string());
  EXPECT_GT(countPixels(image, [](hs::viz::Rgb c) { return c.g > 150 && c.r > 150 && c.b < 100; }), 50);
}

TEST_F(CliRender, UnknownBloodColourNamesTheValidOnes) {
  expectBadInput("normal --times 0 --blood-colour density --out D",
                 "--blood-colour: unknown colour 'density'; valid: speed, pressure, origin, components, stay");
  expectBadInput("normal --times 0 --pressure-max -1 --out D", "--pressure-max: must be a finite pressure >= 0");
}

// Flow components (render/scene.h): at the first beat's end-diastole (0.834 s) the blood is
// coloured by what it does in that beat's systole, which the render steps on to: green direct
// flow and yellow delayed ejection leave, so both show; the key names the four.
bool directGreen(hs::viz::Rgb c) { return c.g > 110 && c.g > c.r + 50 && c.g > c.b + 40; }
bool delayedYellow(hs::viz::Rgb c) { return c.r > 150 && c.g > 130 && c.b + 80 < c.g; }

TEST_F(CliRender, BloodColouredByFlowComponent) {
  const auto dir = scratchDir("render_components");
  const CliResult r =
      renderNoDisplay("normal --times 0.834 --views front --blood-colour components --out C --size 320x240", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  expectImages(dir / "C", {"t0.834_front.png"}, directGreen, 320, 240);
  const hs::viz::Image image = hs::viz::Image::loadPng((dir / "C" / "t0.834_front.png").string());
  EXPECT_GT(countPixels(image, delayedYellow), 100);
}

// Components and stays need beats sorting the blood: a scenario without a heart has none.
TEST_F(CliRender, ComponentColoursNeedAHeartWithBlood) {
  expectBadInput("dam-break --times 0 --blood-colour components --out D",
                 "--blood-colour components: 'dam-break' has no heart with blood and valves");
  expectBadInput("dam-break --times 0 --blood-colour stay --out D",
                 "--blood-colour stay: 'dam-break' has no heart with blood and valves");
}

TEST_F(CliRender, UnknownLookFlowViewAndLabelSetNameTheValidOnes) {
  expectBadInput("normal --times 0 --blood-look glass --out D", "--blood-look: unknown look 'glass'; valid: liquid, spheres");
  expectBadInput("normal --times 0 --flow vortices --out D",
                 "--flow: unknown flow view 'vortices'; valid: off, streaks, arrows");
  expectBadInput("normal --times 0 --labels all --out D", "--labels: unknown label set 'all'; valid: off, anatomy");
}

// The default look is the liquid: one smooth surface, so neighbouring pixels of the blood differ
// far less than those of the same blood drawn as spheres; streaks and labels draw.
TEST_F(CliRender, LiquidIsTheDefaultLookAndStreaksAndLabelsDraw) {
  const auto dir = scratchDir("render_looks");
  CliResult r = renderNoDisplay("fluid-at-rest --times 0 --views front --out L --size 320x240", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  r = renderNoDisplay("fluid-at-rest --times 0 --views front --blood-look spheres --out S --size 320x240", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto bumpiness = [](const hs::viz::Image& image) {
    long sum = 0;
    int pairs = 0;
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x + 1 < image.width(); ++x) {
        const hs::viz::Rgb a = image.at(x, y), b = image.at(x + 1, y);
        if (!bloodBlue(a) || !bloodBlue(b)) continue;
        sum += std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
        ++pairs;
      }
    return pairs > 0 ? double(sum) / pairs : 1e9;
  };
  const double liquid = bumpiness(hs::viz::Image::loadPng((dir / "L" / "t0_front.png").string()));
  const double spheres = bumpiness(hs::viz::Image::loadPng((dir / "S" / "t0_front.png").string()));
  EXPECT_LT(2 * liquid, spheres) << "liquid " << liquid << ", spheres " << spheres;
  r = renderNoDisplay("normal --times 0.02 --views front --flow streaks --labels anatomy --out F --size 320x240", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const hs::viz::Image flow = hs::viz::Image::loadPng((dir / "F" / "t0.02_front.png").string());
  // The labels' paper boxes are white; the streaks carry the speed key's colours.
  EXPECT_GT(countPixels(flow, [](hs::viz::Rgb c) { return c == hs::viz::Rgb{255, 255, 255}; }), 300);
  EXPECT_GT(countPixels(flow, bloodBlue), 50);
}

TEST_F(CliRender, UnknownViewNamesTheValidOnes) {
  expectBadInput("heart-only --times 0 --views front,back --out D", "unknown view 'back'; valid views: front, left, right, top");
}

TEST_F(CliRender, NegativeTimeIsRejected) { expectBadInput("heart-only --times 0,-0.5 --out D", "-0.5 s is negative"); }

TEST_F(CliRender, TimeBeyondTheDurationIsRejected) {
  expectBadInput("heart-only --times 0,5 --out D", "beyond the scenario's duration of 2 s");
}

TEST_F(CliRender, TimeThatIsNotANumberIsRejected) {
  expectBadInput("heart-only --times 0,abc --out D", "'abc' is not a time");
  expectBadInput("heart-only --times nan --out D", "'nan' is not a time");
}

TEST_F(CliRender, BadSizeIsRejected) { expectBadInput("heart-only --times 0 --size 800 --out D", "--size: '800'"); }

// A write failure, exit 1 as for run (not bad input).
TEST_F(CliRender, UnwritableOutputFolderIsAWriteFailure) {
  const auto dir = scratchDir("render_unwritable");
  { std::ofstream(dir / "a_file") << "x"; }
  const CliResult r = renderNoDisplay("heart-only --times 0 --out '" + (dir / "a_file" / "sub").string() + "'", dir);
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("cannot create output directory"), std::string::npos) << r.err;
}

}  // namespace

namespace {

// --e-vortex: the E-wave filling vortex in the long-axis cut (render/vortex_cut.h), drawn on the
// CPU: both signs of vorticity (red and blue), the ring's figures in summary-like words.
TEST_F(CliRender, EVortexDrawsTheLongAxisCutAtTheFirstEPeak) {
  const auto dir = scratchDir("render_e_vortex");
  const CliResult r = renderNoDisplay("normal --resolution coarse --threads 1 --e-vortex 1 --size 400x400 --out out", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const fs::path file = dir / "out" / "e_vortex_beat1.png";
  ASSERT_TRUE(fs::exists(file)) << r.err;
  const hs::viz::Image image = hs::viz::Image::loadPng(file.string());
  EXPECT_GT(countPixels(image, [](hs::viz::Rgb c) { return c.r > 150 && c.r > c.b + 80; }), 20);
  EXPECT_GT(countPixels(image, [](hs::viz::Rgb c) { return c.b > 150 && c.b > c.r + 80; }), 20);
  EXPECT_NE(r.err.find("the E-wave vortex of beat 1"), std::string::npos) << r.err;
}

TEST_F(CliRender, EVortexBeatBelowOneIsRejected) {
  expectBadInput("normal --e-vortex 0 --out D", "--e-vortex: beat 0 is not a beat");
}

TEST_F(CliRender, EVortexWithoutALumpedCirculationIsRejected) {
  expectBadInput("heart-only --e-vortex 1 --out D", "has no lumped circulation with blood");
}

TEST_F(CliRender, EVortexBeyondTheRunIsAFailureThatSaysSo) {
  const auto dir = scratchDir("render_e_vortex_short");
  const CliResult r = renderNoDisplay(
      "normal --resolution coarse --threads 1 --e-vortex 3 --set simulation.duration=0.1 --out out", dir);
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("before beat 3's early filling ended"), std::string::npos) << r.err;
}

}  // namespace
