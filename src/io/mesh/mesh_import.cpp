#include "io/mesh/mesh_import.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hs::io {
namespace {

namespace fs = std::filesystem;

std::string lowerExtension(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext.empty() ? ext : ext.substr(1);
}

std::string readWhole(const fs::path& file) {
  std::error_code error;
  if (!fs::is_regular_file(file, error)) throw std::invalid_argument(file.string() + ": no such mesh file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::invalid_argument(file.string() + ": cannot open for reading");
  std::ostringstream text;
  text << in.rdbuf();
  return std::move(text).str();
}

ImportedMesh readTetgen(const fs::path& file) {
  fs::path stem = file;
  stem.replace_extension();
  const fs::path node = fs::path(stem).concat(".node"), ele = fs::path(stem).concat(".ele"),
                 face = fs::path(stem).concat(".face");
  std::error_code error;
  const std::string nodeText = readWhole(node);
  const std::string eleText = readWhole(ele);
  const std::string faceText = fs::exists(face, error) ? readWhole(face) : std::string();
  return parseTetgen(nodeText, eleText, faceText, stem.string());
}

}  // namespace

ImportedMesh readMesh(const fs::path& file) {
  const std::string ext = lowerExtension(file);
  const std::string name = file.string();
  if (ext == "node" || ext == "ele" || ext == "face") return readTetgen(file);
  if (ext == "msh") return parseGmsh(readWhole(file), name);
  if (ext == "vtu") return parseVtu(readWhole(file), name);
  if (ext == "vtk") return parseLegacyVtk(readWhole(file), name);
  if (ext == "obj" || ext == "stl" || ext == "ply" || ext == "off") return parseSurface(readWhole(file), ext, name);
  throw std::invalid_argument(name + ": unknown mesh extension '" + file.extension().string() +
                              "'; expected .obj, .stl, .ply, .off, .msh, .vtu, .vtk, .node, .ele or .face");
}

void finishMesh(ImportedMesh& mesh, const std::string& name, const std::vector<long long>& tetNumbers) {
  const std::size_t n = mesh.vertices.size();
  auto numberOf = [&](std::size_t i) { return tetNumbers.empty() ? static_cast<long long>(i) : tetNumbers[i]; };
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (pbd::Index v : mesh.triangles[t])
      if (v >= n)
        throw std::invalid_argument(name + ": triangle " + std::to_string(t) + " uses vertex " + std::to_string(v) +
                                    ", expected one of the " + std::to_string(n) + " vertices");
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const pbd::Tet& tet = mesh.tets[t];
    for (pbd::Index v : tet)
      if (v >= n)
        throw std::invalid_argument(name + ": tetrahedron " + std::to_string(numberOf(t)) + " uses vertex " +
                                    std::to_string(v) + ", expected one of the " + std::to_string(n) + " vertices");
    // V = (1/6) (x1 - x0) x (x2 - x0) . (x3 - x0), in double whatever pbd::Real is. A volume
    // below 1e-9 of the cube of the longest edge (a regular tet has 0.118) is a flat tet:
    // its dihedral angles are near 0 or 180 degrees and no constraint can hold it.
    Eigen::Vector3d x[4];
    for (int k = 0; k < 4; ++k) x[k] = mesh.vertices[tet[k]].cast<double>();
    const double volume = (x[1] - x[0]).cross(x[2] - x[0]).dot(x[3] - x[0]) / 6.0;
    double longest = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) longest = std::max(longest, (x[a] - x[b]).norm());
    const double tolerance = 1e-9 * longest * longest * longest;
    if (volume > tolerance) continue;
    std::ostringstream message;
    message << name << ": tetrahedron " << numberOf(t) << " (vertices " << tet[0] << ' ' << tet[1] << ' ' << tet[2]
            << ' ' << tet[3] << ") " << (volume < -tolerance ? "is inverted" : "has zero volume") << " (signed volume "
            << volume << "); expected a positive volume, (x1-x0)x(x2-x0).(x3-x0) > 0";
    throw std::invalid_argument(message.str());
  }
  std::stable_sort(mesh.markers.begin(), mesh.markers.end(), [](const SurfaceMarker& a, const SurfaceMarker& b) {
    return a.number != b.number ? a.number < b.number : a.name < b.name;
  });
}

}  // namespace hs::io
