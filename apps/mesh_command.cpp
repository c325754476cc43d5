#include "mesh_command.h"

#include <iomanip>
#include <iostream>
#include <optional>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "exit_codes.h"
#include "io/mesh/mesh_import.h"
#include "io/mesh/mesh_summary.h"
#include "mesh_wall.h"

namespace hs::app {
namespace {

nlohmann::json toJson(const io::MeshSummary& s, const std::string& file, const std::string& format) {
  nlohmann::json j;
  j["file"] = file;
  j["format"] = format;
  j["vertices"] = s.vertices;
  j["triangles"] = s.triangles;
  j["tets"] = s.tets;
  j["bounding_box"] = {{"min", {s.min[0], s.min[1], s.min[2]}}, {"max", {s.max[0], s.max[1], s.max[2]}}};
  j["size"] = s.size;
  j["unit_guess"] = s.unitGuess;
  j["markers"] = nlohmann::json::array();
  for (const auto& [label, count] : s.markers) j["markers"].push_back({{"marker", label}, {"triangles", count}});
  const auto millilitres = [&](double volume) { return s.millilitresPerCubicUnit > 0 ? nlohmann::json(volume * s.millilitresPerCubicUnit) : nlohmann::json(nullptr); };
  if (s.quality) {
    j["volume"] = s.tetVolume;
    j["volume_ml"] = millilitres(s.tetVolume);
    j["min_dihedral_deg"] = s.quality->minDihedralDeg;
    j["max_aspect_ratio"] = s.quality->maxAspectRatio;
  } else {
    j["closed"] = s.closed;
    j["non_manifold_edges"] = s.nonManifoldEdges;
    if (s.closed) {
      j["enclosed_volume"] = s.enclosedVolume;
      j["enclosed_volume_ml"] = millilitres(s.enclosedVolume);
    } else {
      j["capped_volume"] = s.cappedVolume;
      j["capped_volume_ml"] = millilitres(s.cappedVolume);
      j["boundary_loops"] = nlohmann::json::array();
      for (const io::BoundaryLoop& loop : s.loops)
        j["boundary_loops"].push_back({{"vertices", loop.vertices}, {"perimeter", loop.perimeter}, {"cap_area", loop.capArea}});
    }
  }
  return j;
}

void printText(const io::MeshSummary& s, const std::string& file, const std::string& format) {
  std::cout << std::setprecision(6) << file << " (" << format << ")\n"
            << "  vertices " << s.vertices << ", triangles " << s.triangles << ", tetrahedra " << s.tets << '\n'
            << "  bounding box (" << s.min[0] << ", " << s.min[1] << ", " << s.min[2] << ") to (" << s.max[0] << ", "
            << s.max[1] << ", " << s.max[2] << "), size " << s.size << '\n'
            << "  units: " << (s.unitGuess.empty() ? std::string("unknown (not heart-sized, 5-20 cm, in m, cm or mm)")
                                                   : s.unitGuess + " (guessed from the size of a heart, 5-20 cm)")
            << '\n';
  const auto ml = [&](double volume) {
    return s.millilitresPerCubicUnit > 0 ? " = " + std::to_string(volume * s.millilitresPerCubicUnit) + " mL" : std::string();
  };
  if (s.markers.empty()) std::cout << "  markers: none\n";
  for (const auto& [label, count] : s.markers) std::cout << "  marker " << label << ": " << count << " triangles\n";
  if (s.quality) {
    std::cout << "  volume " << s.tetVolume << ml(s.tetVolume) << '\n'
              << "  worst tetrahedron: smallest dihedral angle " << s.quality->minDihedralDeg
              << " deg, largest aspect ratio " << s.quality->maxAspectRatio << '\n';
    return;
  }
  if (s.nonManifoldEdges > 0) std::cout << "  non-manifold edges: " << s.nonManifoldEdges << '\n';
  if (s.closed) {
    std::cout << "  closed surface, enclosed volume " << s.enclosedVolume << ml(s.enclosedVolume) << '\n';
    return;
  }
  std::cout << "  open surface, " << s.loops.size() << " boundary loop" << (s.loops.size() == 1 ? "" : "s") << '\n';
  for (std::size_t i = 0; i < s.loops.size(); ++i)
    std::cout << "    loop " << i + 1 << ": " << s.loops[i].vertices << " vertices, perimeter " << s.loops[i].perimeter
              << ", flat cap area " << s.loops[i].capArea << '\n';
  std::cout << "  volume with the loops closed by flat caps " << s.cappedVolume << ml(s.cappedVolume) << '\n';
}

}  // namespace

int meshCommand(const MeshOptions& options) {
  io::ImportedMesh mesh;
  try {
    mesh = io::readMesh(options.file);
  } catch (const std::invalid_argument& e) {
    std::cerr << "heartsim: error: " << e.what() << '\n';
    return kExitBadInput;
  }
  const io::MeshSummary summary = io::summarizeMesh(mesh);
  std::optional<WallReport> wall;
  if (options.wall) {
    try {
      wall = buildWallReport(mesh, summary, options);
    } catch (const std::invalid_argument& e) {
      std::cerr << "heartsim: error: " << e.what() << '\n';
      return kExitBadInput;
    }
  }
  if (options.json) {
    nlohmann::json j = toJson(summary, options.file, mesh.format);
    if (wall) j["wall"] = wallJson(*wall);
    std::cout << j.dump(2) << '\n';
  } else {
    printText(summary, options.file, mesh.format);
    if (wall) printWall(*wall);
  }
  return kExitOk;
}

}  // namespace hs::app
