#pragma once
// A flat cap over a planar boundary loop, with circular holes cut in it: the triangles that
// close a truncated surface except where openings are wanted. Knows no hearts.
#include <Eigen/Core>
#include <vector>

#include "pbd/core/tet_mesh.h"

namespace hs::pbd {

struct CircularHole {
  Eigen::Vector2d centre;
  double radius = 0;
};

struct PlanarCap {
  std::vector<Eigen::Vector2d> newPoints;     // ids firstNewId, firstNewId + 1, ...
  std::vector<Triangle> triangles;            // counter-clockwise in the plane
  std::vector<std::vector<Index>> holeRings;  // per hole, its ring's ids, counter-clockwise
};

// Triangulates the polygon `rim` (counter-clockwise, its points carrying the ids `rimIds`)
// minus the holes (inside it and apart from each other), with points about `spacing` apart:
// a triangular lattice inside, kept 0.6 spacing away from the rim and the holes so the rim's
// and the rings' edges stay Delaunay edges, each hole's ring of ceil(2 pi r / spacing) points,
// and a guide point at each hole's centre (Delaunay, then the triangles at the guides, in a hole
// or outside the rim are dropped; as the procedural base plate does, cardiac/lv_base_plate).
// Throws std::invalid_argument when a hole does not fit inside the rim.
PlanarCap capWithHoles(const std::vector<Eigen::Vector2d>& rim, const std::vector<Index>& rimIds,
                       Index firstNewId, const std::vector<CircularHole>& holes, double spacing);

// Whether p lies inside the polygon (even-odd crossing rule).
bool insidePolygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p);

}  // namespace hs::pbd
