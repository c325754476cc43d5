// The located TOML parse the scenario and lesson readers share: a syntax error is one line with
// the file, line and column, even when the character it quotes is a control character (found
// by fuzz_lesson: a carriage return quoted raw broke the line on a terminal).
#include <gtest/gtest.h>

#include "io/scenario/scenario_file.h"
#include "io/scenario/toml_text.h"

namespace {

TEST(TomlText, ParsesAndLocatesASyntaxError) {
  EXPECT_TRUE(hs::io::parseTomlText("a = 1\n", "ok.toml").error.empty());
  const hs::io::TomlText bad = hs::io::parseTomlText("a = 1\nb = = 2\n", "bad.toml");
  EXPECT_EQ(bad.error.rfind("bad.toml:2:", 0), 0u) << bad.error;
  EXPECT_NE(bad.error.find("TOML syntax error"), std::string::npos);
}

TEST(TomlText, AQuotedControlCharacterIsEscapedNotPrinted) {
  const hs::io::TomlText bad = hs::io::parseTomlText("x = [i\r-\x04]\n", "cr.toml");
  ASSERT_FALSE(bad.error.empty());
  for (const char c : bad.error) EXPECT_GE(static_cast<unsigned char>(c), 0x20) << bad.error;
  EXPECT_NE(bad.error.find("\\x0d"), std::string::npos) << bad.error;
  // The scenario reader passes it on as it is.
  try {
    (void)hs::io::parseScenario("x = [i\r-\x04]\n", "cr.toml");
    FAIL() << "accepted";
  } catch (const hs::io::ScenarioError& e) {
    EXPECT_EQ(std::string(e.what()).find('\r'), std::string::npos);
  }
}

}  // namespace
