// Continuous point-vs-moving-triangle contact (swept_contact.h): the vertex-face test against
// a brute force of fine time sampling on random paths and moving triangles; its special cases
// (exits, motion within or parallel to the plane, a path starting on the face, a triangle
// sweeping over a resting point, a shared edge); and the surface contact on a thin moving slab
// shot through at 20 thicknesses a step: no particle crosses into it, exits are free, slip
// keeps the tangential motion, and 1 and 2 threads give bitwise the same result.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "box_mesh.h"
#include "pbd/contact/swept_contact.h"
#include "pbd/core/tet_geometry.h"

namespace hs::pbd {
namespace {

using Vec3d = Eigen::Vector3d;
using Tri = std::array<Vec3, 3>;

const Tri kUnit{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};  // normal +z

Tri shiftedBy(const Tri& x, const Vec3& d) { return {x[0] + d, x[1] + d, x[2] + d}; }

// Brute force: f sampled at N + 1 times, each from positions interpolated afresh (no cubic):
// its height over the entry level and the barycentric coordinates of the foot. An entry is a
// sample step with f > 0 then <= 0 whose point, where f crosses linearly, lies on the triangle
// by at least `margin`; `nearEdge` is set by a crossing within `margin` of the triangle's edges.
struct Sampled {
  std::optional<double> t;
  bool nearEdge = false;
};
Sampled sampledEntry(const Vec3& a0, const Vec3& a1, const Tri& x0, const Tri& x1, int samples, double margin) {
  Sampled out;
  // The entry level of swept_contact.h: kPlaneSlack x the longest edge behind the face, in
  // units of f = distance x |n| with the larger of the start and end normals.
  double edge = 0;
  for (const Tri* x : {&x0, &x1})
    for (std::size_t i = 0; i < 3; ++i) edge = std::max(edge, double(((*x)[(i + 1) % 3] - (*x)[i]).norm()));
  const double normal = std::max(double((x0[1] - x0[0]).cross(x0[2] - x0[0]).norm()),
                                 double((x1[1] - x1[0]).cross(x1[2] - x1[0]).norm()));
  const double level = kPlaneSlack * edge * normal;
  // f above the entry level, and the lowest barycentric coordinate of the point's foot, at t.
  auto sample = [&](double t, double& low) {
    auto at = [t](const Vec3& p, const Vec3& q) { return Vec3d(p.cast<double>() + t * (q - p).cast<double>()); };
    const Vec3d p = at(a0, a1), v0 = at(x0[0], x1[0]), v1 = at(x0[1], x1[1]), v2 = at(x0[2], x1[2]);
    const Vec3d n = (v1 - v0).cross(v2 - v0);
    const double nn = n.squaredNorm();
    const double b1 = (p - v0).cross(v2 - v0).dot(n) / nn, b2 = (v1 - v0).cross(p - v0).dot(n) / nn;
    low = std::min({1 - b1 - b2, b1, b2});
    return (p - v0).dot(n) + level;
  };
  double previous = 0, low = 0;
  for (int j = 0; j <= samples; ++j) {
    const double t = double(j) / double(samples);
    const double f = sample(t, low);
    if (j > 0 && previous > 0 && f <= 0) {
      // The foot where f crosses the level, by linear interpolation within the sample step.
      const double crossing = t - (f / (f - previous)) / double(samples);
      sample(crossing, low);
      if (low >= margin) {
        out.t = t;
        return out;
      }
      if (low > -margin) out.nearEdge = true;
    }
    previous = f;
  }
  return out;
}

TEST(SweptEntry, AgreesWithFineTimeSamplingOnRandomMotion) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<Real> u(-1, 1);
  constexpr int kSamples = 4096;
  const double step = 1.0 / kSamples;
  int entries = 0, checked = 0;
  for (int c = 0; c < 3000; ++c) {
    const Real motion = (c % 3 == 0) ? Real(0) : (c % 3 == 1 ? Real(0.3) : Real(1.2));
    Tri x0, x1;
    for (std::size_t i = 0; i < 3; ++i) {
      x0[i] = Vec3(u(rng), u(rng), u(rng));
      x1[i] = x0[i] + motion * Vec3(u(rng), u(rng), u(rng));
    }
    Vec3 a0 = Real(1.5) * Vec3(u(rng), u(rng), u(rng)), a1 = Real(1.5) * Vec3(u(rng), u(rng), u(rng));
    if (c % 4 != 0) {
      // Aimed: through a random point of the triangle at a random time s of the step.
      const Real s = Real(0.5) * (u(rng) + 1), b1 = Real(0.5) * (u(rng) + 1), b2 = (1 - b1) * Real(0.5) * (u(rng) + 1);
      auto at = [&](std::size_t i) -> Vec3 { return x0[i] + s * (x1[i] - x0[i]); };
      const Vec3 q = (1 - b1 - b2) * at(0) + b1 * at(1) + b2 * at(2);
      const Vec3 d = Real(2) * Vec3(u(rng), u(rng), u(rng));
      a0 = q - s * d;
      a1 = q + (1 - s) * d;
    }
    const Sampled reference = sampledEntry(a0, a1, x0, x1, kSamples, 1e-3);
    if (reference.nearEdge) continue;  // the two may differ within the margin of an edge
    ++checked;
    const std::optional<SweptHit> hit = firstEntry(a0, a1, x0, x1);
    if (!reference.t) {
      // No sampled entry: none, or one the samples stepped over (entering and leaving within
      // one sample step, never seen on these cases).
      EXPECT_FALSE(hit) << "case " << c << ": t " << hit->t;
      continue;
    }
    ++entries;
    ASSERT_TRUE(hit) << "case " << c << ": sampled entry at " << *reference.t;
    EXPECT_LE(hit->t, *reference.t + 1e-9) << "case " << c;
    EXPECT_GE(hit->t, *reference.t - step - 1e-9) << "case " << c;
    EXPECT_NEAR(hit->weights[0] + hit->weights[1] + hit->weights[2], 1.0, 1e-12);
  }
  EXPECT_GT(checked, 2500);
  EXPECT_GT(entries, 300) << "the random cases must enter often enough to test the roots";
}

TEST(SweptEntry, StraightThroughAStillTriangle) {
  const std::optional<SweptHit> hit = firstEntry(Vec3(Real(0.2), Real(0.2), 1), Vec3(Real(0.2), Real(0.2), -1), kUnit, kUnit);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 0.5, 1e-5);
  EXPECT_NEAR(hit->weights[0], 0.6, 1e-5);
  EXPECT_NEAR(hit->weights[1], 0.2, 1e-5);
  EXPECT_NEAR(hit->weights[2], 0.2, 1e-5);
  // Beside the triangle: the plane is crossed, the triangle is not.
  EXPECT_FALSE(firstEntry(Vec3(Real(0.8), Real(0.8), 1), Vec3(Real(0.8), Real(0.8), -1), kUnit, kUnit));
}

