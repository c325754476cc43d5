// Over 400 lines on purpose: one test file per module, its cases sharing the file's set-up helpers.
// ParticleTetCollider (particle_tet_collision.h): particles that end a step inside a
// tetrahedral solid are pushed back out along their motion (thesis 4.4), checked against
// brute force over every tet; untouched particles stay bitwise the same; same result for 1 and
// 2 threads; a solid moving onto resting particles pushes them out too. Two-way coupling: the
// split is the PBD step of the contact constraint, the wall moves back, momentum is conserved
// over random tets and mass ratios, a pinned wall gives the one-way result bitwise, a heavy wall
// still leaves every particle outside, 1 and 2 threads agree, pinned vertices stay.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "box_mesh.h"
#include "pbd/contact/mesh_collider.h"
#include "pbd/contact/particle_tet_collision.h"
#include "pbd/core/tet_geometry.h"

namespace hs::pbd {
namespace {

// A solid cube [0, 1]^3 of 4 x 4 x 4 x 6 tets as particles 0..124, then n free particles.
struct World {
  TetMesh cube = testing::makeBoxMesh(4, Real(0.25));
  Particles particles;
  Index firstFree = 0;
};

World world(std::size_t n, unsigned seed, bool startOutside) {
  World w;
  for (const Vec3& v : w.cube.vertices) w.particles.add(v, 0, ParticleKind::Tissue);
  w.firstFree = Index(w.particles.size());
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.6, 1.6), in(0.02, 0.98);
  for (std::size_t k = 0; k < n; ++k) {
    Vec3 from;
    do {
      from = Vec3(Real(u(rng)), Real(u(rng)), Real(u(rng)));
    } while (startOutside && (from.array() > Real(-0.1)).all() && (from.array() < Real(1.1)).all());
    const Vec3 to(Real(in(rng)), Real(in(rng)), Real(in(rng)));
    const Index i = w.particles.add(from, 1, ParticleKind::Fluid);
    w.particles.predicted[i] = k % 4 == 0 ? from : to;  // a quarter do not move at all
  }
  return w;
}

bool insideAnyTet(const World& w, const std::vector<Vec3>& x, const Vec3& p, Real tolerance) {
  for (const Tet& t : w.cube.tets)
    if (isPointInTet(tetPoints(x, t), p, tolerance)) return true;
  return false;
}

TEST(ParticleTetCollision, ParticlesEnteringASolidEndOutsideEveryTet) {
  World w = world(3000, 7, true);
  const std::vector<Vec3> before = w.particles.predicted;
  ParticleTetCollider collider(w.cube.tets, 0);
  ParticleTetSettings s;
  s.radius = Real(0.02);
  const std::size_t moved = collider.resolve(w.particles, w.firstFree, Index(w.particles.size()), s);
  std::size_t entered = 0, onRay = 0;
  for (Index i = w.firstFree; i < w.particles.size(); ++i) {
    const Vec3& p = w.particles.predicted[i];
    const bool wasInside = insideAnyTet(w, w.particles.predicted, before[i], 0);
    entered += wasInside;
    ASSERT_FALSE(insideAnyTet(w, w.particles.predicted, p, 0)) << "particle " << i;
    if (!wasInside) {
      EXPECT_EQ(std::memcmp(&p, &before[i], sizeof(Vec3)), 0) << "particle " << i << " moved without cause";
    } else {
      // Eq. 4.20: back along the ray to the radius beyond where it entered the cube. The
      // entry E of the segment previous -> predicted into [0, 1]^3 by the slab method.
      const Vec3& from = w.particles.position[i];
      const Vec3 dir = before[i] - from;
      double tEnter = 0;
      for (int a = 0; a < 3; ++a) {
        if (dir[a] == 0) continue;
        const double t0 = (0.0 - from[a]) / dir[a], t1 = (1.0 - from[a]) / dir[a];
        tEnter = std::max(tEnter, std::min(t0, t1));
      }
      const Vec3 entry = from + Real(tEnter) * dir;
      // Most take exactly that path; the rest (rays grazing an edge or a vertex of an inner
      // tet, where the Plücker signs are rounding noise) leave through the nearest face
      // instead: still outside, checked above.
      onRay += std::abs((p - entry).norm() - s.radius) < Real(1e-4) &&
               (p - entry).cross(dir.normalized()).norm() < Real(1e-4);
    }
  }
  EXPECT_EQ(moved, entered);
  EXPECT_GT(entered, 1500u);
  EXPECT_GE(double(onRay), 0.98 * double(entered));
  std::printf("%zu of %zu entering particles pushed back along their ray by exactly the radius\n", onRay,
              entered);
  EXPECT_EQ(collider.countInside(w.particles.predicted, w.firstFree, Index(w.particles.size()), 0), 0u);
}

TEST(ParticleTetCollision, SameResultForOneAndTwoThreads) {
  World a = world(5000, 3, true), b = world(5000, 3, true);
  ParticleTetCollider ca(a.cube.tets, 0), cb(b.cube.tets, 0);
  ParticleTetSettings s;
  s.threads = 1;
  ca.resolve(a.particles, a.firstFree, Index(a.particles.size()), s);
  s.threads = 2;
  cb.resolve(b.particles, b.firstFree, Index(b.particles.size()), s);
  EXPECT_EQ(std::memcmp(a.particles.predicted.data(), b.particles.predicted.data(),
                        a.particles.size() * sizeof(Vec3)),
            0);
}

TEST(ParticleTetCollision, ASolidMovingOntoRestingParticlesPushesThemOut) {
  // Particles resting inside the cube's region (position = predicted: no ray); the cube has
  // just arrived there. They leave through the nearest boundary face.
  World w = world(0, 1, false);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> in(0.05, 0.95);
  for (int k = 0; k < 500; ++k) {
    const Vec3 x(Real(in(rng)), Real(in(rng)), Real(in(rng)));
    w.particles.add(x, 1, ParticleKind::Fluid);
  }
  ParticleTetCollider collider(w.cube.tets, 0);
  ParticleTetSettings s;
  s.radius = Real(0.01);
  s.maxPasses = 16;
  collider.resolve(w.particles, w.firstFree, Index(w.particles.size()), s);
  std::size_t stillInside = 0;
  for (Index i = w.firstFree; i < w.particles.size(); ++i)
    stillInside += insideAnyTet(w, w.particles.predicted, w.particles.predicted[i], 0);
  // Tets deep inside the cube have no boundary face and no ray: they cannot know the way out
  // in one pass (tet_geometry.h); passes walk the particle outwards face by face.
  EXPECT_EQ(stillInside, 0u);
}

TEST(ParticleTetCollision, AWallSweepingOverRestingParticlesPushesThemAheadOfIt) {
  // The cube moves 0.3 along +x in one step onto particles resting at x = 0.85, close to its
  // -y face. The face that swept over them is +x: they end at x = 1 + r, not below the
  // nearest face (y = -r).
  World w = world(0, 1, false);
  for (Index v = 0; v < w.firstFree; ++v) w.particles.position[v] -= Vec3(Real(0.3), 0, 0);
  std::vector<Index> ids;
  for (int k = 0; k < 9; ++k)
    ids.push_back(w.particles.add(Vec3(Real(0.85), Real(0.02) + Real(0.1) * Real(k), Real(0.37)), 1,
                                  ParticleKind::Fluid));
  ParticleTetCollider collider(w.cube.tets, 0);
  ParticleTetSettings s;
  s.radius = Real(0.02);
  collider.resolve(w.particles, w.firstFree, Index(w.particles.size()), s);
  for (const Index i : ids) {
    const Vec3& p = w.particles.predicted[i];
    EXPECT_NEAR(double(p.x()), 1.02, 1e-4) << "particle " << i;
    EXPECT_NEAR(double(p.y()), double(w.particles.position[i].y()), 1e-4) << "particle " << i;
    EXPECT_FALSE(insideAnyTet(w, w.particles.predicted, p, 0));
  }
}

TEST(ParticleTetCollision, CountInsideMatchesBruteForceDepth) {
  World w = world(2000, 9, false);
  ParticleTetCollider collider(w.cube.tets, 0);
  const Real minDepth = Real(0.01);
  std::size_t expected = 0;
  for (Index i = w.firstFree; i < w.particles.size(); ++i) {
    bool deep = false;
    for (const Tet& t : w.cube.tets) {
      const TetPointQuery q = queryPointInTet(tetPoints(w.particles.predicted, t), w.particles.predicted[i]);
      deep = deep || (q.inside && q.depth > minDepth);
    }
    expected += deep;
  }
  EXPECT_GT(expected, 100u);
  EXPECT_EQ(collider.countInside(w.particles.predicted, w.firstFree, Index(w.particles.size()), minDepth, 2),
            expected);
}

// ---- Two-way coupling (ParticleTetSettings::twoWay) -----------------------------------------

// One tet as particles 0..3 with the given inverse masses, then one particle (index 4) moving
// from `from` to `to`.
Particles singleTet(const TetPoints& x, const std::array<Real, 4>& wallW, const Vec3& from, const Vec3& to,
                    Real particleW) {
  Particles p;
  for (std::size_t k = 0; k < 4; ++k) p.add(x[k], wallW[k], ParticleKind::Tissue);
  p.add(from, particleW, ParticleKind::Fluid);
  p.predicted[4] = to;
  return p;
}

const std::vector<Tet> kOneTet{Tet{0, 1, 2, 3}};
const TetPoints kUnitTet{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};

ParticleTetSettings twoWay(Real radius) {
  ParticleTetSettings s;
  s.radius = radius;
  s.twoWay = true;
  return s;
}

bool sameBits(const Vec3& a, const Vec3& b) { return std::memcmp(&a, &b, sizeof(Vec3)) == 0; }

// A tet of 4 random points in [-1, 1]^3 with 6|V| >= 0.05 L^3 (either orientation).
TetPoints randomTet(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  for (;;) {
    TetPoints x;
    for (Vec3& v : x) v = Vec3(Real(u(rng)), Real(u(rng)), Real(u(rng)));
    const Eigen::Vector3d a = (x[1] - x[0]).cast<double>(), b = (x[2] - x[0]).cast<double>(),
                          c = (x[3] - x[0]).cast<double>();
    double l2 = 0;
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = i + 1; j < 4; ++j) l2 = std::max(l2, double((x[i] - x[j]).squaredNorm()));
    if (std::abs(a.cross(b).dot(c)) >= 0.05 * l2 * std::sqrt(l2)) return x;
  }
}

