// TetGen's text mesh: .node (points), .ele (tetrahedra), .face (boundary triangles with
// markers). Format: https://wias-berlin.de/software/tetgen/fformats.html. Indices start at 0
// or 1, as the file's first point number says; '#' starts a comment.
#include <map>
#include <stdexcept>

#include "io/mesh/mesh_import.h"
#include "io/mesh/mesh_text.h"

namespace hs::io {
namespace {

// A point number of the file, as an index into the vertices.
pbd::Index vertexIndex(MeshTokens& tokens, long long base, std::size_t vertexCount, const char* what) {
  const long long number = tokens.integer(what);
  if (number < base || number - base >= static_cast<long long>(vertexCount))
    tokens.fail(std::string("expected ") + what + " in [" + std::to_string(base) + ", " +
                std::to_string(base + static_cast<long long>(vertexCount) - 1) + "], got " + std::to_string(number));
  return static_cast<pbd::Index>(number - base);
}

// The rest of a record: `count` numbers that the format allows and heartsim does not use.
void skipNumbers(MeshTokens& tokens, long long count, const char* what) {
  for (long long i = 0; i < count; ++i) (void)tokens.real(what);
}

}  // namespace

ImportedMesh parseTetgen(std::string_view nodeText, std::string_view eleText, std::string_view faceText,
                         const std::string& stem) {
  ImportedMesh mesh;
  mesh.format = "tetgen";
  // .node: <#points> <dimension (3)> <#attributes> <#boundary markers (0 or 1)>, then
  // <point #> <x> <y> <z> [attributes] [boundary marker].
  MeshTokens node(nodeText, stem + ".node", '#');
  const long long pointCount = node.count("the number of points", countLimit(nodeText));
  const long long dimension = node.integer("the dimension");
  if (dimension != 3) node.fail("expected dimension 3, got " + std::to_string(dimension));
  const long long attributes = node.count("the number of point attributes", 1000);
  const long long pointMarkers = node.count("the number of boundary markers (0 or 1)", 1);
  long long base = 0;
  mesh.vertices.reserve(static_cast<std::size_t>(pointCount));
  for (long long i = 0; i < pointCount; ++i) {
    const long long number = node.integer("a point number");
    if (i == 0 && (number == 0 || number == 1)) base = number;
    if (number != base + i)
      node.fail("expected point number " + std::to_string(base + i) + ", got " + std::to_string(number));
    mesh.vertices.push_back(node.point("point coordinates"));
    skipNumbers(node, attributes + pointMarkers, "a point attribute or marker");
  }
  // .ele: <#tetrahedra> <nodes per tetrahedron (4)> <#attributes>, then
  // <tetrahedron #> <n1> <n2> <n3> <n4> [attributes].
  MeshTokens ele(eleText, stem + ".ele", '#');
  const long long tetCount = ele.count("the number of tetrahedra", countLimit(eleText));
  const long long corners = ele.integer("the number of nodes per tetrahedron");
  if (corners != 4) ele.fail("expected 4 nodes per tetrahedron (linear), got " + std::to_string(corners));
  const long long tetAttributes = ele.count("the number of tetrahedron attributes", 1000);
  std::vector<long long> tetNumbers;
  mesh.tets.reserve(static_cast<std::size_t>(tetCount));
  for (long long i = 0; i < tetCount; ++i) {
    tetNumbers.push_back(ele.integer("a tetrahedron number"));
    pbd::Tet tet;
    for (pbd::Index& v : tet) v = vertexIndex(ele, base, mesh.vertices.size(), "a point number");
    mesh.tets.push_back(tet);
    skipNumbers(ele, tetAttributes, "a tetrahedron attribute");
  }
  // .face: <#faces> <boundary marker (0 or 1)>, then <face #> <n1> <n2> <n3> [marker].
  if (!faceText.empty()) {
    MeshTokens face(faceText, stem + ".face", '#');
    const long long faceCount = face.count("the number of faces", countLimit(faceText));
    const long long hasMarker = face.count("the boundary marker flag (0 or 1)", 1);
    std::map<long long, std::size_t> markerOf;
    for (long long i = 0; i < faceCount; ++i) {
      (void)face.integer("a face number");
      pbd::Triangle triangle;
      for (pbd::Index& v : triangle) v = vertexIndex(face, base, mesh.vertices.size(), "a point number");
      if (hasMarker == 1) {
        const long long marker = face.integer("a face marker");
        if (marker < -1000000 || marker > 1000000) face.fail("expected a face marker within +-1e6, got " + std::to_string(marker));
        auto [it, added] = markerOf.try_emplace(marker, mesh.markers.size());
        if (added) mesh.markers.push_back({std::string(), static_cast<int>(marker), {}});
        mesh.markers[it->second].triangles.push_back(static_cast<pbd::Index>(mesh.triangles.size()));
      }
      mesh.triangles.push_back(triangle);
    }
  }
  finishMesh(mesh, stem + ".ele", tetNumbers);
  return mesh;
}

}  // namespace hs::io
