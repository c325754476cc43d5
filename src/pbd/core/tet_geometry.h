#pragma once
// One tetrahedron against a point and against a ray: the geometric core of particle–tetrahedron
// penetration handling (thesis section 4.4.1, eq. 4.12–4.20, Algorithms 4–5), with the
// ray–tetrahedron test of Platis & Theoharis 2003, "Fast ray-tetrahedron intersection using
// Plücker coordinates", Journal of Graphics Tools 8(4).
//
// Conventions
//  * A tet is four corner positions x0..x3 (TetPoints). Positive orientation means
//    (x1 - x0) x (x2 - x0) . (x3 - x0) > 0, as in TetMesh. Inverted tets (negative volume) are
//    handled too: every test below depends only on the convex hull of the four points.
//  * Face i is the face opposite vertex i, wound (kTetFaceVertices) so that its normal
//    (b - a) x (c - a) points out of a positive tet. These are the thesis's faces of Fig. 4.9
//    (F0 = (V3,V2,V1), F1 = (V2,V3,V0), F2 = (V1,V0,V3), F3 = (V0,V1,V2)) with the winding
//    reversed: the thesis's faces point into a positive tet, which its eq. 4.12 matches by
//    using X - P; outward normals make "inside" mean "behind every face" and the push-out
//    direction the normal itself.
//
// Tolerances (Real is float unless HS_DOUBLE; eps = machine epsilon of Real)
//  * kTetDegenerateVolume: a tet with |6V| <= 64 eps * L^3 (L = longest edge) is degenerate:
//    barycentric coordinates would carry relative errors of order eps L^3 / |6V| >= 1/64, so
//    such a tet reports "not inside", "no intersection" and is never pushed out of. A regular
//    tet has 6V = L^3 / sqrt(2), so only extreme slivers (8e-6 of that in float) are affected.
//  * kBarycentricSlack = 32 eps: the rounding error of a computed barycentric coordinate of a
//    well-shaped tet. Pass it as `tolerance` to count points on a shared face as inside both
//    tets instead of, by rounding, in neither.
//  * pushOutOfTet (tet_geometry.cpp): a motion |p - previous| <= 64 eps max(L, |p|_inf) is
//    rounding noise and gives no ray; the ray's entry point may lie up to 1e-3 L outside the
//    segment [previous, p] (a deliberate slack, not a rounding bound: a previous position that
//    deep inside means the tet moved onto the particle, and the nearest face is the better exit).
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "pbd/core/tet_mesh.h"
#include "pbd/core/types.h"