TEST(ParticleTetTwoWay, SplitIsThePbdStepOfTheContactConstraint) {
  // C(x_p, x_0, x_1, x_2) = n . (x_p - sum_i b_i x_i): its gradient by central differences, then
  // the PBD step dx_j = -w_j (C - C_target) grad_j C / sum_k w_k |grad_k C|^2 for the target
  // C + |d| (Müller et al. 2007, eq. 9-10), against splitPushOut.
  const Vec3 d(Real(0.3), Real(-0.1), Real(0.2));
  const std::array<Real, 3> b{Real(0.2), Real(0.5), Real(0.3)}, wWall{Real(0.5), Real(2), Real(0)};
  const Real wP = Real(1.5);
  const Eigen::Vector3d n = d.cast<double>().normalized();
  std::array<Eigen::Vector3d, 4> x{Eigen::Vector3d(0.1, 0.2, 0.3), Eigen::Vector3d(1, 0, 0),
                                   Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1)};
  auto constraint = [&](const std::array<Eigen::Vector3d, 4>& y) {
    return n.dot(y[0] - double(b[0]) * y[1] - double(b[1]) * y[2] - double(b[2]) * y[3]);
  };
  std::array<Eigen::Vector3d, 4> grad;
  const double h = 1e-6;
  for (std::size_t j = 0; j < 4; ++j)
    for (int a = 0; a < 3; ++a) {
      auto plus = x, minus = x;
      plus[j][a] += h;
      minus[j][a] -= h;
      grad[j][a] = (constraint(plus) - constraint(minus)) / (2 * h);
    }
  const std::array<double, 4> w{wP, wWall[0], wWall[1], wWall[2]};
  double denominator = 0;
  for (std::size_t j = 0; j < 4; ++j) denominator += w[j] * grad[j].squaredNorm();
  const double s = d.cast<double>().norm() / denominator;
  const TwoWayPushOut split = splitPushOut(d, wP, b, wWall);
  ASSERT_TRUE(split.shared);
  EXPECT_LT((split.particle.cast<double>() - s * w[0] * grad[0]).norm(), 1e-6);
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_LT((split.wall[k].cast<double>() - s * w[k + 1] * grad[k + 1]).norm(), 1e-6) << k;
  // The whole face pinned: nothing shared, the particle keeps d exactly.
  const TwoWayPushOut pinned = splitPushOut(d, wP, b, {0, 0, 0});
  EXPECT_FALSE(pinned.shared);
  EXPECT_TRUE(sameBits(pinned.particle, d));
}

