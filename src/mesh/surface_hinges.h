#pragma once
// Hinges of a triangle surface: each interior edge with the two triangles that share it. The
// angle a hinge is bent by is the turn between the triangles' normals, signed about the edge,
//   theta = atan2((n1 x n2) . e, n1 . n2),   e the unit edge a -> b,
// with n1 the normal of (a, b, c) and n2 of (b, a, d) (consistently wound neighbours): 0 where
// the surface is flat, +-pi where it folds back onto itself. A crease in a surface that was
// smooth is a hinge whose angle changed by much (tens of degrees) from its rest angle.
#include <span>
#include <vector>

#include "pbd/core/tet_mesh.h"

namespace hs::pbd {

struct Hinge {
  Index a, b;  // the shared edge, in the first triangle's winding
  Index c, d;  // the vertex of the first triangle off the edge, and that of the second
};

// Every edge shared by exactly two consistently wound triangles (a boundary edge, or one of a
// non-manifold fan, has no hinge).
std::vector<Hinge> surfaceHinges(const std::vector<Triangle>& triangles);

// The signed angle (radians, in (-pi, pi]) hinge h is bent by at positions x; 0 for a
// degenerate triangle.
double hingeAngle(const Hinge& h, std::span<const Vec3> x);

// The largest |theta - theta_rest| over the hinges (radians, the difference wrapped to [0, pi]).
double largestHingeTurn(const std::vector<Hinge>& hinges, const std::vector<double>& restAngles,
                        std::span<const Vec3> x);

}  // namespace hs::pbd
