#include "io/mesh/mesh_vtk_cells.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace hs::io {
namespace {

constexpr long long kVtkVertex = 1, kVtkLine = 3, kVtkTriangle = 5, kVtkTetra = 10;

bool markerLikeName(std::string name) {
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const char* known : {"gmsh:physical", "cellentityids", "medit:ref", "marker", "markers", "ref", "boundary_id"})
    if (name == known) return true;
  return false;
}

bool wholeOnTriangles(const std::vector<double>& values, const std::vector<std::size_t>& triangleCells) {
  return std::all_of(triangleCells.begin(), triangleCells.end(), [&](std::size_t c) {
    const double v = values[c];
    return std::isfinite(v) && v == std::floor(v) && std::abs(v) <= 1e6;
  });
}

}  // namespace

void assembleVtkCells(ImportedMesh& mesh, const VtkCells& cells, const std::string& name) {
  const std::size_t n = cells.types.size();
  if (cells.offsets.size() != n + 1)
    throw std::invalid_argument(name + ": " + std::to_string(cells.offsets.size()) + " cell offsets; expected " +
                                std::to_string(n + 1));
  std::vector<long long> tetNumbers;
  std::vector<std::size_t> triangleCells;
  const auto vertexCount = static_cast<long long>(mesh.vertices.size());
  for (std::size_t c = 0; c < n; ++c) {
    const long long type = cells.types[c];
    const long long begin = cells.offsets[c], end = cells.offsets[c + 1];
    const std::string cell = name + ": cell " + std::to_string(c);
    if (begin < 0 || end < begin || end > static_cast<long long>(cells.connectivity.size()))
      throw std::invalid_argument(cell + ": offsets " + std::to_string(begin) + ".." + std::to_string(end) +
                                  " outside the connectivity's " + std::to_string(cells.connectivity.size()) + " entries");
    if (type == kVtkVertex || type == kVtkLine) continue;
    const long long corners = type == kVtkTetra ? 4 : type == kVtkTriangle ? 3 : -1;
    if (corners < 0)
      throw std::invalid_argument(cell + " has type " + std::to_string(type) +
                                  "; expected 10 (tetra), 5 (triangle), 3 (line) or 1 (vertex): only linear meshes are read");
    if (end - begin != corners)
      throw std::invalid_argument(cell + " has " + std::to_string(end - begin) + " points; expected " + std::to_string(corners));
    pbd::Tet ids{};
    for (long long k = 0; k < corners; ++k) {
      const long long v = cells.connectivity[static_cast<std::size_t>(begin + k)];
      if (v < 0 || v >= vertexCount)
        throw std::invalid_argument(cell + " uses point " + std::to_string(v) + "; expected one in [0, " +
                                    std::to_string(vertexCount - 1) + "]");
      ids[static_cast<std::size_t>(k)] = static_cast<pbd::Index>(v);
    }
    if (type == kVtkTetra) {
      mesh.tets.push_back(ids);
      tetNumbers.push_back(static_cast<long long>(c));
    } else {
      mesh.triangles.push_back({ids[0], ids[1], ids[2]});
      triangleCells.push_back(c);
    }
  }
  const std::vector<double>* markers = nullptr;
  for (int pass = 0; pass < 2 && markers == nullptr && !triangleCells.empty(); ++pass)
    for (const auto& [arrayName, values] : cells.cellData)
      if (values.size() == n && (pass == 1 || markerLikeName(arrayName)) && wholeOnTriangles(values, triangleCells)) {
        markers = &values;
        break;
      }
  if (markers != nullptr) {
    std::map<int, std::size_t> markerOf;
    for (std::size_t t = 0; t < triangleCells.size(); ++t) {
      const int number = static_cast<int>((*markers)[triangleCells[t]]);
      auto [it, added] = markerOf.try_emplace(number, mesh.markers.size());
      if (added) mesh.markers.push_back({std::string(), number, {}});
      mesh.markers[it->second].triangles.push_back(static_cast<pbd::Index>(t));
    }
  }
  finishMesh(mesh, name, tetNumbers);
}

}  // namespace hs::io