TEST(ParticleTetTwoWay, APushOutMovesAFreeTetBack) {
  // The particle enters the unit tet through face 3 (z = 0) at E = (0.2, 0.25, 0), the point
  // with weights (0.55, 0.25, 0.2) of vertices (0, 2, 1).
  const Real r = Real(0.02);
  Particles p = singleTet(kUnitTet, {1, 1, 1, 1}, Vec3(Real(0.2), Real(0.25), Real(-0.5)),
                          Vec3(Real(0.2), Real(0.25), Real(0.1)), 1);
  const std::vector<Vec3> before = p.predicted;
  ParticleTetCollider collider(kOneTet, 0);
  EXPECT_EQ(collider.resolve(p, 4, 5, twoWay(r)), 1u);
  const Vec3 dp = p.predicted[4] - before[4];
  EXPECT_LT(dp.z(), 0);
  for (Index v = 0; v < 3; ++v) {
    const Vec3 dv = p.predicted[v] - before[v];
    EXPECT_LT(dv.dot(dp), 0) << "vertex " << v << " must move against the particle";
    EXPECT_LT(dv.head<2>().norm(), 1e-6);
  }
  EXPECT_TRUE(sameBits(p.predicted[3], before[3])) << "vertex 3 is not on the face pushed";
  // s = |d| / (w_p + sum b^2 w) with |d| = 0.1 + r; dx_p = -s z, dx_i = b_i s z.
  const double bsq = 0.55 * 0.55 + 0.25 * 0.25 + 0.2 * 0.2, s = (0.1 + double(r)) / (1 + bsq);
  EXPECT_NEAR(double(dp.z()), -s, 1e-6);
  EXPECT_NEAR(double(p.predicted[0].z()), 0.55 * s, 1e-6);
  EXPECT_NEAR(double(p.predicted[2].z()), 0.25 * s, 1e-6);
  EXPECT_NEAR(double(p.predicted[1].z()), 0.2 * s, 1e-6);
  // The particle ends the radius beyond the moved contact point, as in one-way.
  const Real contactZ =
      Real(0.55) * p.predicted[0].z() + Real(0.25) * p.predicted[2].z() + Real(0.2) * p.predicted[1].z();
  EXPECT_NEAR(double(p.predicted[4].z() - contactZ), -double(r), 1e-6);
}

