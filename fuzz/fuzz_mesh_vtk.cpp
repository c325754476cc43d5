// VTK meshes: any bytes as a .vtu file when they start with '<', else as a legacy .vtk file. A
// mesh that reads is summarised; anything but the reader's one-line std::invalid_argument is a bug.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "io/mesh/mesh_import.h"
#include "io/mesh/mesh_summary.h"
#include "one_line.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const bool xml = !text.empty() && text[0] == '<';
    (void)hs::io::summarizeMesh(xml ? hs::io::parseVtu(text, "fuzz.vtu") : hs::io::parseLegacyVtk(text, "fuzz.vtk"));
  } catch (const std::invalid_argument& e) {
    hs::fuzz::requireOneLine(e.what());
  }
  return 0;
}
