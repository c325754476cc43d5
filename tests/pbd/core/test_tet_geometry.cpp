// Over 400 lines on purpose: one test file per module, its cases sharing the file's set-up helpers.
// Point-in-tet, Plücker ray–tet intersection and push-out against brute-force references in
// double: signed volumes, point–triangle distances and Möller–Trumbore on the four faces.
// Degenerate rays (through a vertex, an edge, in a face plane, zero or NaN direction) must give
// sane answers and never NaN. Push-out is checked for one tet, a pair sharing a face and a small
// jittered box mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <vector>

#include "box_mesh.h"
#include "pbd/core/tet_geometry.h"

namespace hs::pbd {
namespace {

using Vec3d = Eigen::Vector3d;
Vec3d d(const Vec3& v) { return v.cast<double>(); }

// Well-shaped random tet: 4 points in [-1, 1]^3 + offset with 6|V| >= 0.05 L^3.
TetPoints randomTet(std::mt19937& rng, const Vec3& offset, bool positive = true) {
  std::uniform_real_distribution<float> u(-1, 1);
  for (;;) {
    TetPoints x;
    for (Vec3& v : x) v = Vec3(Real(u(rng)), Real(u(rng)), Real(u(rng))) + offset;
    const double v6 = (d(x[1]) - d(x[0])).cross(d(x[2]) - d(x[0])).dot(d(x[3]) - d(x[0]));
    double l2 = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) l2 = std::max(l2, (d(x[i]) - d(x[j])).squaredNorm());
    if (std::abs(v6) < 0.05 * l2 * std::sqrt(l2)) continue;
    if ((v6 > 0) != positive) std::swap(x[2], x[3]);
    return x;
  }
}

// A random point of the tet (random convex weights, not uniform in volume; may lie on rounding
// distance from a face).
Vec3 randomPointIn(const TetPoints& x, std::mt19937& rng) {
  std::uniform_real_distribution<float> u(0, 1);
  Vec3 p = Vec3::Zero();
  Real sum = 0;
  for (const Vec3& v : x) {
    const Real w = Real(u(rng));
    p += w * v;
    sum += w;
  }
  return p / sum;
}

// A random point with every barycentric coordinate >= 0.1.
Vec3 wellInsidePoint(const TetPoints& x, std::mt19937& rng) {
  std::uniform_real_distribution<float> u(0, 1);
  std::array<Real, 4> w;
  for (Real& v : w) v = Real(u(rng));
  const Real sum = w[0] + w[1] + w[2] + w[3];
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i < 4; ++i) p += (Real(0.1) + Real(0.6) * w[i] / sum) * x[i];
  return p;
}

// Reference barycentric coordinates: signed volume with vertex i replaced by p, over the volume.
std::array<double, 4> refBarycentric(const TetPoints& x, const Vec3& p) {
  auto vol = [](const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& e) {
    return (b - a).cross(c - a).dot(e - a);
  };
  const double v = vol(d(x[0]), d(x[1]), d(x[2]), d(x[3]));
  std::array<double, 4> l;
  for (int i = 0; i < 4; ++i) {
    std::array<Vec3d, 4> y{d(x[0]), d(x[1]), d(x[2]), d(x[3])};
    y[std::size_t(i)] = d(p);
    l[std::size_t(i)] = vol(y[0], y[1], y[2], y[3]) / v;
  }
  return l;
}

// Distance from p to triangle (a, b, c) (Ericson, Real-Time Collision Detection, 5.1.5).
double pointTriangleDistance(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const Vec3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return (p - a).norm();
  const Vec3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return (p - b).norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const Vec3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return (p - c).norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  const double den = 1 / (va + vb + vc);
  return (p - (a + ab * vb * den + ac * vc * den)).norm();
}

// Möller–Trumbore against the line o + t dir (any t): t and the smallest barycentric (margin).
struct MtHit {
  double t, margin, cosine;  // cosine of dir with the outward normal
  Vec3d point;
};
std::optional<MtHit> mollerTrumbore(const Vec3d& o, const Vec3d& dir, const Vec3d& a, const Vec3d& b,
                                    const Vec3d& c, const Vec3d& outward) {
  const Vec3d e1 = b - a, e2 = c - a, h = dir.cross(e2);
  const double det = e1.dot(h);
  if (std::abs(det) < 1e-12 * dir.norm() * e1.norm() * e2.norm()) return std::nullopt;
  const Vec3d s = o - a, q = s.cross(e1);
  const double u = s.dot(h) / det, v = dir.dot(q) / det, t = e2.dot(q) / det;
  return MtHit{t, std::min({u, v, 1 - u - v}), dir.normalized().dot(outward.normalized()), o + t * dir};
}