TEST(ParticleTetTwoWay, ConservesLinearMomentumOnRandomTets) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(0, 1), dirs(-1, 1);
  int checked = 0;
  double worst = 0;
  for (int c = 0; c < 600; ++c) {
    const TetPoints x = randomTet(rng);
    // Half the cases a heavy wall and a light particle, half the reverse; masses differ per vertex.
    const bool heavyWall = c % 2 == 0;
    auto inverseMass = [&](bool heavy) { return Real(heavy ? 0.01 + 0.09 * u(rng) : 1 + 9 * u(rng)); };
    const std::array<Real, 4> wallW{inverseMass(heavyWall), inverseMass(heavyWall), inverseMass(heavyWall),
                                    inverseMass(heavyWall)};
    const Real particleW = inverseMass(!heavyWall);
    std::array<Real, 4> bary;
    Real sum = 0;
    for (Real& v : bary) sum += (v = Real(0.05 + u(rng)));
    Vec3 to = Vec3::Zero();
    for (std::size_t k = 0; k < 4; ++k) to += (bary[k] / sum) * x[k];
    // A quarter rest where the tet arrived (no ray: out through the nearest face).
    const Vec3 dir = Vec3(Real(dirs(rng)), Real(dirs(rng)), Real(dirs(rng))).normalized();
    const Vec3 from = c % 4 == 3 ? to : Vec3(to - Real(4) * dir);
    Particles p = singleTet(x, wallW, from, to, particleW);
    const std::vector<Vec3> before = p.predicted;
    ParticleTetCollider collider(kOneTet, 0);
    if (collider.resolve(p, 4, 5, twoWay(Real(0.02))) != 1) continue;
    ++checked;
    // sum_j m_j dx_j in double from the float positions; the bound allows a few float roundings
    // of every position (|x| <= 5) times its mass.
    Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
    double scale = 0, roundoff = 0;
    for (std::size_t j = 0; j < 5; ++j) {
      const double m = 1 / double(p.inverseMass[j]);
      const Eigen::Vector3d dx = (p.predicted[j].cast<double>() - before[j].cast<double>());
      momentum += m * dx;
      scale += m * dx.norm();
      roundoff += m * 5 * 8 * double(std::numeric_limits<Real>::epsilon());
    }
    ASSERT_GT(scale, 0);
    ASSERT_LT(momentum.norm(), roundoff + 1e-5 * scale) << "case " << c << ", heavy wall " << heavyWall;
    worst = std::max(worst, momentum.norm() / scale);
  }
  EXPECT_GT(checked, 550);
  std::printf("%d random cases, largest |sum m dx| / sum m |dx| = %.2e\n", checked, worst);
}

