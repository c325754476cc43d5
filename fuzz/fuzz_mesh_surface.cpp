// Surface meshes through Assimp: the first byte picks the format (its value mod 4: obj, stl,
// ply, off), the rest is the file. A mesh that reads is summarised; anything but the reader's
// one-line std::invalid_argument is a bug. Assimp itself is Debian's build, not instrumented:
// ASan sees its crashes, not its out-of-bounds reads.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "io/mesh/mesh_import.h"
#include "io/mesh/mesh_summary.h"
#include "one_line.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* const kExtensions[4] = {"obj", "stl", "ply", "off"};
  const std::string extension = kExtensions[data[0] % 4];
  try {
    (void)hs::io::summarizeMesh(hs::io::parseSurface(std::string_view(reinterpret_cast<const char*>(data + 1), size - 1),
                                                     extension, "fuzz." + extension));
  } catch (const std::invalid_argument& e) {
    hs::fuzz::requireOneLine(e.what());
  }
  return 0;
}