// Reference entering and leaving faces of the line through the tet (or nothing); `clear` when
// every face is hit or missed by a margin and the hits are not grazing.
struct RefRay {
  int enter = -1, leave = -1;
  MtHit enterHit{}, leaveHit{};
  bool clear = true;
};
RefRay referenceRay(const TetPoints& x, const Vec3& o, const Vec3& dir) {
  RefRay r;
  const double sign = (d(x[1]) - d(x[0])).cross(d(x[2]) - d(x[0])).dot(d(x[3]) - d(x[0])) > 0 ? 1 : -1;
  for (int i = 0; i < 4; ++i) {
    const auto& f = kTetFaceVertices[std::size_t(i)];
    const Vec3d a = d(x[std::size_t(f[0])]), b = d(x[std::size_t(f[1])]), c = d(x[std::size_t(f[2])]);
    const auto hit = mollerTrumbore(d(o), d(dir), a, b, c, sign * (b - a).cross(c - a));
    if (!hit || std::abs(hit->margin) < 1e-3) {
      r.clear = false;
      continue;
    }
    if (hit->margin < 0) continue;
    if (std::abs(hit->cosine) < 0.05) r.clear = false;
    (hit->cosine < 0 ? r.enter : r.leave) = i;
    (hit->cosine < 0 ? r.enterHit : r.leaveHit) = *hit;
  }
  return r;
}

bool finite(const RayTetHit& h) { return h.point.allFinite() && std::isfinite(h.t); }

TEST(TetPlucker, PermutedInnerProductIsTripleProductAndSymmetric) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-2, 2);
  auto rnd = [&] { return Vec3(Real(u(rng)), Real(u(rng)), Real(u(rng))); };
  for (int k = 0; k < 1000; ++k) {
    const Vec3 pr = rnd(), lr = rnd(), ps = rnd(), ls = rnd();
    const PluckerLine r = pluckerFromPointDirection(pr, lr), s = pluckerFromPointDirection(ps, ls);
    const double expected = (d(ps) - d(pr)).dot(d(lr).cross(d(ls)));  // (P_s - P_r) . (L_r x L_s)
    EXPECT_NEAR(double(permutedInnerProduct(r, s)), expected, 1e-4);
    EXPECT_EQ(permutedInnerProduct(r, s), permutedInnerProduct(s, r));
    // Another point on s: same line, same product (eq. 4.14 is point independent).
    EXPECT_NEAR(double(permutedInnerProduct(r, pluckerFromPointDirection(ps + Real(0.7) * ls, ls))), expected,
                1e-4);
    // Lines through a common point meet: product zero (eq. 4.16).
    EXPECT_NEAR(double(permutedInnerProduct(r, pluckerFromPointDirection(pr + Real(0.5) * lr, ls))), 0.0,
                1e-4);
  }
  // r = z axis, s = line x = 1 going +y: seen looking along +z (x right, y down) s passes the
  // right side downwards, i.e. clockwise, and the product is negative (eq. 4.16).
  const PluckerLine r = pluckerFromPointDirection(Vec3(0, 0, 0), Vec3(0, 0, 1));
  EXPECT_LT(permutedInnerProduct(r, pluckerFromPointDirection(Vec3(1, 0, 0), Vec3(0, 1, 0))), 0);
  EXPECT_GT(permutedInnerProduct(r, pluckerFromPointDirection(Vec3(1, 0, 0), Vec3(0, -1, 0))), 0);
  // A ray entering the unit tet's face 3 (z = 0, outward normal -z) goes counterclockwise
  // around its three edges b -> c, c -> a, a -> b (eq. 4.17).
  const TetPoints x{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  const PluckerLine ray = pluckerFromPointDirection(Vec3(Real(0.2), Real(0.3), -1), Vec3(0, 0, 1));
  const auto& f = kTetFaceVertices[3];
  for (int k = 0; k < 3; ++k) {
    const PluckerLine e = pluckerFromPoints(x[std::size_t(f[std::size_t((k + 1) % 3)])],
                                            x[std::size_t(f[std::size_t((k + 2) % 3)])]);
    EXPECT_GT(permutedInnerProduct(ray, e), 0) << "edge " << k;
  }
}