TEST(ParticleTetTwoWay, InfinitelyHeavyWallGivesTheOneWayResultBitwise) {
  // The cube of World is pinned (inverse mass 0).
  World a = world(3000, 7, true), b = world(3000, 7, true);
  ParticleTetCollider ca(a.cube.tets, 0), cb(b.cube.tets, 0);
  ParticleTetSettings s;
  s.radius = Real(0.02);
  const std::size_t movedA = ca.resolve(a.particles, a.firstFree, Index(a.particles.size()), s);
  s.twoWay = true;
  const std::size_t movedB = cb.resolve(b.particles, b.firstFree, Index(b.particles.size()), s);
  EXPECT_EQ(movedA, movedB);
  EXPECT_GT(movedA, 1500u);
  EXPECT_EQ(std::memcmp(a.particles.predicted.data(), b.particles.predicted.data(),
                        a.particles.size() * sizeof(Vec3)),
            0);
  // And for random single tets.
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0.1, 0.3);
  for (int c = 0; c < 200; ++c) {
    const TetPoints x = randomTet(rng);
    const Vec3 to =
        Real(0.25) * (x[0] + x[1] + x[2] + x[3]) + Vec3(Real(u(rng)), Real(u(rng)), 0) * Real(0.1);
    const Vec3 from = to + Vec3(Real(3), Real(u(rng)), Real(-1));
    Particles one = singleTet(x, {0, 0, 0, 0}, from, to, 1), two = one;
    ParticleTetCollider collider(kOneTet, 0);
    ParticleTetSettings oneWay = twoWay(Real(0.02));
    oneWay.twoWay = false;
    collider.resolve(one, 4, 5, oneWay);
    collider.resolve(two, 4, 5, twoWay(Real(0.02)));
    for (std::size_t j = 0; j < 5; ++j)
      ASSERT_TRUE(sameBits(one.predicted[j], two.predicted[j])) << c << " " << j;
  }
}

TEST(ParticleTetTwoWay, AHeavyWallStillLeavesEveryParticleOutside) {
  World w = world(3000, 7, true);
  for (Index v = 0; v < w.firstFree; ++v) w.particles.inverseMass[v] = Real(1e-4);
  const std::vector<Vec3> before = w.particles.predicted;
  ParticleTetCollider collider(w.cube.tets, 0);
  const ParticleTetSettings s = twoWay(Real(0.02));
  EXPECT_GT(collider.resolve(w.particles, w.firstFree, Index(w.particles.size()), s), 1500u);
  Real wallMotion = 0;
  for (Index v = 0; v < w.firstFree; ++v)
    wallMotion = std::max(wallMotion, (w.particles.predicted[v] - before[v]).norm());
  EXPECT_GT(wallMotion, 0);
  EXPECT_LT(wallMotion, s.radius);
  std::printf("wall vertices moved by up to %.2e\n", double(wallMotion));
  for (Index i = w.firstFree; i < w.particles.size(); ++i)
    ASSERT_FALSE(insideAnyTet(w, w.particles.predicted, w.particles.predicted[i], 0)) << "particle " << i;
  EXPECT_EQ(collider.countInside(w.particles.predicted, w.firstFree, Index(w.particles.size()), 0), 0u);
}

