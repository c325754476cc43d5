#pragma once
// `heartsim mesh FILE [--json]`: reads a patient mesh in any supported format (io/mesh_import.h)
// and prints what it holds: counts, bounding box and a guess of its unit, markers, the volume
// and worst quality of its tetrahedra, or for a surface its enclosed volume or boundary loops.
// Exit 2 with the reader's one-line error on bad input.
#include <string>

namespace hs::app {

struct MeshOptions {
  std::string file;
  bool json = false;
};

int meshCommand(const MeshOptions& options);

}  // namespace hs::app