TEST(TetPlucker, RayTetMatchesMollerTrumboreOnRandomRays) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1, 1);
  int clearHits = 0, clearMisses = 0, unclear = 0;
  for (int tet = 0; tet < 200; ++tet) {
    const Vec3 offset = tet % 2 ? Vec3(Real(3.3), Real(-1.7), Real(0.4)) : Vec3::Zero();
    const TetPoints x = randomTet(rng, offset, tet % 5 != 0);  // every fifth tet inverted
    for (int ray = 0; ray < 50; ++ray) {
      const Vec3 o = offset + Real(2.5) * Vec3(Real(u(rng)), Real(u(rng)), Real(u(rng)));
      // Half the rays aim at a random point of the tet, half at a random point of its box.
      const Vec3 target =
          ray % 2 ? offset + Vec3(Real(u(rng)), Real(u(rng)), Real(u(rng))) : randomPointIn(x, rng);
      const Vec3 dir = (target - o) * Real(ray % 3 == 0 ? 0.01 : 1);  // length must not matter
      const RayTetIntersection got = intersectRayTet(x, o, dir);
      const RefRay ref = referenceRay(x, o, dir);
      if (got.enter.face >= 0) {
        EXPECT_TRUE(finite(got.enter));
        for (Real w : got.enter.weights) EXPECT_GE(w, 0);
      }
      if (got.leave.face >= 0) {
        EXPECT_TRUE(finite(got.leave));
      }
      if (!ref.clear) {
        ++unclear;
        continue;
      }
      ASSERT_EQ(got.enter.face, ref.enter) << "tet " << tet << " ray " << ray;
      ASSERT_EQ(got.leave.face, ref.leave) << "tet " << tet << " ray " << ray;
      if (ref.enter < 0) {
        ++clearMisses;
        continue;
      }
      ++clearHits;
      EXPECT_LT((d(got.enter.point) - ref.enterHit.point).norm(), 1e-4);
      EXPECT_LT((d(got.leave.point) - ref.leaveHit.point).norm(), 1e-4);
      EXPECT_NEAR(double(got.enter.t), ref.enterHit.t, 1e-4 * (1 + std::abs(ref.enterHit.t)));
      EXPECT_LT(got.enter.t, got.leave.t);
    }
  }
  EXPECT_GT(clearHits, 5000);
  EXPECT_GT(clearMisses, 1000);
  EXPECT_LT(unclear, 2000);
  std::printf("clear hits %d, clear misses %d, near an edge or grazing %d\n", clearHits, clearMisses,
              unclear);
}

// The unit tet: exact coordinates, so the products of the degenerate rays below are exactly 0.
TetPoints unitTet() { return {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}; }

void expectHitNear(const RayTetHit& h, const Vec3& expected, const char* what) {
  SCOPED_TRACE(what);
  ASSERT_GE(h.face, 0);
  EXPECT_TRUE(finite(h));
  for (Real w : h.weights) EXPECT_GE(w, 0);
  EXPECT_LT((h.point - expected).norm(), 1e-5);
}

