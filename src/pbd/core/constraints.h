#pragma once
// Constraint data (plain structs, one array per type) and their pure kernels:
//   evaluate*  the value C(x) and its gradient dC/dx_i, checked against finite differences;
//   project*   one XPBD projection (projection.h): positions, inverse masses, parameters and
//              lambda in; position corrections and the lambda increment out.
// Arguments and results are named scalars and vectors rather than arrays: the compiler then
// keeps everything in registers, which makes the kernels about twice as fast.
#include <array>

#include "pbd/core/projection.h"
#include "pbd/core/types.h"

namespace hs::pbd {

struct Correction2 {
  Vec3 dx0, dx1;
  Real deltaLambda;
};
struct Correction3 {
  Vec3 dx0, dx1, dx2;
  Real deltaLambda;
};
struct Correction4 {
  Vec3 dx0, dx1, dx2, dx3;
  Real deltaLambda;
};

// Tetrahedron volume conservation, thesis eq. 4.1-4.2:
//   C = (1/6) (x1 - x0) x (x2 - x0) . (x3 - x0) - V0
// dC/dx1 = (1/6) (x2 - x0) x (x3 - x0), dC/dx2 = (1/6) (x3 - x0) x (x1 - x0),
// dC/dx3 = (1/6) (x1 - x0) x (x2 - x0), dC/dx0 = -(dC/dx1 + dC/dx2 + dC/dx3).
struct TetVolumeConstraint {
  std::array<Index, 4> particles;
  Real restVolume;
};

struct TetVolumeEval {
  Real value;
  Vec3 g0, g1, g2, g3;
};

HS_KERNEL TetVolumeEval evaluateTetVolume(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3,
                                       Real restVolume) {
  const Vec3 e1 = x1 - x0;
  const Vec3 e2 = x2 - x0;
  const Vec3 e3 = x3 - x0;
  constexpr Real kSixth = Real(1) / Real(6);
  TetVolumeEval c;
  c.g1 = kSixth * e2.cross(e3);
  c.g2 = kSixth * e3.cross(e1);
  c.g3 = kSixth * e1.cross(e2);
  c.g0 = -(c.g1 + c.g2 + c.g3);
  c.value = e1.dot(c.g1) - restVolume;
  return c;
}

// The same XPBD step as xpbdDeltaLambda with the gradient above, with the factor 1/6 folded
// into one scale: G_i = 6 dC/dx_i, sum_i w_i |dC/dx_i|^2 = (1/36) sum_i w_i |G_i|^2.
HS_KERNEL Correction4 projectTetVolume(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3, Real w0,
                                       Real w1, Real w2, Real w3, Real restVolume, const ProjectionParams& params,
                                       Real lambda) {
  const Vec3 e1 = x1 - x0;
  const Vec3 e2 = x2 - x0;
  const Vec3 e3 = x3 - x0;
  const Vec3 g1 = e2.cross(e3);
  const Vec3 g2 = e3.cross(e1);
  const Vec3 g3 = e1.cross(e2);
  const Vec3 g0 = -(g1 + g2 + g3);
  constexpr Real kSixth = Real(1) / Real(6);
  const Real c = kSixth * e1.dot(g1) - restVolume;
  const Real denominator =
      Real(1) / Real(36) * (w0 * g0.squaredNorm() + w1 * g1.squaredNorm() + w2 * g2.squaredNorm() + w3 * g3.squaredNorm()) +
      params.alphaTilde;
  constexpr Real kTiny = Real(1e-30);
  if (denominator <= kTiny) return {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), 0};
  const Real dl = params.stiffness * (-c - params.alphaTilde * lambda) / denominator;
  const Real scale = kSixth * dl;
  return {(w0 * scale) * g0, (w1 * scale) * g1, (w2 * scale) * g2, (w3 * scale) * g3, dl};
}

// Triangle area conservation, thesis eq. 4.3-4.4:
//   C = (1/2) |(x1 - x0) x (x2 - x0)| - A0
// With n = (x1 - x0) x (x2 - x0) and n^ = n/|n|: dC/dx1 = (1/2) (x2 - x0) x n^,
// dC/dx2 = (1/2) n^ x (x1 - x0), dC/dx0 = -(dC/dx1 + dC/dx2). A collapsed triangle has no
// direction to restore along: zero gradient.
struct TriangleAreaConstraint {
  std::array<Index, 3> particles;
  Real restArea;
};

struct TriangleAreaEval {
  Real value;
  Vec3 g0, g1, g2;
};

