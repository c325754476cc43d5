// TetGen meshes: any bytes as "<.node text>\0<.ele text>\0<.face text>" (a missing part is an
// empty file; an empty .face means none). A mesh that reads is summarised; anything but the
// reader's one-line std::invalid_argument is a bug.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "io/mesh/mesh_import.h"
#include "io/mesh/mesh_summary.h"
#include "one_line.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view rest(reinterpret_cast<const char*>(data), size);
  std::string_view parts[3];
  for (std::string_view& part : parts) {
    const std::size_t end = rest.find('\0');
    part = rest.substr(0, end);
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
  }
  try {
    (void)hs::io::summarizeMesh(hs::io::parseTetgen(parts[0], parts[1], parts[2], "fuzz"));
  } catch (const std::invalid_argument& e) {
    hs::fuzz::requireOneLine(e.what());
  }
  return 0;
}
