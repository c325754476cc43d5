// Gmsh meshes: any bytes as a .msh file. A mesh that reads is summarised (quality, volumes,
// boundary loops); anything but the reader's one-line std::invalid_argument is a bug.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "io/mesh/mesh_import.h"
#include "io/mesh/mesh_summary.h"
#include "one_line.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    (void)hs::io::summarizeMesh(hs::io::parseGmsh(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.msh"));
  } catch (const std::invalid_argument& e) {
    hs::fuzz::requireOneLine(e.what());
  }
  return 0;
}