HS_KERNEL TriangleAreaEval evaluateTriangleArea(const Vec3& x0, const Vec3& x1, const Vec3& x2, Real restArea) {
  const Vec3 e1 = x1 - x0;
  const Vec3 e2 = x2 - x0;
  const Vec3 n = e1.cross(e2);
  const Real length = n.norm();
  TriangleAreaEval c;
  c.value = Real(0.5) * length - restArea;
  if (length <= Real(0)) {
    c.g0 = c.g1 = c.g2 = Vec3::Zero();
    return c;
  }
  const Vec3 unit = n * (Real(1) / length);
  c.g1 = Real(0.5) * e2.cross(unit);
  c.g2 = Real(0.5) * unit.cross(e1);
  c.g0 = -(c.g1 + c.g2);
  return c;
}

// The same XPBD step as xpbdDeltaLambda with the gradient above, in fewer operations: since
// e1, e2 and e2 - e1 are perpendicular to n^, |dC/dx1|^2 = |e2|^2/4, |dC/dx2|^2 = |e1|^2/4 and
// |dC/dx0|^2 = |e2 - e1|^2/4 need no cross product, and dLambda / |n| takes one division.
HS_KERNEL Correction3 projectTriangleArea(const Vec3& x0, const Vec3& x1, const Vec3& x2, Real w0, Real w1,
                                          Real w2, Real restArea, const ProjectionParams& params, Real lambda) {
  const Vec3 e1 = x1 - x0;
  const Vec3 e2 = x2 - x0;
  const Vec3 n = e1.cross(e2);
  const Real length = n.norm();
  const Real denominator =
      Real(0.25) * (w0 * (e2 - e1).squaredNorm() + w1 * e2.squaredNorm() + w2 * e1.squaredNorm()) +
      params.alphaTilde;
  constexpr Real kTiny = Real(1e-30);
  if (length <= Real(0) || denominator <= kTiny) return {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), 0};
  const Real c = Real(0.5) * length - restArea;
  const Real numerator = params.stiffness * (-c - params.alphaTilde * lambda);
  const Real scale = Real(0.5) * numerator / (denominator * length);  // dLambda / (2 |n|)
  const Vec3 g1 = e2.cross(n);  // 2 |n| dC/dx1
  const Vec3 g2 = n.cross(e1);  // 2 |n| dC/dx2
  return {(-w0 * scale) * (g1 + g2), (w1 * scale) * g1, (w2 * scale) * g2, numerator / denominator};
}

// Edge distance: C = |x1 - x0| - L0, dC/dx1 = n^ = (x1 - x0)/|x1 - x0|, dC/dx0 = -n^.
// Volume and area alone leave shear and bending modes free; edges hold the rest shape
// (Mueller et al. 2007, section 4.2).
struct DistanceConstraint {
  std::array<Index, 2> particles;
  Real restLength;
};

struct DistanceEval {
  Real value;
  Vec3 g0, g1;
};

HS_KERNEL DistanceEval evaluateDistance(const Vec3& x0, const Vec3& x1, Real restLength) {
  const Vec3 d = x1 - x0;
  const Real length = d.norm();
  DistanceEval c;
  c.value = length - restLength;
  c.g1 = length > Real(0) ? Vec3(d * (Real(1) / length)) : Vec3::Zero();
  c.g0 = -c.g1;
  return c;
}

// The same XPBD step with |dC/dx|^2 = 1 and dLambda / |d| in one division.
HS_KERNEL Correction2 projectDistance(const Vec3& x0, const Vec3& x1, Real w0, Real w1, Real restLength,
                                      const ProjectionParams& params, Real lambda) {
  const Vec3 d = x1 - x0;
  const Real length = d.norm();
  const Real denominator = w0 + w1 + params.alphaTilde;
  constexpr Real kTiny = Real(1e-30);
  if (length <= Real(0) || denominator <= kTiny) return {Vec3::Zero(), Vec3::Zero(), 0};
  const Real numerator = params.stiffness * (-(length - restLength) - params.alphaTilde * lambda);
  const Real scale = numerator / (denominator * length);  // dLambda / |d|
  return {(-w0 * scale) * d, (w1 * scale) * d, numerator / denominator};
}

// Collision with a static plane, thesis eq. 4.5 (unilateral):
//   C = n . x - d >= 0,  n unit normal pointing into the allowed half-space,
// d = plane offset plus the particle's radius. Gradient n.
struct Plane {
  Vec3 normal = Vec3::UnitY();
  Real offset = 0;
};

HS_KERNEL Real evaluatePlaneCollision(const Vec3& x, const Plane& plane, Real radius) {
  return plane.normal.dot(x) - (plane.offset + radius);
}

// Projection of an inequality contact: only a violated constraint (C < 0) is corrected, and
// fully (contacts are hard): dx = -C n for a movable particle.
HS_KERNEL Vec3 projectPlaneCollision(const Vec3& x, Real inverseMass, const Plane& plane, Real radius) {
  const Real c = evaluatePlaneCollision(x, plane, radius);
  if (c >= Real(0) || inverseMass <= Real(0)) return Vec3::Zero();
  return -c * plane.normal;
}

}  // namespace hs::pbd