TEST(TetPlucker, DegenerateRaysGiveSaneFaces) {
  const TetPoints x = unitTet();
  // Through vertex 0 and the centroid: enters at the vertex (t = 1), leaves through face 0.
  RayTetIntersection r = intersectRayTet(x, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  expectHitNear(r.enter, Vec3(0, 0, 0), "vertex: enter");
  EXPECT_NEAR(r.enter.t, 1, 1e-6);
  expectHitNear(r.leave, Vec3::Constant(Real(1) / 3), "vertex: leave");
  EXPECT_EQ(r.leave.face, 0);
  // Through the midpoint of edge 1-2 and the centroid: enters and leaves through edges.
  r = intersectRayTet(x, Vec3(Real(0.75), Real(0.75), Real(-0.25)),
                      Vec3(Real(-0.25), Real(-0.25), Real(0.25)));
  expectHitNear(r.enter, Vec3(Real(0.5), Real(0.5), 0), "edge: enter");
  expectHitNear(r.leave, Vec3(0, 0, Real(0.5)), "edge: leave");
  EXPECT_NEAR(r.enter.t, 1, 1e-6);
  EXPECT_NEAR(r.leave.t, 3, 1e-6);
  // In the plane of face 3 (z = 0), through it: face 3 is skipped, the line enters through
  // face 1 (x = 0) on edge 0-2 and leaves through face 0 on edge 1-2.
  r = intersectRayTet(x, Vec3(-1, Real(0.25), 0), Vec3(1, 0, 0));
  expectHitNear(r.enter, Vec3(0, Real(0.25), 0), "coplanar: enter");
  expectHitNear(r.leave, Vec3(Real(0.75), Real(0.25), 0), "coplanar: leave");
  EXPECT_EQ(r.enter.face, 1);
  EXPECT_EQ(r.leave.face, 0);
  // In the plane of face 3 but beside the triangle; only touching edge 1-2 at a point.
  r = intersectRayTet(x, Vec3(-1, 2, 0), Vec3(1, 0, 0));
  EXPECT_FALSE(r.hit());
  r = intersectRayTet(x, Vec3(Real(0.5), Real(0.5), -1), Vec3(0, 0, 1));
  if (r.enter.face >= 0) expectHitNear(r.enter, Vec3(Real(0.5), Real(0.5), 0), "touching edge");
  // Along an edge (the line of edge 0-1): every face either contains it or touches it.
  r = intersectRayTet(x, Vec3(-1, 0, 0), Vec3(1, 0, 0));
  if (r.enter.face >= 0) {
    EXPECT_TRUE(finite(r.enter));
  }
  if (r.leave.face >= 0) {
    EXPECT_TRUE(finite(r.leave));
  }
  // Zero, NaN direction, NaN origin, flat tet: nothing.
  EXPECT_EQ(intersectRayTet(x, Vec3(-1, 0, 0), Vec3::Zero()).enter.face, -1);
  EXPECT_EQ(intersectRayTet(x, Vec3(-1, 0, 0), Vec3::Constant(std::nanf(""))).enter.face, -1);
  EXPECT_EQ(intersectRayTet(x, Vec3::Constant(std::nanf("")), Vec3(1, 0, 0)).enter.face, -1);
  const TetPoints flat{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
  EXPECT_EQ(intersectRayTet(flat, Vec3(Real(0.3), Real(0.3), -1), Vec3(0, 0, 1)).enter.face, -1);
}

TEST(TetPlucker, DegenerateRaysSurviveRoundingAfterATransform) {
  // The same rays on a rotated, scaled, shifted copy: products are no longer exactly 0, so a
  // face wins by rounding; the point must still be the vertex or edge point.
  const Eigen::Matrix<Real, 3, 3> rot =
      Eigen::AngleAxis<Real>(Real(0.7), Vec3(1, 2, 3).normalized()).toRotationMatrix();
  auto T = [&](const Vec3& v) {
    Vec3 r = Real(0.037) * (rot * v) + Vec3(Real(0.011), Real(-0.02), Real(0.05));
    return r;
  };
  auto L = [&](const Vec3& v) {
    Vec3 r = Real(0.037) * (rot * v);
    return r;
  };
  const TetPoints u = unitTet();
  const TetPoints x{T(u[0]), T(u[1]), T(u[2]), T(u[3])};
  const Real s = Real(0.037);
  RayTetIntersection r = intersectRayTet(x, T(Vec3(-1, -1, -1)), L(Vec3(1, 1, 1)));
  ASSERT_GE(r.enter.face, 0);
  EXPECT_LT((r.enter.point - x[0]).norm(), 1e-5 * s * 100);
  r = intersectRayTet(x, T(Vec3(Real(0.75), Real(0.75), Real(-0.25))),
                      L(Vec3(Real(-0.25), Real(-0.25), Real(0.25))));
  ASSERT_GE(r.enter.face, 0);
  EXPECT_LT((r.enter.point - T(Vec3(Real(0.5), Real(0.5), 0))).norm(), 1e-3 * s);
  r = intersectRayTet(x, T(Vec3(-1, Real(0.25), 0)), L(Vec3(1, 0, 0)));
  for (const RayTetHit* h : {&r.enter, &r.leave})
    if (h->face >= 0) {
      EXPECT_TRUE(finite(*h));
    }
}

TEST(TetPointQuery, MatchesSignedVolumesOnRandomPoints) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.2f, 1.2f);
  int inside = 0;
  for (int tet = 0; tet < 100; ++tet) {
    const Vec3 offset(Real(tet % 3) * Real(0.5), Real(-0.25), Real(1));
    const TetPoints x = randomTet(rng, offset, tet % 4 != 0);
    for (int k = 0; k < 100; ++k) {
      const Vec3 p = k % 2 ? offset + Vec3(Real(u(rng)), Real(u(rng)), Real(u(rng))) : randomPointIn(x, rng);
      const TetPointQuery q = queryPointInTet(x, p);
      const std::array<double, 4> ref = refBarycentric(x, p);
      ASSERT_FALSE(q.degenerate);
      for (int i = 0; i < 4; ++i)
        EXPECT_NEAR(double(q.barycentric[std::size_t(i)]), ref[std::size_t(i)], 1e-4);
      const double minRef = *std::min_element(ref.begin(), ref.end());
      if (std::abs(minRef) > 1e-4) {
        EXPECT_EQ(q.inside, minRef > 0);
      }
      EXPECT_EQ(isPointInTet(x, p), q.inside);
      EXPECT_EQ(isPointInTet(x, p, Real(0.1)), queryPointInTet(x, p, Real(0.1)).inside);
      double dist = 1e30;  // distance to the boundary: nearest of the four triangles
      for (const auto& f : kTetFaceVertices)
        dist = std::min(dist, pointTriangleDistance(d(p), d(x[std::size_t(f[0])]), d(x[std::size_t(f[1])]),
                                                    d(x[std::size_t(f[2])])));
      if (minRef > 0) {
        ++inside;
        EXPECT_NEAR(double(q.depth), dist, 1e-5);  // inside: depth = distance to the boundary
      } else {
        EXPECT_LE(double(q.depth), 1e-6);
        EXPECT_LE(-double(q.depth), dist + 1e-5);  // outside: a lower bound of the distance
      }
    }
  }
  EXPECT_GT(inside, 5000);
  // Tolerance semantics on the face x + y + z = 1 of the unit tet (point exactly on it).
  const TetPoints x = unitTet();
  const Vec3 onFace(Real(0.25), Real(0.25), Real(0.5));
  EXPECT_TRUE(isPointInTet(x, onFace, kBarycentricSlack));
  EXPECT_FALSE(isPointInTet(x, onFace, -kBarycentricSlack));
  const TetPoints flat{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
  EXPECT_TRUE(queryPointInTet(flat, Vec3(Real(0.3), Real(0.3), 0)).degenerate);
  EXPECT_FALSE(isPointInTet(flat, Vec3(Real(0.3), Real(0.3), 0), Real(1)));
  EXPECT_FALSE(queryPointInTet(x, Vec3::Constant(std::nanf(""))).inside);
}

TEST(TetPlucker, RaysThroughRandomEdgeAndVertexPoints) {
  // A line through an edge point into the tet: the shared edge product makes exactly one of the
  // two faces at the edge accept it, whatever the rounding, so "enter" always exists. Through a
  // vertex three products are near zero and may disagree: then only sanity is required.
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(0, 1);
  int vertexEntered = 0;
  for (int k = 0; k < 2000; ++k) {
    const TetPoints x = randomTet(rng, Vec3(Real(0.2), Real(-0.4), Real(1.3)), k % 3 != 0);
    const int i = k % 4, j = (k / 4 + i + 1) % 4;
    const Real w = Real(u(rng));
    const Vec3 edgePoint =
        k % 8 < 4 ? Vec3((1 - w) * x[std::size_t(i)] + w * x[std::size_t(j)]) : x[std::size_t(i)];
    const Vec3 dir = wellInsidePoint(x, rng) - edgePoint;  // not grazing a face
    const RayTetIntersection r = intersectRayTet(x, edgePoint - dir, dir);
    for (const RayTetHit* h : {&r.enter, &r.leave}) {
      if (h->face >= 0) {
        EXPECT_TRUE(finite(*h));
      }
    }
    if (k % 8 < 4) {
      ASSERT_GE(r.enter.face, 0) << k;
      EXPECT_LT((r.enter.point - edgePoint).norm(), 2e-4) << k;
    } else if (r.enter.face >= 0) {
      ++vertexEntered;
      EXPECT_LT((r.enter.point - edgePoint).norm(), 2e-4) << k;
    }
  }
  std::printf("lines through a vertex with an entering face: %d of 1000\n", vertexEntered);
}

// ---- Push-out ---------------------------------------------------------------------------------

bool insideAny(const std::vector<TetPoints>& tets, const Vec3& p) {
  return std::any_of(tets.begin(), tets.end(),
                     [&](const TetPoints& x) { return isPointInTet(x, p, kBarycentricSlack); });
}

TEST(TetPushOut, SingleTetAlongTheRayMatchesReferenceEntry) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<float> u(-1, 1);
  int alongRay = 0, total = 0;
  for (int k = 0; k < 2000; ++k) {
    const TetPoints x = randomTet(rng, Vec3(Real(-0.3), Real(0.1), Real(0.8)), k % 4 != 0);
    const Vec3 p = randomPointIn(x, rng);
    const Vec3 dir = Vec3(Real(u(rng)), Real(u(rng)), Real(u(rng))).normalized();
    const Vec3 previous = p - Real(4) * dir;  // the tet fits in a box of side 2: outside
    const Real radius = Real(0.02);
    if (!isPointInTet(x, p, kBarycentricSlack) || isPointInTet(x, previous, kBarycentricSlack)) continue;
    ++total;
    const TetPushOut out = pushOutOfTet(x, p, previous, radius);
    ASSERT_GE(out.face, 0);
    ASSERT_TRUE(out.position.allFinite());
    EXPECT_FALSE(isPointInTet(x, out.position, kBarycentricSlack)) << k;
    const TetPointQuery after = queryPointInTet(x, out.position);
    EXPECT_LE(after.depth, 0);
    EXPECT_GE(after.depth, -radius - Real(1e-5));  // no farther than radius from the face plane
    const RefRay ref = referenceRay(x, previous, p - previous);
    if (out.alongRay) ++alongRay;
    if (!ref.clear) continue;
    ASSERT_TRUE(out.alongRay) << k;
    EXPECT_EQ(out.face, ref.enter);
    // Eq. 4.20: radius behind the entry point along the motion.
    EXPECT_LT((d(out.position) - (ref.enterHit.point - double(radius) * d(dir))).norm(), 1e-4) << k;
    EXPECT_NEAR(double(out.depth), (d(p) - ref.enterHit.point).norm(), 1e-4);
  }
  EXPECT_GT(total, 1500);
  EXPECT_GT(alongRay, total * 99 / 100);
}

