#pragma once
// Patient meshes from CT/MRI pipelines, read into plain engine types: vertices, triangles,
// tetrahedra, and the file's named surface groups (markers). One reader per format family:
//   surfaces  .obj .stl .ply .off    through Assimp (mesh_surface.cpp)
//   Gmsh      .msh 2.2 and 4.1 ASCII  (mesh_gmsh.cpp)
//   TetGen    .node/.ele/.face       (mesh_tetgen.cpp)
//   VTK       .vtu XML, legacy .vtk  (mesh_vtu.cpp, mesh_vtk_legacy.cpp)
// Every bad input is a std::invalid_argument with one line: "FILE:LINE: what was expected"
// (or "FILE: element N: ..."), which the apps turn into exit code 2.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "pbd/core/tet_mesh.h"

namespace hs::io {

// A surface group of the file: Gmsh physical group, TetGen face marker, VTK cell-data value on
// triangles, OBJ group/object. `number` is -1 where the file gives only a name (OBJ), `name`
// empty where it gives only a number (TetGen). Triangles index ImportedMesh::triangles.
struct SurfaceMarker {
  std::string name;
  int number = -1;
  std::vector<pbd::Index> triangles;
};

struct ImportedMesh {
  std::vector<pbd::Vec3> vertices;
  std::vector<pbd::Triangle> triangles;  // a surface mesh, or the marked faces of a volume mesh
  std::vector<pbd::Tet> tets;            // positively oriented (checked)
  std::vector<SurfaceMarker> markers;    // in the order of their first appearance or number
  std::string format;                    // e.g. "gmsh 4.1 ascii", "tetgen", "vtu binary", "obj"
};

// Reads any supported format, chosen by the extension (case-insensitive). For TetGen, FILE may
// be the .node, .ele or .face file: the other two are found beside it (.face is optional).
ImportedMesh readMesh(const std::filesystem::path& file);

// The readers on text in memory (the fuzz targets and tests use them); `name` labels errors.
ImportedMesh parseGmsh(std::string_view text, const std::string& name);
ImportedMesh parseTetgen(std::string_view nodeText, std::string_view eleText, std::string_view faceText,
                         const std::string& stem);  // faceText empty: no .face
ImportedMesh parseVtu(std::string_view text, const std::string& name);
ImportedMesh parseLegacyVtk(std::string_view text, const std::string& name);
// `extension` without the dot: obj, stl, ply or off.
ImportedMesh parseSurface(std::string_view bytes, const std::string& extension, const std::string& name);

// The checks every reader ends with: indices in range, tets of positive volume (a zero-volume or
// inverted one is named by its element number as the file counts it: tetNumbers[i], or i when
// tetNumbers is empty), and markers sorted by number, then name. Throws std::invalid_argument.
void finishMesh(ImportedMesh& mesh, const std::string& name, const std::vector<long long>& tetNumbers);

}  // namespace hs::io