TEST(SweptEntry, ExitsAreFree) {
  EXPECT_FALSE(firstEntry(Vec3(Real(0.2), Real(0.2), -1), Vec3(Real(0.2), Real(0.2), 1), kUnit, kUnit));
  // The triangle sweeping down past a point that was behind it: the point comes out.
  EXPECT_FALSE(firstEntry(Vec3(Real(0.2), Real(0.2), 0), Vec3(Real(0.2), Real(0.2), 0), shiftedBy(kUnit, Vec3(0, 0, 1)),
                          shiftedBy(kUnit, Vec3(0, 0, -1))));
}

TEST(SweptEntry, ATriangleSweepingOntoARestingPointHitsIt) {
  const Vec3 p(Real(0.25), Real(0.25), 0);
  const std::optional<SweptHit> hit =
      firstEntry(p, p, shiftedBy(kUnit, Vec3(0, 0, -1)), shiftedBy(kUnit, Vec3(0, 0, 3)));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 0.25, 1e-5);
}

TEST(SweptEntry, MotionWithinOrAlongThePlaneNeverEnters) {
  // In the plane (f identically 0), parallel above it, and carried along with the triangle
  // (f constant): degenerate cubics.
  EXPECT_FALSE(firstEntry(Vec3(-1, Real(0.2), 0), Vec3(2, Real(0.2), 0), kUnit, kUnit));
  EXPECT_FALSE(firstEntry(Vec3(-1, Real(0.2), Real(0.1)), Vec3(2, Real(0.2), Real(0.1)), kUnit, kUnit));
  const Vec3 d(Real(0.3), Real(-0.2), Real(0.7));
  EXPECT_FALSE(firstEntry(Vec3(Real(0.2), Real(0.2), Real(0.01)), Vec3(Real(0.2), Real(0.2), Real(0.01)) + d, kUnit,
                          shiftedBy(kUnit, d)));
}

