#include "pbd/core/tet_geometry.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace hs::pbd {
namespace {

constexpr Real kEps = std::numeric_limits<Real>::epsilon();
// A motion shorter than 64 eps times the coordinate scale is rounding noise of p - previous:
// its direction means nothing, so the ray test is skipped.
constexpr Real kNoiseMotion = Real(64) * kEps;
// The entry point may lie up to 1e-3 of the tet's longest edge outside the segment
// [previous, p] and still be used: this absorbs rounding and a previous position marginally
// inside, but rejects a previous position really inside (the tet moved onto the particle),
// where the entry behind it says nothing about the shortest way out.
constexpr Real kEntrySlack = Real(1e-3);

Real longestEdgeSquared(const TetPoints& x) {
  Real m = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) m = std::max(m, (x[i] - x[j]).squaredNorm());
  return m;
}

// 6V = (x1 - x0) x (x2 - x0) . (x3 - x0) (TetMesh's signedTetVolume times 6).
Real sixVolume(const TetPoints& x) { return (x[1] - x[0]).cross(x[2] - x[0]).dot(x[3] - x[0]); }

// See kTetDegenerateVolume. Written with ! so that NaN and infinite input count as degenerate.
bool isDegenerate(Real vol6, Real longest2) {
  return !(std::abs(vol6) > kTetDegenerateVolume * longest2 * std::sqrt(longest2));
}

Vec3 faceCross(const TetPoints& x, int i) {
  const auto& f = kTetFaceVertices[std::size_t(i)];
  const Vec3& a = x[std::size_t(f[0])];
  return (x[std::size_t(f[1])] - a).cross(x[std::size_t(f[2])] - a);
}

// lambda_i = -n_i . (p - a_i) / 6V, because n_i . (x_i - a_i) = -6V for every face (the
// faces are outward for a positive tet). This is eq. 4.12 normalised so that the opposite
// vertex has lambda_i = 1; the sign of 6V makes it valid for inverted tets as well. The one
// expression for queryPointInTet and isPointInTet, so that both always agree.
Real barycentricOf(const TetPoints& x, const Vec3& p, Real vol6, int i, const Vec3& n) {
  return -n.dot(p - x[std::size_t(kTetFaceVertices[std::size_t(i)][0])]) / vol6;
}

RayTetHit makeHit(const TetPoints& x, int face, const std::array<Real, 3>& side, const Vec3& origin,
                  const Vec3& direction) {
  // Algorithm 5: the weight of a face vertex is the product of the edge opposite it,
  // normalised by their sum (all three share one sign, so the sum is nonzero).
  RayTetHit h;
  h.face = face;
  const Real sum = side[0] + side[1] + side[2];
  const auto& f = kTetFaceVertices[std::size_t(face)];
  for (int k = 0; k < 3; ++k) {
    h.weights[std::size_t(k)] = side[std::size_t(k)] / sum;
    h.point += h.weights[std::size_t(k)] * x[std::size_t(f[std::size_t(k)])];
  }
  h.t = (h.point - origin).dot(direction) / direction.squaredNorm();
  return h;
}

}  // namespace

TetPointQuery queryPointInTet(const TetPoints& x, const Vec3& p, Real tolerance) {
  TetPointQuery q;
  const Real vol6 = sixVolume(x);
  q.degenerate = isDegenerate(vol6, longestEdgeSquared(x));
  if (q.degenerate || !p.allFinite()) return q;  // not inside, no nearest face
  std::array<Vec3, 4> n;
  for (int i = 0; i < 4; ++i) {
    n[std::size_t(i)] = faceCross(x, i);
    q.barycentric[std::size_t(i)] = barycentricOf(x, p, vol6, i, n[std::size_t(i)]);
  }
  q.inside = true;
  q.depth = std::numeric_limits<Real>::infinity();
  for (std::size_t i = 0; i < 4; ++i) {
    // The height over face i is |6V| / |n_i| (|n_i| is twice its area).
    q.faceDistance[i] = q.barycentric[i] * (std::abs(vol6) / n[i].norm());
    q.inside = q.inside && q.barycentric[i] > -tolerance;
    if (q.faceDistance[i] < q.depth) {
      q.depth = q.faceDistance[i];
      q.nearestFace = int(i);
    }
  }
  return q;
}

