// Lesson files: any bytes as a lesson's TOML text.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "one_line.h"
#include "viewer/lessons/lesson.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    (void)hs::viewer::parseLesson(text, "fuzz.toml");
  } catch (const hs::viewer::LessonError& e) {
    hs::fuzz::requireOneLine(e.what());
  }
  return 0;
}