TEST(TetPushOut, FallsBackToTheNearestFace) {
  const TetPoints x = unitTet();
  const Real radius = Real(0.05);
  const Vec3 p(Real(0.1), Real(0.3), Real(0.2));  // nearest face: face 1 (x = 0), distance 0.1
  const Vec3 expected(-radius, Real(0.3), Real(0.2));
  const std::vector<Vec3> previous{
      p,                                                         // no motion
      Vec3(Real(0.2), Real(0.25), Real(0.25)),                   // previous inside: the tet moved onto it
      Vec3(std::nanf(""), 0, 0),                                 // garbage
      p - Vec3(0, 0, std::numeric_limits<Real>::denorm_min())};  // motion at noise level
  for (const Vec3& prev : previous) {
    const TetPushOut out = pushOutOfTet(x, p, prev, radius);
    EXPECT_FALSE(out.alongRay);
    EXPECT_EQ(out.face, 1);
    EXPECT_LT((out.position - expected).norm(), 1e-6);
    EXPECT_NEAR(out.depth, Real(0.1), 1e-6);
  }
  // Only faces 0 and 3 may be used (say faces 1 and 2 are shared with neighbours): out through
  // face 3 (z = 0), the nearer of the two.
  const TetPushOut masked = pushOutOfTet(x, p, p, radius, 0b1001u);
  EXPECT_EQ(masked.face, 3);
  EXPECT_LT((masked.position - Vec3(Real(0.1), Real(0.3), -radius)).norm(), 1e-6);
  // Not inside, or a flat tet: unchanged.
  const Vec3 outside(Real(0.6), Real(0.6), Real(0.6));
  EXPECT_EQ(pushOutOfTet(x, outside, Vec3(-1, -1, -1), radius).face, -1);
  EXPECT_EQ(pushOutOfTet(x, outside, Vec3(-1, -1, -1), radius).position, outside);
  const TetPoints flat{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
  EXPECT_EQ(pushOutOfTet(flat, Vec3(Real(0.3), Real(0.3), 0), Vec3(0, 0, -1), radius).face, -1);
}

TEST(TetPushOut, SharedFaceHandsTheParticleBackAlongTheRay) {
  // A = unit tet, B = (x1, x2, x3, (1,1,1)) on the other side of their shared face
  // x + y + z = 1 (face 0 of A, face 3 of B).
  const TetPoints a = unitTet();
  const TetPoints b{Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 1, 1)};
  const std::vector<TetPoints> both{a, b};
  const Real radius = Real(0.05);
  const Vec3 p = Vec3::Constant(Real(0.5));  // inside B
  ASSERT_TRUE(isPointInTet(b, p) && !isPointInTet(a, p));

  // 1. Came from outside through A (entered A at x = 0, crossed the shared face into B). The
  //    push out of B stops radius before the shared face: inside A, at depth <= radius. A second
  //    push, out of A with the same previous position, continues back along the ray to radius
  //    before where it entered A: outside both.
  const Vec3 previous(Real(-0.5), Real(0.2), Real(0.3));
  const TetPushOut first = pushOutOfTet(b, p, previous, radius);
  EXPECT_TRUE(first.alongRay);
  EXPECT_EQ(first.face, 3);
  const TetPointQuery inA = queryPointInTet(a, first.position);
  EXPECT_TRUE(inA.inside);
  EXPECT_LE(inA.depth, radius);
  const TetPushOut second = pushOutOfTet(a, first.position, previous, radius);
  EXPECT_TRUE(second.alongRay);
  EXPECT_EQ(second.face, 1);
  EXPECT_FALSE(insideAny(both, second.position));
  const Vec3 entryA(0, Real(0.35), Real(0.4));
  EXPECT_LT((second.position - (entryA - radius * (p - previous).normalized())).norm(), 1e-5);

  // 2. Came straight into B through its own outer face: one push, outside both.
  const TetPushOut direct = pushOutOfTet(b, p, Vec3(Real(0.9), Real(0.9), Real(0.1)), radius);
  EXPECT_TRUE(direct.alongRay);
  EXPECT_FALSE(insideAny(both, direct.position));

  // 3. No usable ray (no motion) near the shared face: with all faces allowed the particle goes
  //    through the shared face into A, and A, seeing the motion back across that face, would
  //    return it. With the boundary masks the fallback only uses outer faces and one push ends
  //    outside both.
  const std::vector<std::uint8_t> masks = tetBoundaryFaceMasks({{0, 1, 2, 3}, {1, 2, 3, 4}});
  EXPECT_EQ(masks, (std::vector<std::uint8_t>{0b1110, 0b0111}));
  const Vec3 nearShared(Real(0.36), Real(0.36), Real(0.36));
  const TetPushOut unmasked = pushOutOfTet(b, nearShared, nearShared, radius);
  EXPECT_EQ(unmasked.face, 3);
  EXPECT_TRUE(isPointInTet(a, unmasked.position));
  const TetPushOut masked = pushOutOfTet(b, nearShared, nearShared, radius, masks[1]);
  EXPECT_NE(masked.face, 3);
  EXPECT_FALSE(insideAny(both, masked.position));
}

