// `heartsim view --lesson`: a bad lesson file stops with exit 2 and one line naming the file,
// line, step and key, before any window is opened (so without a display too); a scripted run
// under Xvfb plays a short lesson by itself and writes one screenshot per step and the final one.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_runner.h"
#include "viz/image.h"
#include "xvfb_fixture.h"

namespace {

using hs::testing::CliResult;
using hs::testing::runHeartsim;
using hs::testing::scratchDir;
using hs::testing::ScopedDisplay;
namespace fs = std::filesystem;
using LessonUnderXvfb = hs::testing::XvfbFixture;  // one Xvfb per test process

void writeFile(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

int lineCount(const std::string& text) { return int(std::count(text.begin(), text.end(), '\n')); }

TEST(LessonCli, BadLessonFileIsExitTwoWithOneLine) {
  const fs::path dir = scratchDir("lesson_bad");
  writeFile(dir / "bad.toml", "[lesson]\ntitle = \"Bad\"\nscenario = \"normal\"\n\n[[step]]\ntext = \"Read.\"\n"
                              "play_beats = 1\nsegments = [1, 19]\n");
  ScopedDisplay none(std::nullopt);  // refused before a window is asked for
  const CliResult r = runHeartsim("view --lesson bad.toml --frames 1", dir);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_EQ(r.err, "heartsim: error: bad.toml:8: step 1: key 'segments': expected AHA segment numbers 1-17, got 19\n");
}

TEST(LessonCli, UnknownKeyAndUnknownLessonAreExitTwo) {
  const fs::path dir = scratchDir("lesson_unknown");
  writeFile(dir / "typo.toml", "[lesson]\ntitle = \"T\"\nscenario = \"normal\"\n[[step]]\ntext = \"t\"\nbeats = 2\n");
  ScopedDisplay none(std::nullopt);
  CliResult r = runHeartsim("view --lesson typo.toml", dir);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("typo.toml:6: step 1: key 'beats': unknown key"), std::string::npos) << r.err;
  r = runHeartsim("view --lesson no-such-lesson", dir);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("regional-wall-motion"), std::string::npos) << r.err;
}

// heart-only: no blood, the thesis's 0.08 s beat, so a beat costs a few frames.
const char* const kShortLesson = R"toml([lesson]
title = "Short"
scenario = "heart-only"

[[step]]
title = "Look"
text = "The wall beats."
play_beats = 1

[[step]]
text = "Now only the lateral wall beats."
segments = [5, 6, 11, 12, 16]
play_beats = 1
result = "done"
[step.predict]
question = "Which wall still moves?"
choices = ["lateral", "septal"]
answer = 1
)toml";

TEST_F(LessonUnderXvfb, ScriptedRunWritesAScreenshotPerStep) {
  const fs::path dir = scratchDir("lesson_scripted");
  writeFile(dir / "short.toml", kShortLesson);
  const CliResult r = view("--lesson short.toml --frames 400 --screenshot s.png --size 800x600", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* name : {"s_step01.png", "s_step02.png", "s.png"}) {
    ASSERT_TRUE(fs::exists(dir / name)) << name << ": " << r.err;
    const hs::viz::Image image = hs::viz::Image::loadPng((dir / name).string());
    EXPECT_EQ(image.width(), 800);
    EXPECT_EQ(image.height(), 600);
  }
  EXPECT_FALSE(fs::exists(dir / "s_step03.png"));
  // It ended with the lesson, long before 400 frames: no "stopped at step" note.
  EXPECT_EQ(r.err.find("the lesson stopped"), std::string::npos) << r.err;
}

TEST_F(LessonUnderXvfb, TooFewFramesSaySoAndStillSaveTheLastOne) {
  const fs::path dir = scratchDir("lesson_few_frames");
  writeFile(dir / "short.toml", kShortLesson);
  const CliResult r = view("--lesson short.toml --frames 2 --screenshot s.png --size 640x480", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "s.png"));
  EXPECT_FALSE(fs::exists(dir / "s_step01.png"));
  EXPECT_NE(r.err.find("the lesson stopped at step 1 of 2 when the 2 frames ran out"), std::string::npos) << r.err;
}

}  // namespace