TEST(ParticleTetTwoWay, SameResultForOneAndTwoThreads) {
  World a = world(5000, 3, true), b = world(5000, 3, true);
  for (World* w : {&a, &b})
    for (Index v = 0; v < w->firstFree; ++v) w->particles.inverseMass[v] = Real(0.05);
  const std::vector<Vec3> before = a.particles.predicted;
  ParticleTetCollider ca(a.cube.tets, 0), cb(b.cube.tets, 0);
  ParticleTetSettings s = twoWay(Real(0.02));
  s.threads = 1;
  ca.resolve(a.particles, a.firstFree, Index(a.particles.size()), s);
  s.threads = 2;
  cb.resolve(b.particles, b.firstFree, Index(b.particles.size()), s);
  EXPECT_EQ(std::memcmp(a.particles.predicted.data(), b.particles.predicted.data(),
                        a.particles.size() * sizeof(Vec3)),
            0);
  std::size_t wallMoved = 0;
  for (Index v = 0; v < a.firstFree; ++v) wallMoved += !sameBits(a.particles.predicted[v], before[v]);
  EXPECT_GT(wallMoved, 50u);
}

TEST(ParticleTetTwoWay, APinnedVertexDoesNotMove) {
  // As APushOutMovesAFreeTetBack with vertex 0 pinned: it keeps its bits, vertices 1 and 2
  // move, and the pair's momentum misses exactly vertex 0's share b_0 m_p dx_p (absorbed like
  // a fixed wall's).
  Particles p = singleTet(kUnitTet, {0, 1, 1, 1}, Vec3(Real(0.2), Real(0.25), Real(-0.5)),
                          Vec3(Real(0.2), Real(0.25), Real(0.1)), 1);
  const std::vector<Vec3> before = p.predicted;
  ParticleTetCollider collider(kOneTet, 0);
  EXPECT_EQ(collider.resolve(p, 4, 5, twoWay(Real(0.02))), 1u);
  EXPECT_TRUE(sameBits(p.predicted[0], before[0]));
  EXPECT_TRUE(sameBits(p.predicted[3], before[3]));
  EXPECT_GT(p.predicted[1].z(), 0);
  EXPECT_GT(p.predicted[2].z(), 0);
  Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
  for (std::size_t j = 1; j < 5; ++j)
    momentum += (p.predicted[j].cast<double>() - before[j].cast<double>()) / double(p.inverseMass[j]);
  const Eigen::Vector3d particle = (p.predicted[4].cast<double>() - before[4].cast<double>());
  EXPECT_LT((momentum - 0.55 * particle).norm(), 1e-6);
}

// A vertex left out of the yielding set acts as pinned, whatever its mass: the same bits as
// pinning it by inverse mass 0 (APinnedVertexDoesNotMove), and with none yielding the one-way
// result bitwise.
TEST(ParticleTetTwoWay, AVertexThatDoesNotYieldActsAsPinned) {
  const Vec3 from(Real(0.2), Real(0.25), Real(-0.5)), to(Real(0.2), Real(0.25), Real(0.1));
  Particles masked = singleTet(kUnitTet, {1, 1, 1, 1}, from, to, 1);
  Particles pinned = singleTet(kUnitTet, {0, 1, 1, 1}, from, to, 1);
  ParticleTetCollider maskedCollider(kOneTet, 0), pinnedCollider(kOneTet, 0);
  maskedCollider.setYieldingVertices({0, 1, 1, 1});
  EXPECT_EQ(maskedCollider.resolve(masked, 4, 5, twoWay(Real(0.02))), 1u);
  EXPECT_EQ(pinnedCollider.resolve(pinned, 4, 5, twoWay(Real(0.02))), 1u);
  for (std::size_t j = 0; j < 5; ++j) EXPECT_TRUE(sameBits(masked.predicted[j], pinned.predicted[j])) << j;

  Particles none = singleTet(kUnitTet, {1, 1, 1, 1}, from, to, 1), oneWay = none;
  ParticleTetCollider noneCollider(kOneTet, 0), oneWayCollider(kOneTet, 0);
  noneCollider.setYieldingVertices({0, 0, 0, 0});
  noneCollider.resolve(none, 4, 5, twoWay(Real(0.02)));
  ParticleTetSettings s = twoWay(Real(0.02));
  s.twoWay = false;
  oneWayCollider.resolve(oneWay, 4, 5, s);
  for (std::size_t j = 0; j < 5; ++j) EXPECT_TRUE(sameBits(none.predicted[j], oneWay.predicted[j])) << j;
  EXPECT_FALSE(sameBits(none.predicted[4], to));  // the particle was pushed out
}

}  // namespace
}  // namespace hs::pbd