TEST(TetPushOut, RepeatedPassesLeaveAJitteredBoxMesh) {
  // The loop an integrator runs: while some tet contains the particle, push it out of that tet
  // with the boundary-face mask. A particle that came from outside the mesh walks back along its
  // ray tet by tet and leaves where it entered. A particle whose previous position was inside
  // the same tet (the mesh moved onto it) leaves through that tet's nearest boundary face in one
  // push, if the tet has one. A tet with no boundary face (deep inside a thick wall) and no
  // usable ray cannot know the way out: per-tet pushes may then hand the particle back and
  // forth, and the integrator needs a mesh-level fallback (nearest boundary triangle).
  TetMesh mesh = testing::makeBoxMesh(3, Real(0.01));
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> jitter(-0.0015f, 0.0015f), u(0, 1);
  for (Vec3& v : mesh.vertices) v += Vec3(Real(jitter(rng)), Real(jitter(rng)), Real(jitter(rng)));
  std::vector<TetPoints> tets;
  for (const Tet& t : mesh.tets) tets.push_back(tetPoints(mesh.vertices, t));
  const std::vector<std::uint8_t> masks = tetBoundaryFaceMasks(mesh.tets);
  const Real radius = Real(0.0005);
  auto containing = [&](const Vec3& p) {
    int found = -1;
    for (std::size_t t = 0; t < tets.size() && found < 0; ++t)
      if (isPointInTet(tets[t], p, kBarycentricSlack)) found = int(t);
    return found;
  };
  int maxPasses = 0, fromOutside = 0, movedOnto = 0;
  for (int k = 0; k < 1000; ++k) {
    const int start = int(rng() % tets.size());
    const Vec3 p = wellInsidePoint(tets[std::size_t(start)], rng);
    const Vec3 dir =
        Vec3(Real(u(rng)) - Real(0.5), Real(u(rng)) - Real(0.5), Real(u(rng)) - Real(0.5)).normalized();
    Vec3 previous = p - Real(0.06) * dir;  // outside the box (side 0.03 + jitter)
    if (k % 2) {
      // Previous position inside the same tet, which has a boundary face.
      previous = p - Real(0.0002) * dir;
      if (masks[std::size_t(start)] == 0 || containing(previous) != start) continue;
      ++movedOnto;
    } else {
      ++fromOutside;
    }
    Vec3 q = p;
    int passes = 0;
    for (int t = containing(q); t >= 0 && passes < 100; t = containing(q), ++passes)
      q = pushOutOfTet(tets[std::size_t(t)], q, previous, radius, masks[std::size_t(t)]).position;
    if (k % 2) {
      EXPECT_EQ(passes, 1) << k;
    }
    maxPasses = std::max(maxPasses, passes);
    ASSERT_TRUE(q.allFinite());
    EXPECT_FALSE(insideAny(tets, q)) << k;
  }
  EXPECT_GT(fromOutside, 400);
  EXPECT_GT(movedOnto, 100);
  EXPECT_LT(maxPasses, 30);
  std::printf("most pushes for one particle: %d\n", maxPasses);
}