namespace hs::pbd {

using TetPoints = std::array<Vec3, 4>;

inline TetPoints tetPoints(const std::vector<Vec3>& x, const Tet& t) {
  return {x[t[0]], x[t[1]], x[t[2]], x[t[3]]};
}

// Face i opposite vertex i, outward for a positive tet: 6V = -n_i . (x_i - a_i) for every i.
inline constexpr std::array<std::array<int, 3>, 4> kTetFaceVertices{
    {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};

inline constexpr Real kTetDegenerateVolume = Real(64) * std::numeric_limits<Real>::epsilon();
inline constexpr Real kBarycentricSlack = Real(32) * std::numeric_limits<Real>::epsilon();

// ---- Point in tetrahedron (thesis eq. 4.12–4.13) -------------------------------------------

struct TetPointQuery {
  // lambda_i = V(x with x_i replaced by p) / V: the thesis's theta_i (eq. 4.12) of face i,
  // divided by the same quantity for the opposite vertex. Sum 1; all zero if degenerate.
  std::array<Real, 4> barycentric{};
  // Signed distance from p to the plane of face i, positive on the tet's side (= lambda_i times
  // the height over face i).
  std::array<Real, 4> faceDistance{};
  // min_i faceDistance[i]. Inside, this is the penetration depth: the distance from p to the
  // tet's boundary (for a convex cell, the nearest boundary point lies on the nearest face
  // plane). Outside it is negative and its magnitude is a lower bound of the distance to the tet.
  Real depth = 0;
  int nearestFace = -1;  // argmin of faceDistance (lowest on ties); -1: degenerate or p non-finite
  bool inside = false;   // every lambda_i > -tolerance
  bool degenerate = false;
};

// Full query: 4 cross products and 4 square roots.
TetPointQuery queryPointInTet(const TetPoints& x, const Vec3& p, Real tolerance = 0);

// Inside test only (no square roots): lambda_i > -tolerance for all i. tolerance > 0 grows the
// tet, tolerance < 0 shrinks it, both in barycentric units (fractions of the heights).
bool isPointInTet(const TetPoints& x, const Vec3& p, Real tolerance = 0);

// Outward unit normal of face i (outward also for an inverted tet); zero if degenerate.
Vec3 tetFaceNormal(const TetPoints& x, int face);

// ---- Plücker coordinates (thesis eq. 4.14–4.16, 4.19) --------------------------------------

// pi = {U : V} = {L : L x P} for the line through P with direction L (eq. 4.14).
struct PluckerLine {
  Vec3 u = Vec3::Zero();  // direction L
  Vec3 v = Vec3::Zero();  // moment L x P
};

inline PluckerLine pluckerFromPointDirection(const Vec3& point, const Vec3& direction) {
  return {direction, direction.cross(point)};
}

// The line through a then b, directed from a to b (a tet edge a -> b).
inline PluckerLine pluckerFromPoints(const Vec3& a, const Vec3& b) {
  return pluckerFromPointDirection(a, b - a);
}

// Permuted inner product pi_r (.) pi_s = U_r . V_s + U_s . V_r (eq. 4.15; eq. 4.19 is the same
// sum in another component layout). It equals (P_s - P_r) . (L_r x L_s): > 0 when s goes
// counterclockwise around r seen looking along r, < 0 clockwise, 0 when the lines meet or are
// parallel (eq. 4.16). It is symmetric and independent of the points chosen on the lines.
inline Real permutedInnerProduct(const PluckerLine& r, const PluckerLine& s) {
  return r.u.dot(s.v) + s.u.dot(r.v);
}

// ---- Ray–tetrahedron intersection (Platis & Theoharis 2003; thesis eq. 4.17–4.18, Alg. 4–5) --

struct RayTetHit {
  int face = -1;                  // -1: none
  std::array<Real, 3> weights{};  // barycentric weights of kTetFaceVertices[face][0..2]
  Vec3 point = Vec3::Zero();      // sum_k weights[k] * x[kTetFaceVertices[face][k]]
  Real t = 0;                     // point = origin + t * direction (projected; any sign)
};

struct RayTetIntersection {
  RayTetHit enter;  // face where the directed line goes into the tet
  RayTetHit leave;  // face where it comes out
  bool hit() const { return enter.face >= 0 && leave.face >= 0; }
};

// Intersects the directed line origin + t * direction (all t, not only t >= 0) with the tet.
// Zero, non-finite direction or a degenerate tet: no faces. Ties (the line through a vertex or
// an edge) are resolved by Algorithm 4's face order 3, 2, 1, 0 and still give a valid face whose
// weights are >= 0; a line in a face's plane skips that face (all three products zero) and
// enters/leaves through the faces sharing that face's edges. If rounding makes the six edge
// products inconsistent (lines grazing a vertex), enter or leave may be missing: check.
RayTetIntersection intersectRayTet(const TetPoints& x, const Vec3& origin, const Vec3& direction);

// ---- Pushing a particle out (thesis eq. 4.20) ------------------------------------------------

struct TetPushOut {
  Vec3 position = Vec3::Zero();  // corrected position (== p when nothing was done)
  int face = -1;                 // face it was pushed out through; -1: nothing done
  bool alongRay = false;         // true: along the motion (eq. 4.20); false: nearest face
  Real depth = 0;                // penetration depth removed: |p - entry| or distance to face
  // The wall point the particle is pushed away from, as weights (>= 0, sum 1) of the face's
  // vertices kTetFaceVertices[face][0..2]: the ray's entry point E, or for the nearest-face exit
  // the foot of p on the face plane, brought into the face (triangleWeights). Two-way coupling
  // (particle_tet_collision.h) distributes the wall's reaction over the face with them.
  std::array<Real, 3> faceWeights{};
};

// A particle of radius `radius` at p inside the tet (queryPointInTet(x, p, kBarycentricSlack)
// inside), which was at `previous` before. The ray previous -> p enters the tet at E (Plücker,
// above); the particle goes back along the ray to radius beyond E (thesis eq. 4.20:
// p* = p - r (dist + radius), r the unit motion, dist = |p - E|). The ray is not used when the
// motion is at rounding-noise level, the entry lies outside the segment [previous, p] (previous
// already inside: the tet moved onto the particle), or the result is not outside the tet (a
// numerically grazing ray); then the particle leaves through the nearest face along its outward
// normal n: p* = p + (distance to face + radius) n. p not inside or degenerate tet: unchanged.
//
// In a mesh, the result is outside this tet but may lie inside a neighbour: by at most `radius`
// when the ray entered through a shared face. Pushing again against that neighbour (same
// `previous`) moves the particle further back along the same ray, so repeated passes walk back
// tet by tet to where the ray entered the mesh. The fallback only uses faces whose bit is set in
// `exitFaces` (bit i = face i; pass the mesh-boundary faces, tetBoundaryFaceMasks), otherwise two
// tets could hand a particle back and forth across their shared face; a mask with no bit set
// allows all faces. A tet without boundary faces (deep in a thick wall) and no usable ray cannot
// know the way out: per-tet pushes may then bounce between neighbours, and the caller needs a
// mesh-level fallback (e.g. nearest boundary triangle). See tests/pbd/core/test_tet_geometry.cpp
// (TetPushOut.SharedFaceHandsTheParticleBackAlongTheRay, RepeatedPassesLeaveAJitteredBoxMesh).
//
// Cost: one queryPointInTet, one intersectRayTet, one isPointInTet (~30 cross/dot products and
// 4 square roots); the fallback adds one normal.
TetPushOut pushOutOfTet(const TetPoints& x, const Vec3& p, const Vec3& previous, Real radius,
                        unsigned exitFaces = 0xFu);

// Weights (w_a, w_b, w_c), >= 0 and summing to 1, of a point of the triangle abc near p: the
// barycentric coordinates of p's projection onto the triangle's plane, with negative ones set
// to zero and the rest renormalised (for a projection outside the triangle this is a point on
// its boundary, not necessarily the nearest one). Degenerate triangle or non-finite input:
// (1/3, 1/3, 1/3).
std::array<Real, 3> triangleWeights(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

// For every tet, the bit mask of its faces (bit i = face i, kTetFaceVertices) that lie on the
// mesh boundary, i.e. belong to no other tet. O(T log T); the topology is fixed, compute once.
std::vector<std::uint8_t> tetBoundaryFaceMasks(const std::vector<Tet>& tets);

}  // namespace hs::pbd