namespace hs::pbd {
namespace {

// Tunnelling: a wall thinner than a particle's step (a 4 x 4 x 1 slab of 0.05 m cubes, 0.05 m
// thick) stops fast particles that cross it within one step, though they end outside every
// tet: each ends on the side it came from, outside the slab. Without the path samples all 500
// ended beyond it.
TEST(ParticleTetCollision, FastParticlesDoNotTunnelThroughAThinWall) {
  TetMesh slab = testing::makeBoxMesh(4, Real(0.05));
  // Keep the bottom layer of cubes only: z in [0, 0.05].
  std::vector<Tet> thin;
  for (const Tet& t : slab.tets) {
    bool low = true;
    for (Index v : t) low = low && slab.vertices[v].z() <= Real(0.05) + Real(1e-6);
    if (low) thin.push_back(t);
  }
  ASSERT_EQ(thin.size(), 4u * 4u * 6u);
  Particles particles;
  for (const Vec3& v : slab.vertices) particles.add(v, 0, ParticleKind::Tissue);
  const Index first = Index(particles.size());
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> across(0.03, 0.17), below(-0.2, -0.03), above(0.08, 0.25);
  for (int k = 0; k < 500; ++k) {
    const Index i = particles.add(Vec3(Real(across(rng)), Real(across(rng)), Real(below(rng))), 1, ParticleKind::Fluid);
    particles.predicted[i] = Vec3(Real(across(rng)), Real(across(rng)), Real(above(rng)));  // through the slab
  }
  ParticleTetCollider collider(thin, 0);
  ParticleTetSettings s;
  s.radius = Real(0.02);
  collider.resolve(particles, first, Index(particles.size()), s);
  for (std::size_t i = first; i < particles.size(); ++i) {
    const Vec3& p = particles.predicted[i];
    // Eq. 4.20 moves it back along its ray: radius |cos| from the face, on its own side.
    EXPECT_LT(p.z(), Real(0)) << "particle " << i << " crossed the slab: z = " << p.z();
    for (const Tet& t : thin) ASSERT_FALSE(isPointInTet(tetPoints(particles.predicted, t), p, Real(0))) << i;
  }
}

// Free slip (ParticleTetSettings::slip): a particle entering the cube's top face z = 1 at a
// slant leaves along that face's normal to radius above it and keeps its motion along the
// face; eq. 4.20 (the default) sends it back along its ray instead, undoing that motion too.
TEST(ParticleTetCollision, SlipLeavesThroughTheEntryFaceKeepingTheMotionAlongIt) {
  World w = world(0, 1, true);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> across(0.2, 0.8), slide(-0.15, 0.15), above(1.01, 1.1), depth(0.01, 0.1);
  for (int k = 0; k < 400; ++k) {
    const Vec3 from(Real(across(rng)), Real(across(rng)), Real(above(rng)));
    const Index i = w.particles.add(from, 1, ParticleKind::Fluid);
    w.particles.predicted[i] = from + Vec3(Real(slide(rng)), Real(slide(rng)), Real(1) - from.z() - Real(depth(rng)));
  }
  const std::vector<Vec3> penetrated = w.particles.predicted;
  Particles ray = w.particles;
  ParticleTetCollider collider(w.cube.tets, 0);
  ParticleTetSettings s;
  s.radius = Real(0.02);
  s.slip = true;
  ASSERT_EQ(collider.resolve(w.particles, w.firstFree, Index(w.particles.size()), s), 400u);
  s.slip = false;
  ASSERT_EQ(collider.resolve(ray, w.firstFree, Index(ray.size()), s), 400u);
  double raySlide = 0;
  for (Index i = w.firstFree; i < w.particles.size(); ++i) {
    const Vec3& p = w.particles.predicted[i];
    EXPECT_NEAR(p.z(), 1 + s.radius, 1e-5) << i;
    EXPECT_NEAR(p.x(), penetrated[i].x(), 1e-5) << i;
    EXPECT_NEAR(p.y(), penetrated[i].y(), 1e-5) << i;
    ASSERT_FALSE(insideAnyTet(w, w.particles.predicted, p, 0)) << i;
    // Along the ray: back toward where it started, so its sideways motion mostly undone.
    const Vec3 along = penetrated[i] - w.particles.position[i];
    const Vec3 back = ray.predicted[i] - w.particles.position[i];
    raySlide += double(std::hypot(back.x(), back.y()) / std::max(std::hypot(along.x(), along.y()), Real(1e-6)));
  }
  EXPECT_LT(raySlide / 400, 0.5);  // eq. 4.20 keeps under half the sideways motion on average
}

// Two cubes a gap narrower than a particle apart (a ridge between two lumens, in the LV): a
// particle the solid moved onto (its start is inside too) near the face toward the gap cannot
// leave through it, as a radius beyond that face lies in the other cube, and the nearest
// exit from there leads back. It leaves through the next nearest face (the top) instead, and
// ends outside every tet.
TEST(ParticleTetCollision, ParticleCaughtAtANarrowGapTakesTheNearestFreeExit) {
  const TetMesh cube = testing::makeBoxMesh(2, Real(0.5));
  Particles particles;
  std::vector<Tet> tets = cube.tets;
  for (const Vec3& v : cube.vertices) particles.add(v, 0, ParticleKind::Tissue);
  const Index shift = Index(cube.vertices.size());
  const Real gap = Real(0.01);
  for (const Vec3& v : cube.vertices) particles.add(v + Vec3(1 + gap, 0, 0), 0, ParticleKind::Tissue);
  for (Tet t : cube.tets) {
    for (Index& v : t) v += shift;
    tets.push_back(t);
  }
  const Index i = particles.add(Vec3(Real(0.985), Real(0.95), Real(0.6)), 1, ParticleKind::Fluid);
  particles.predicted[i] = Vec3(Real(0.99), Real(0.95), Real(0.6));
  ParticleTetCollider collider(tets, 0);
  ParticleTetSettings s;
  s.radius = Real(0.02);
  for (const bool slip : {false, true}) {
    SCOPED_TRACE(slip ? "slip" : "ray");
    Particles p = particles;
    s.slip = slip;
    ASSERT_EQ(collider.resolve(p, i, i + 1, s), 1u);
    const Vec3& x = p.predicted[i];
    for (const Tet& t : tets) ASSERT_FALSE(isPointInTet(tetPoints(p.predicted, t), x, Real(0))) << x.transpose();
    EXPECT_NEAR(x.y(), 1 + s.radius, 1e-5) << x.transpose();  // out through the top
    EXPECT_NEAR(x.x(), Real(0.99), 1e-5) << x.transpose();
  }
}

}  // namespace
}  // namespace hs::pbd