TEST(TetPushOut, TriangleWeightsGiveAPointOfTheTriangle) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<float> u(-1, 1), v(0, 1);
  for (int k = 0; k < 500; ++k) {
    const Vec3 a(Real(u(rng)), Real(u(rng)), Real(u(rng))), b(Real(u(rng)), Real(u(rng)), Real(u(rng))),
        c(Real(u(rng)), Real(u(rng)), Real(u(rng)));
    const Vec3 n = (b - a).cross(c - a);
    if (n.norm() < Real(0.05)) continue;
    // Inside: the weights are recovered, also for a point off the plane along the normal.
    std::array<Real, 3> w{Real(v(rng)), Real(v(rng)), Real(v(rng))};
    const Real sum = w[0] + w[1] + w[2];
    for (Real& x : w) x /= sum;
    const Vec3 q = w[0] * a + w[1] * b + w[2] * c;
    const std::array<Real, 3> got = triangleWeights(q + Real(u(rng)) * n.normalized(), a, b, c);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(got[i], w[i], 1e-4) << k;
    // Anywhere: non-negative and summing to 1.
    const std::array<Real, 3> far =
        triangleWeights(Vec3(Real(3) * u(rng), Real(3) * u(rng), Real(3) * u(rng)), a, b, c);
    EXPECT_NEAR(far[0] + far[1] + far[2], 1, 1e-6);
    for (const Real x : far) EXPECT_GE(x, 0);
  }
  const std::array<Real, 3> flat =
      triangleWeights(Vec3(1, 2, 3), Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2));
  for (const Real x : flat) EXPECT_EQ(x, Real(1) / Real(3));
}