TEST(SweptEntry, APathStartingOnTheFace) {
  // Exactly on it (or a rounding hair behind) and moving in: an entry at once; moving out: none;
  // starting clearly behind the face (inside the solid) and going deeper: none.
  for (Real z0 : {Real(0), Real(-1e-8)}) {
    const std::optional<SweptHit> in = firstEntry(Vec3(Real(0.2), Real(0.2), z0), Vec3(Real(0.2), Real(0.2), -1), kUnit, kUnit);
    ASSERT_TRUE(in) << z0;
    EXPECT_LT(in->t, 1e-5);
    EXPECT_FALSE(firstEntry(Vec3(Real(0.2), Real(0.2), z0), Vec3(Real(0.2), Real(0.2), 1), kUnit, kUnit)) << z0;
  }
  EXPECT_FALSE(firstEntry(Vec3(Real(0.2), Real(0.2), Real(-1e-3)), Vec3(Real(0.2), Real(0.2), -1), kUnit, kUnit));
}

TEST(SweptEntry, ASharedEdgeIsCaughtByOneOfItsTriangles) {
  // The unit square as two triangles sharing the diagonal (1,0)-(0,1), both normal +z.
  const Tri lower = kUnit, upper{Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  std::mt19937 rng(2);
  std::uniform_real_distribution<Real> u(0, 1);
  for (int k = 0; k < 200; ++k) {
    const Real s = u(rng);
    const Vec3 onEdge(s, 1 - s, 0), tilt(Real(0.3) * (u(rng) - Real(0.5)), Real(0.3) * (u(rng) - Real(0.5)), 1);
    const Vec3 a0 = onEdge + tilt, a1 = onEdge - tilt;
    EXPECT_TRUE(firstEntry(a0, a1, lower, lower) || firstEntry(a0, a1, upper, upper)) << s;
  }
}

// ---- The surface: a thin slab (2 mm) moving over the step ------------------------------------

constexpr Real kThickness = Real(0.002), kWidth = Real(0.1), kRadius = Real(0.0018);

struct Slab {
  TetMesh mesh;
  std::vector<Triangle> surface;
};

// 8 x 8 cells across, 2 layers of tets through the thickness (x, z in [0, 0.1], y in [0, 2 mm]).
Slab makeSlab() {
  Slab s;
  s.mesh = testing::makeBoxMesh(8, 1);
  std::vector<Tet> kept;
  for (const Tet& t : s.mesh.tets) {
    bool low = true;
    for (Index v : t) low = low && s.mesh.vertices[v].y() <= 2;
    if (low) kept.push_back(t);
  }
  s.mesh.tets = kept;
  for (Vec3& v : s.mesh.vertices) v = Vec3(v.x() * kWidth / 8, v.y() * kThickness / 2, v.z() * kWidth / 8);
  s.surface = boundaryFaces(s.mesh.tets);
  return s;
}

// The slab's end of step: lifted by 1 mm and turned by 0.01 rad about z.
std::vector<Vec3> movedSlab(const std::vector<Vec3>& x) {
  const Real c = std::cos(Real(0.01)), s = std::sin(Real(0.01));
  std::vector<Vec3> out;
  for (const Vec3& v : x) {
    const Vec3 d = v - Vec3(kWidth / 2, 0, kWidth / 2);
    out.push_back(Vec3(kWidth / 2, Real(0.001), kWidth / 2) + Vec3(c * d.x() - s * d.y(), s * d.x() + c * d.y(), d.z()));
  }
  return out;
}

bool insideAnyTet(const TetMesh& m, const std::vector<Vec3>& x, const Vec3& p) {
  for (const Tet& t : m.tets)
    if (isPointInTet(tetPoints(x, t), p)) return true;
  return false;
}

// The brute-force check of the guarantee: no triangle of the surface is entered on a0 -> a1.
bool entersAny(const std::vector<Triangle>& surface, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
               const Vec3& a0, const Vec3& a1) {
  for (const Triangle& f : surface)
    if (firstEntry(a0, a1, {x0[f[0]], x0[f[1]], x0[f[2]]}, {x1[f[0]], x1[f[1]], x1[f[2]]})) return true;
  return false;
}

// Slab vertices first, then blood above the slab shot down through it: 40 mm a step (20
// thicknesses), up to 45 degrees off the normal.
Particles shotAtSlab(const Slab& slab, std::size_t count, unsigned seed) {
  Particles particles;
  const std::vector<Vec3> end = movedSlab(slab.mesh.vertices);
  for (std::size_t v = 0; v < slab.mesh.vertices.size(); ++v) {
    particles.add(slab.mesh.vertices[v], 0, ParticleKind::Tissue);
    particles.predicted[v] = end[v];
  }
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> across(Real(0.035), Real(0.065)), tilt(Real(-0.7), Real(0.7)),
      above(kRadius, Real(3) * kRadius);
  for (std::size_t k = 0; k < count; ++k) {
    const Vec3 a0(across(rng), kThickness + above(rng), across(rng));
    const Vec3 direction = Vec3(tilt(rng), -1, tilt(rng)).normalized();
    const Index i = particles.add(a0, 1, ParticleKind::Fluid);
    particles.predicted[i] = a0 + Real(0.04) * direction;
  }
  return particles;
}

TEST(SweptContact, NothingTunnelsThroughAThinMovingSlab) {
  const Slab slab = makeSlab();
  for (bool slip : {false, true}) {
    SCOPED_TRACE(slip);
    Particles particles = shotAtSlab(slab, 400, 4);
    const std::vector<Vec3> shot = particles.predicted;
    const auto first = Index(slab.mesh.vertices.size());
    SweptContact contact(slab.surface, particles.position);
    SweptContactSettings settings;
    settings.radius = kRadius;
    settings.slip = slip;
    EXPECT_EQ(contact.resolve(particles, first, Index(particles.size()), settings), particles.size() - first);
    EXPECT_EQ(contact.lastUnresolved(), 0u);
    const std::vector<Vec3> end(particles.predicted.begin(), particles.predicted.begin() + first);
    const Real c = std::cos(Real(0.01)), s = std::sin(Real(0.01));
    const Vec3 up(-s, c, 0);  // the slab's turned normal
    const Vec3 top = end[0] + kThickness * up;  // a point of its top face (vertex 0 is a bottom corner)
    for (std::size_t i = first; i < particles.size(); ++i) {
      const Vec3& x = particles.predicted[i];
      ASSERT_FALSE(entersAny(slab.surface, particles.position, particles.predicted, particles.position[i], x)) << i;
      EXPECT_FALSE(insideAnyTet(slab.mesh, end, x)) << i;
      EXPECT_GT(up.dot(x - top), Real(0.99) * kRadius) << "particle " << i << " is not on the slab's side it came from";
      if (!slip) continue;
      // Free slip keeps the motion along the face: most of the shot's sideways travel.
      const Vec3 shotAlong = (shot[i] - particles.position[i]) - up.dot(shot[i] - particles.position[i]) * up;
      const Vec3 along = (x - particles.position[i]) - up.dot(x - particles.position[i]) * up;
      EXPECT_GT(along.dot(shotAlong), Real(0.5) * shotAlong.squaredNorm()) << i;
    }
  }
}

TEST(SweptContact, FindsTheSameFirstEntryAsAllTriangles) {
  const Slab slab = makeSlab();
  Particles particles = shotAtSlab(slab, 300, 8);
  SweptContact contact(slab.surface, particles.position);
  contact.update(particles.position, particles.predicted, Real(1e-5));
  const auto first = slab.mesh.vertices.size();
  std::size_t hits = 0;
  for (std::size_t i = first; i < particles.size(); ++i) {
    const Vec3 a0 = particles.position[i], a1 = particles.predicted[i];
    std::optional<SurfaceHit> brute;
    for (std::size_t t = 0; t < slab.surface.size(); ++t) {
      const Triangle& f = slab.surface[t];
      const std::optional<SweptHit> hit =
          firstEntry(a0, a1, {particles.position[f[0]], particles.position[f[1]], particles.position[f[2]]},
                     {particles.predicted[f[0]], particles.predicted[f[1]], particles.predicted[f[2]]});
      if (hit && (!brute || hit->t < brute->hit.t)) brute = SurfaceHit{t, *hit};
    }
    const std::optional<SurfaceHit> fast = contact.firstSurfaceEntry(particles.position, particles.predicted, a0, a1);
    ASSERT_EQ(bool(fast), bool(brute)) << i;
    if (!fast) continue;
    ++hits;
    EXPECT_EQ(fast->triangle, brute->triangle);
    EXPECT_EQ(fast->hit.t, brute->hit.t);
  }
  EXPECT_EQ(hits, particles.size() - first) << "every shot meets the slab";
}

TEST(SweptContact, ExitsAndMisses) {
  // Inside the slab moving out of either face, below it moving away, above it moving along
  // it: every prediction stays as it was.
  const Slab slab = makeSlab();
  Particles particles;
  for (const Vec3& v : slab.mesh.vertices) particles.add(v, 0, ParticleKind::Tissue);
  const auto first = Index(particles.size());
  auto shoot = [&](const Vec3& from, const Vec3& to) {
    const Index i = particles.add(from, 1, ParticleKind::Fluid);
    particles.predicted[i] = to;
  };
  const Real mid = kThickness / 2;
  for (int k = 0; k < 10; ++k) {
    const Real x = Real(0.03) + Real(0.004) * Real(k);
    shoot(Vec3(x, mid, Real(0.05)), Vec3(x + Real(0.01), Real(0.04), Real(0.05)));    // up and out
    shoot(Vec3(x, mid, Real(0.04)), Vec3(x, Real(-0.04), Real(0.06)));              // down and out
    shoot(Vec3(x, Real(-0.003), Real(0.05)), Vec3(x, Real(-0.05), Real(0.05)));     // below, away
    shoot(Vec3(x, Real(0.004), Real(0.05)), Vec3(x + Real(0.04), Real(0.004), Real(0.07)));  // along
  }
  const std::vector<Vec3> before = particles.predicted;
  SweptContact contact(slab.surface, particles.position);
  SweptContactSettings settings;
  settings.radius = kRadius;
  EXPECT_EQ(contact.resolve(particles, first, Index(particles.size()), settings), 0u);
  EXPECT_EQ(particles.predicted, before);
}

TEST(SweptContact, SlipKeepsTheTangentialMotionAndNoSlipStopsAtTheContact) {
  const Slab slab = makeSlab();
  Particles particles;
  for (const Vec3& v : slab.mesh.vertices) particles.add(v, 0, ParticleKind::Tissue);
  const auto first = Index(particles.size());
  const Vec3 a0(Real(0.04), kThickness + Real(0.01), Real(0.05)), a1(Real(0.06), kThickness - Real(0.01), Real(0.05));
  particles.add(a0, 1, ParticleKind::Fluid);
  particles.predicted[first] = a1;
  SweptContact contact(slab.surface, particles.position);
  SweptContactSettings settings;
  settings.radius = kRadius;
  Particles stop = particles;
  contact.resolve(stop, first, first + 1, settings);
  EXPECT_NEAR(stop.predicted[first].x(), 0.05, 1e-5) << "the contact point, halfway";
  EXPECT_NEAR(stop.predicted[first].y(), kThickness + kRadius, 1e-6);
  settings.slip = true;
  contact.resolve(particles, first, first + 1, settings);
  EXPECT_NEAR(particles.predicted[first].x(), 0.06, 1e-5) << "all of the motion along the face";
  EXPECT_NEAR(particles.predicted[first].y(), kThickness + kRadius, 1e-6);
  EXPECT_NEAR(particles.predicted[first].z(), 0.05, 1e-6);
}

TEST(SweptContact, BitwiseTheSameForOneAndTwoThreads) {
  const Slab slab = makeSlab();
  const auto first = Index(slab.mesh.vertices.size());
  std::vector<Vec3> results[2];
  for (int threads : {1, 2}) {
    Particles particles = shotAtSlab(slab, 1000, 12);
    SweptContact contact(slab.surface, particles.position);
    SweptContactSettings settings;
    settings.radius = kRadius;
    settings.slip = true;
    settings.threads = threads;
    contact.resolve(particles, first, Index(particles.size()), settings);
    results[threads - 1] = particles.predicted;
  }
  ASSERT_EQ(results[0].size(), results[1].size());
  for (std::size_t i = 0; i < results[0].size(); ++i) {
    ASSERT_EQ(results[0][i].x(), results[1][i].x()) << i;
    ASSERT_EQ(results[0][i].y(), results[1][i].y()) << i;
    ASSERT_EQ(results[0][i].z(), results[1][i].z()) << i;
  }
}

}  // namespace
}  // namespace hs::pbd