bool isPointInTet(const TetPoints& x, const Vec3& p, Real tolerance) {
  // Most grid candidates are outside: exit at the first failing face, and test degeneracy
  // (6 edge lengths) only for a point that passed all four. Written as "!(lambda > -tolerance)"
  // so that NaN (non-finite p, or 6V = 0) counts as outside.
  const Real vol6 = sixVolume(x);
  for (int i = 0; i < 4; ++i)
    if (!(barycentricOf(x, p, vol6, i, faceCross(x, i)) > -tolerance)) return false;
  return !isDegenerate(vol6, longestEdgeSquared(x));
}

Vec3 tetFaceNormal(const TetPoints& x, int face) {
  assert(face >= 0 && face < 4);
  const Real vol6 = sixVolume(x);
  if (isDegenerate(vol6, longestEdgeSquared(x))) return Vec3::Zero();
  const Vec3 n = faceCross(x, face);
  return (vol6 > 0 ? Real(1) : Real(-1)) * n.normalized();
}

RayTetIntersection intersectRayTet(const TetPoints& x, const Vec3& origin, const Vec3& direction) {
  RayTetIntersection r;
  const Real vol6 = sixVolume(x);
  if (!(direction.squaredNorm() > 0) || !direction.allFinite() || !origin.allFinite() ||
      isDegenerate(vol6, longestEdgeSquared(x)))
    return r;

  // pi_r (.) pi_e for the 6 edges x_i -> x_j (i < j), each computed once and shared, with the
  // opposite sign, by the two faces that traverse the edge in opposite directions: Platis &
  // Theoharis's key to consistency, as a line near an edge then falls in exactly one of the two
  // faces. Translating everything by -origin makes the ray's moment zero, so eq. 4.15 reduces
  // to L . V_e with V_e = (b - a) x a = b x a: 6 cross products instead of 12, and no precision
  // lost to large moments when the tet is far from the coordinate origin.
  std::array<Vec3, 4> rel;
  for (std::size_t i = 0; i < 4; ++i) rel[i] = x[i] - origin;
  std::array<std::array<Real, 4>, 4> side{};  // side[i][j] = -side[j][i]
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = i + 1; j < 4; ++j) {
      side[i][j] = direction.dot(rel[j].cross(rel[i]));
      side[j][i] = -side[i][j];
    }

  // Algorithm 4 with delta = sign of the products (eq. 4.18). For face (a, b, c) the edges are
  // e0 = b -> c, e1 = c -> a, e2 = a -> b; with outward faces, a line entering goes
  // counterclockwise around all three (products >= 0, eq. 4.17), a leaving one clockwise. A face
  // whose three products are all zero is coplanar with the line and skipped. The first face in
  // the order 3, 2, 1, 0 wins ties (a line through an edge or a vertex).
  int enter = -1, leave = -1;
  std::array<Real, 3> enterSide{}, leaveSide{};
  for (int i = 3; i >= 0; --i) {
    const auto& f = kTetFaceVertices[std::size_t(i)];
    const std::size_t a = std::size_t(f[0]), b = std::size_t(f[1]), c = std::size_t(f[2]);
    const std::array<Real, 3> s{side[b][c], side[c][a], side[a][b]};
    if (s[0] == 0 && s[1] == 0 && s[2] == 0) continue;
    if (enter < 0 && s[0] >= 0 && s[1] >= 0 && s[2] >= 0) {
      enter = i;
      enterSide = s;
    } else if (leave < 0 && s[0] <= 0 && s[1] <= 0 && s[2] <= 0) {
      leave = i;
      leaveSide = s;
    }
  }
  // An inverted tet has inward faces: "counterclockwise" then means leaving.
  if (vol6 < 0) {
    std::swap(enter, leave);
    std::swap(enterSide, leaveSide);
  }
  if (enter >= 0) r.enter = makeHit(x, enter, enterSide, origin, direction);
  if (leave >= 0) r.leave = makeHit(x, leave, leaveSide, origin, direction);
  return r;
}