TEST(TetPushOut, FaceWeightsLocateThePointPushedAwayFrom) {
  // Along the ray: the weights give the entry point, radius back from the result along the
  // motion. Fallback: the foot of p on the exit face's plane (inside the face here).
  std::mt19937 rng(22);
  std::uniform_real_distribution<float> u(-1, 1);
  const Real radius = Real(0.02);
  int alongRay = 0;
  for (int k = 0; k < 500; ++k) {
    const TetPoints x = randomTet(rng, Vec3::Zero(), k % 2 == 0);
    const Vec3 p = wellInsidePoint(x, rng);
    const Vec3 dir = Vec3(Real(u(rng)), Real(u(rng)), Real(u(rng))).normalized();
    const TetPushOut out = pushOutOfTet(x, p, p - Real(4) * dir, radius);
    ASSERT_GE(out.face, 0);
    const auto& f = kTetFaceVertices[std::size_t(out.face)];
    Vec3 point = Vec3::Zero();
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_GE(out.faceWeights[i], 0);
      point += out.faceWeights[i] * x[std::size_t(f[i])];
    }
    EXPECT_NEAR(out.faceWeights[0] + out.faceWeights[1] + out.faceWeights[2], 1, 1e-6);
    if (out.alongRay) {
      ++alongRay;
      EXPECT_LT((point - (out.position + radius * dir)).norm(), 1e-5) << k;
    }
  }
  EXPECT_GT(alongRay, 450);
  const TetPoints x = unitTet();
  const TetPushOut fallback =
      pushOutOfTet(x, Vec3(Real(0.1), Real(0.3), Real(0.2)), Vec3(Real(0.1), Real(0.3), Real(0.2)), radius);
  ASSERT_EQ(fallback.face, 1);  // x = 0: foot (0, 0.3, 0.2) = 0.5 x_0 + 0.2 x_3 + 0.3 x_2
  const std::array<Real, 3> expected{Real(0.5), Real(0.2), Real(0.3)};  // vertices 0, 3, 2
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(fallback.faceWeights[i], expected[i], 1e-6);
}

}  // namespace
}  // namespace hs::pbd
