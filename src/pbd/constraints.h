#pragma once
// Constraint data (plain structs, one array per type) and their pure kernels:
//   evaluate*  the value C(x) and its gradient dC/dx_i, checked against finite differences;
//   project*   one XPBD projection (projection.h): positions, inverse masses, parameters and
//              lambda in; position corrections and the lambda increment out.
// Arguments and results are named scalars and vectors rather than arrays: the compiler then
// keeps everything in registers, which makes the kernels about twice as fast.
#include <array>

#include "pbd/projection.h"
#include "pbd/types.h"

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

HS_KERNEL Correction4 projectTetVolume(const Vec3& x0, const Vec3& x1, const Vec3& x2, const Vec3& x3, Real w0,
                                    Real w1, Real w2, Real w3, Real restVolume, const ProjectionParams& params,
                                    Real lambda) {
  const TetVolumeEval c = evaluateTetVolume(x0, x1, x2, x3, restVolume);
  const Real gradientNorm = w0 * c.g0.squaredNorm() + w1 * c.g1.squaredNorm() + w2 * c.g2.squaredNorm() +
                            w3 * c.g3.squaredNorm();
  const Real dl = xpbdDeltaLambda(c.value, gradientNorm, params, lambda);
  return {(w0 * dl) * c.g0, (w1 * dl) * c.g1, (w2 * dl) * c.g2, (w3 * dl) * c.g3, dl};
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

HS_KERNEL Correction3 projectTriangleArea(const Vec3& x0, const Vec3& x1, const Vec3& x2, Real w0, Real w1, Real w2,
                                       Real restArea, const ProjectionParams& params, Real lambda) {
  const TriangleAreaEval c = evaluateTriangleArea(x0, x1, x2, restArea);
  const Real gradientNorm = w0 * c.g0.squaredNorm() + w1 * c.g1.squaredNorm() + w2 * c.g2.squaredNorm();
  const Real dl = xpbdDeltaLambda(c.value, gradientNorm, params, lambda);
  return {(w0 * dl) * c.g0, (w1 * dl) * c.g1, (w2 * dl) * c.g2, dl};
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

HS_KERNEL Correction2 projectDistance(const Vec3& x0, const Vec3& x1, Real w0, Real w1, Real restLength,
                                   const ProjectionParams& params, Real lambda) {
  const DistanceEval c = evaluateDistance(x0, x1, restLength);
  const Real gradientNorm = (w0 + w1) * c.g1.squaredNorm();  // |g0| = |g1|
  const Real dl = xpbdDeltaLambda(c.value, gradientNorm, params, lambda);
  return {(w0 * dl) * c.g0, (w1 * dl) * c.g1, dl};
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