TetPushOut pushOutOfTet(const TetPoints& x, const Vec3& p, const Vec3& previous, Real radius,
                        unsigned exitFaces) {
  assert(radius >= 0);
  TetPushOut out;
  out.position = p;
  const TetPointQuery q = queryPointInTet(x, p, kBarycentricSlack);
  if (q.degenerate || !q.inside) return out;

  const Real longest = std::sqrt(longestEdgeSquared(x));
  const Vec3 motion = p - previous;
  const Real length = motion.norm();
  const Real scale = std::max(longest, p.cwiseAbs().maxCoeff());
  if (std::isfinite(length) && length > kNoiseMotion * scale) {
    const RayTetIntersection hit = intersectRayTet(x, previous, motion);
    const Real slack = kEntrySlack * longest / length;
    if (hit.enter.face >= 0 && hit.enter.t >= -slack && hit.enter.t <= 1 + slack) {
      // Eq. 4.20: p* = p - r (dist + radius) = E - radius r, with r the unit motion.
      const Vec3 unit = motion / length;
      const Vec3 candidate = hit.enter.point - radius * unit;
      // The normal clearance is radius |r . n|: a grazing ray may leave the particle within
      // rounding of the face, where a detection with kBarycentricSlack would find it again.
      if (candidate.allFinite() && !isPointInTet(x, candidate, kBarycentricSlack)) {
        out.position = candidate;
        out.face = hit.enter.face;
        out.alongRay = true;
        out.depth = (p - hit.enter.point).norm();
        out.faceWeights = hit.enter.weights;
        return out;
      }
    }
  }
  // Fallback: out through the nearest allowed face plane, to `radius` beyond it.
  if ((exitFaces & 0xFu) == 0) exitFaces = 0xFu;
  int f = -1;
  for (int i = 0; i < 4; ++i)
    if ((exitFaces >> i) & 1u)
      if (f < 0 || q.faceDistance[std::size_t(i)] < q.faceDistance[std::size_t(f)]) f = i;
  out.position = p + (q.faceDistance[std::size_t(f)] + radius) * tetFaceNormal(x, f);
  out.face = f;
  out.depth = std::max(q.faceDistance[std::size_t(f)], Real(0));
  const auto& fv = kTetFaceVertices[std::size_t(f)];
  out.faceWeights = triangleWeights(p, x[std::size_t(fv[0])], x[std::size_t(fv[1])], x[std::size_t(fv[2])]);
  return out;
}

std::array<Real, 3> triangleWeights(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  // w_a = N . ((b - p) x (c - p)) / N . N with N = (b - a) x (c - a), and cyclically: twice the
  // signed area of the sub-triangle opposite a over twice the whole. The component of p - a
  // along N drops out of N . (...), so this is the projection's coordinates.
  constexpr Real kThird = Real(1) / Real(3);
  const std::array<Real, 3> even{kThird, kThird, kThird};
  const Vec3 n = (b - a).cross(c - a);
  const Real nn = n.squaredNorm();
  if (!(nn > 0) || !p.allFinite() || !std::isfinite(nn)) return even;
  std::array<Real, 3> w{n.dot((b - p).cross(c - p)) / nn, n.dot((c - p).cross(a - p)) / nn,
                        n.dot((a - p).cross(b - p)) / nn};
  Real sum = 0;
  for (Real& v : w) {
    v = std::max(v, Real(0));
    sum += v;
  }
  if (!(sum > 0) || !std::isfinite(sum)) return even;
  for (Real& v : w) v /= sum;
  return w;
}

std::vector<std::uint8_t> tetBoundaryFaceMasks(const std::vector<Tet>& tets) {
  // Every face as (sorted vertex ids, tet, local face); after sorting, a key that occurs once
  // belongs to one tet only and is on the boundary.
  struct FaceRef {
    std::array<Index, 3> key;
    Index tet;
    int face;
  };
  std::vector<FaceRef> faces;
  faces.reserve(4 * tets.size());
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (int i = 0; i < 4; ++i) {
      const auto& f = kTetFaceVertices[std::size_t(i)];
      std::array<Index, 3> key{tets[t][std::size_t(f[0])], tets[t][std::size_t(f[1])],
                               tets[t][std::size_t(f[2])]};
      std::sort(key.begin(), key.end());
      faces.push_back({key, Index(t), i});
    }
  std::sort(faces.begin(), faces.end(), [](const FaceRef& a, const FaceRef& b) { return a.key < b.key; });
  std::vector<std::uint8_t> masks(tets.size(), 0);
  for (std::size_t k = 0; k < faces.size();) {
    std::size_t e = k + 1;
    while (e < faces.size() && faces[e].key == faces[k].key) ++e;
    if (e - k == 1) masks[faces[k].tet] = std::uint8_t(masks[faces[k].tet] | (1u << faces[k].face));
    k = e;
  }
  return masks;
}

}  // namespace hs::pbd
