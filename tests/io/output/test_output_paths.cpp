// Default output folders (output_paths.h): whatever a scenario is named, its files go to a
// folder directly inside results/.
#include <gtest/gtest.h>

#include <cctype>

#include "io/output/output_paths.h"

namespace hs::io {
namespace {

TEST(OutputPaths, OrdinaryNamesAreKept) {
  EXPECT_EQ(safeFileStem("normal"), "normal");
  EXPECT_EQ(safeFileStem("paper-chamber-beating"), "paper-chamber-beating");
  EXPECT_EQ(safeFileStem("My_Lesson2"), "My_Lesson2");
  EXPECT_EQ(defaultOutputFolder("normal"), std::filesystem::path("results") / "normal");
}

TEST(OutputPaths, NamesThatWouldLeaveResultsStayInsideIt) {
  for (const char* name : {"..", "../..", "/tmp/x", "a/../../b", "a\"b", "a\nb", "a'b", "~", ".", "a b", "\\x"}) {
    const std::filesystem::path folder = defaultOutputFolder(name);
    const std::string stem = folder.filename().string();
    EXPECT_EQ(folder.parent_path(), std::filesystem::path("results")) << name;
    EXPECT_FALSE(stem.empty()) << name;
    for (const char c : stem)
      EXPECT_TRUE(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') << name << " -> " << stem;
  }
  EXPECT_EQ(safeFileStem(".."), "__");
  EXPECT_EQ(safeFileStem("/tmp/x"), "_tmp_x");
}

TEST(OutputPaths, AnEmptyNameGetsOne) { EXPECT_EQ(safeFileStem(""), "scenario"); }

}  // namespace
}  // namespace hs::io
