#pragma once
// What the two VTK readers share: cells given as types, offsets and connectivity become
// tetrahedra (VTK_TETRA 10) and triangles (VTK_TRIANGLE 5), and a cell-data array of whole
// numbers becomes the triangles' markers.
#include <string>
#include <utility>
#include <vector>

#include "io/mesh/mesh_import.h"

namespace hs::io {

struct VtkCells {
  std::vector<long long> types;         // one per cell
  std::vector<long long> offsets;       // cells + 1: cell c's points are connectivity[offsets[c], offsets[c+1])
  std::vector<long long> connectivity;  // point indices (0-based)
  // Cell data with one component, by name.
  std::vector<std::pair<std::string, std::vector<double>>> cellData;
};

// Fills mesh.tets, mesh.triangles and mesh.markers and runs finishMesh (tets numbered by cell).
// Vertex points (1) and lines (3) are skipped; any other cell type is refused by number.
// The markers come from the first cell-data array named like a marker (gmsh:physical,
// CellEntityIds, medit:ref, marker(s), ref, boundary_id, any case) or else the first array,
// that holds whole numbers on every triangle.
void assembleVtkCells(ImportedMesh& mesh, const VtkCells& cells, const std::string& name);

}  // namespace hs::io