namespace hs::pbd {
namespace {

// The last resort's nearest boundary exit skips faces by their boxes; it must pick the face a
// search of every boundary face picks (the first of the nearest), for points inside, on the
// surface and outside a deformed cube.
TEST(ParticleTetCollision, NearestBoundaryExitMatchesBruteForce) {
  World w = world(0, 1, false);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05), u(-0.3, 1.3);
  for (Vec3& v : w.particles.position) v += Vec3(Real(jitter(rng)), Real(jitter(rng)), Real(jitter(rng)));
  ParticleTetCollider collider(w.cube.tets, 0);
  const std::vector<Triangle> faces = boundaryFaces(collider.tets());
  const std::vector<Vec3>& x = w.particles.position;
  const Real radius = Real(0.01);
  for (int q = 0; q < 3000; ++q) {
    Vec3 p(Real(u(rng)), Real(u(rng)), Real(u(rng)));
    if (q % 10 == 0) p = x[std::size_t(q) % x.size()];  // on a vertex: many faces equally near
    Real best = std::numeric_limits<Real>::infinity();
    Vec3 expected = p;
    for (const Triangle& f : faces) {
      const Vec3 c = closestPointOnTriangle(p, x[f[0]], x[f[1]], x[f[2]]);
      const Vec3 n = (x[f[1]] - x[f[0]]).cross(x[f[2]] - x[f[0]]);
      if (!(n.norm() > 0) || !((c - p).squaredNorm() < best)) continue;
      best = (c - p).squaredNorm();
      expected = c + (radius / n.norm()) * n;
    }
    const Vec3 got = collider.nearestBoundaryExitAt(x, p, radius);
    EXPECT_TRUE(got.x() == expected.x() && got.y() == expected.y() && got.z() == expected.z())
        << "query " << q << ": got " << got.transpose() << ", brute force " << expected.transpose();
  }
}

}  // namespace
}  // namespace hs::pbd
