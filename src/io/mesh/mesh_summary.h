#pragma once
// What `heartsim mesh FILE` reports of an imported mesh: counts, bounding box, a guess of the
// length unit, markers, for tetrahedra their volume and worst quality, for a surface whether
// it is closed, its enclosed volume, or its boundary loops with the areas of their flat caps.
#include <optional>
#include <string>
#include <vector>

#include "io/mesh/mesh_import.h"

namespace hs::io {

// One boundary loop of an open surface: the edges used by one triangle only, chained.
struct BoundaryLoop {
  std::size_t vertices = 0;
  double perimeter = 0;
  // Area of the flat cap: |vector area| = (1/2) |sum_i p_i x p_(i+1)|, exact for a planar loop
  // and the area of its projection on the best plane otherwise.
  double capArea = 0;
};

struct MeshSummary {
  std::size_t vertices = 0, triangles = 0, tets = 0;
  double min[3] = {0, 0, 0}, max[3] = {0, 0, 0};
  double size = 0;          // the largest extent of the bounding box, in file units
  std::string unitGuess;    // "m", "cm", "mm" or "" when the size fits no heart (5-20 cm) in any
  double millilitresPerCubicUnit = 0;  // 0 when the unit is not guessed
  std::vector<std::pair<std::string, std::size_t>> markers;  // label ("3" or "3 ENDO" or "ENDO"), triangles
  // Tetrahedra.
  double tetVolume = 0;
  std::optional<pbd::MeshQuality> quality;
  // Surface (a mesh without tetrahedra).
  bool closed = false;
  std::size_t nonManifoldEdges = 0;
  double enclosedVolume = 0;  // |V| by the divergence theorem when closed
  std::vector<BoundaryLoop> loops;
  double cappedVolume = 0;    // |V| with every loop closed by a fan from its centroid (open surface)
};

MeshSummary summarizeMesh(const ImportedMesh& mesh);

// The boundary loops of a triangle surface (exposed for tests), numbered as
// pbd::boundaryLoopVertices numbers them, as `heartsim mesh --mitral-loop` counts them.
std::vector<BoundaryLoop> boundaryLoops(const std::vector<pbd::Vec3>& vertices,
                                        const std::vector<pbd::Triangle>& triangles);

}  // namespace hs::io
