#pragma once
// Constraint data (plain structs, one array per type) and their pure evaluation kernels:
// value C(x) and gradient dC/dx_i. The solver turns an evaluation into a correction with
// projectXpbd (projection.h); tests check every gradient against finite differences.
#include <array>

#include "pbd/projection.h"
#include "pbd/types.h"

namespace hs::pbd {

// Tetrahedron volume conservation, thesis eq. 4.1-4.2:
//   C = (1/6) (x1 - x0) x (x2 - x0) . (x3 - x0) - V0
struct TetVolumeConstraint {
  std::array<Index, 4> particles;
  Real restVolume;
};

inline ConstraintEval<4> evaluateTetVolume(const std::array<Vec3, 4>& x, Real restVolume) {
  const Vec3 e1 = x[1] - x[0];
  const Vec3 e2 = x[2] - x[0];
  const Vec3 e3 = x[3] - x[0];
  constexpr Real kSixth = Real(1) / Real(6);
  ConstraintEval<4> c;
  c.value = kSixth * e1.cross(e2).dot(e3) - restVolume;
  c.gradient[1] = kSixth * e2.cross(e3);
  c.gradient[2] = kSixth * e3.cross(e1);
  c.gradient[3] = kSixth * e1.cross(e2);
  c.gradient[0] = -(c.gradient[1] + c.gradient[2] + c.gradient[3]);
  return c;
}

// Triangle area conservation, thesis eq. 4.3-4.4:
//   C = (1/2) |(x1 - x0) x (x2 - x0)| - A0
// With n = (x1 - x0) x (x2 - x0) and n^ = n/|n|: dC/dx1 = (1/2) (x2 - x0) x n^,
// dC/dx2 = (1/2) n^ x (x1 - x0), dC/dx0 = -(dC/dx1 + dC/dx2).
struct TriangleAreaConstraint {
  std::array<Index, 3> particles;
  Real restArea;
};

inline ConstraintEval<3> evaluateTriangleArea(const std::array<Vec3, 3>& x, Real restArea) {
  const Vec3 e1 = x[1] - x[0];
  const Vec3 e2 = x[2] - x[0];
  const Vec3 n = e1.cross(e2);
  const Real length = n.norm();
  ConstraintEval<3> c;
  c.value = Real(0.5) * length - restArea;
  if (length <= Real(0)) {  // collapsed triangle: no defined direction to restore along
    for (auto& g : c.gradient) g.setZero();
    return c;
  }
  const Vec3 unit = n * (Real(1) / length);
  c.gradient[1] = Real(0.5) * e2.cross(unit);
  c.gradient[2] = Real(0.5) * unit.cross(e1);
  c.gradient[0] = -(c.gradient[1] + c.gradient[2]);
  return c;
}

// Edge distance: C = |x1 - x0| - L0. Volume and area alone leave shear and bending modes
// free; edges hold the rest shape (Mueller et al. 2007, section 4.2).
struct DistanceConstraint {
  std::array<Index, 2> particles;
  Real restLength;
};

inline ConstraintEval<2> evaluateDistance(const std::array<Vec3, 2>& x, Real restLength) {
  const Vec3 d = x[1] - x[0];
  const Real length = d.norm();
  ConstraintEval<2> c;
  c.value = length - restLength;
  const Vec3 unit = length > Real(0) ? Vec3(d * (Real(1) / length)) : Vec3::Zero();
  c.gradient[1] = unit;
  c.gradient[0] = -unit;
  return c;
}

// Collision with a static plane, thesis eq. 4.5 (unilateral):
//   C = n . x - d >= 0,  n unit normal pointing into the allowed half-space,
// d = plane offset plus the particle's radius. Gradient n.
struct Plane {
  Vec3 normal = Vec3::UnitY();
  Real offset = 0;
};

inline ConstraintEval<1> evaluatePlaneCollision(const Vec3& x, const Plane& plane, Real radius) {
  ConstraintEval<1> c;
  c.value = plane.normal.dot(x) - (plane.offset + radius);
  c.gradient[0] = plane.normal;
  return c;
}

// Projection of an inequality contact: only a violated constraint (C < 0) is corrected, and
// fully (contacts are hard): dx = -C n for a movable particle.
inline Vec3 projectPlaneCollision(const Vec3& x, Real inverseMass, const Plane& plane,
                                  Real radius) {
  const ConstraintEval<1> c = evaluatePlaneCollision(x, plane, radius);
  if (c.value >= Real(0) || inverseMass <= Real(0)) return Vec3::Zero();
  return -c.value * c.gradient[0];
}

}  // namespace hs::pbd
