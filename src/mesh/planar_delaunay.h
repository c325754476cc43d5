#pragma once
// Planar Delaunay triangulation by Bowyer-Watson point insertion, used to mesh flat parts of
// procedural models (the LV base plate). O(n^2): meant for a few thousand points.
#include <Eigen/Core>
#include <vector>

#include "pbd/core/tet_mesh.h"

namespace hs::pbd {

// In-circle predicate: > 0 when d lies strictly inside the circle through the
// counter-clockwise triangle (a, b, c), < 0 outside, ~0 on it.
double inCircle(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                const Eigen::Vector2d& d);

// Delaunay triangulation of distinct points: counter-clockwise triangles covering their convex
// hull, indexing `points`. Deterministic: depends only on the points and their order.
std::vector<Triangle> delaunayTriangulation(const std::vector<Eigen::Vector2d>& points);

}  // namespace hs::pbd
