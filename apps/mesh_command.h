#pragma once
// `heartsim mesh FILE [--json]`: reads a patient mesh in any supported format (io/mesh/mesh_import.h)
// and prints what it holds: counts, bounding box and a guess of its unit, markers, the volume
// and worst quality of its tetrahedra, or for a surface its enclosed volume or boundary loops.
// With --wall, also the tetrahedral wall it would build (cardiac/patient/patient_wall.h): its size, worst
// quality, annuli and frame (apps/mesh_wall.cpp).
// Exit 2 with the reader's one-line error on bad input.
#include <string>

namespace hs::app {

struct MeshOptions {
  std::string file;
  bool json = false;
  // --wall and its settings, as typed (checked in mesh_wall.cpp, so that a bad value gets a
  // one-line error naming the file).
  bool wall = false;
  std::string units;        // "mm" or "m"; empty: the unit guessed from the size
  std::string thickness;    // m; empty: 0.010
  std::string resolution = "default";
  std::string septum;       // "x,y,z" in the file's frame; empty: from the annuli
  int mitralLoop = 0, aorticLoop = 0;
  std::string epicardium;   // a second surface file; empty: the file's EPI marker, if any
};

int meshCommand(const MeshOptions& options);

}  // namespace hs::app
