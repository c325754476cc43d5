// ParticleTetCollider (particle_tet_collision.h): particles that end a step inside a
// tetrahedral solid are pushed back out along their motion (thesis 4.4), checked against
// brute force over every tet; untouched particles stay bitwise the same; same result for 1 and
// 2 threads; a solid moving onto resting particles pushes them out too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "box_mesh.h"
#include "pbd/particle_tet_collision.h"
#include "pbd/tet_geometry.h"

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
  std::printf("%zu of %zu entering particles pushed back along their ray by exactly the radius\n", onRay, entered);
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
    ids.push_back(w.particles.add(Vec3(Real(0.85), Real(0.02) + Real(0.1) * Real(k), Real(0.37)), 1, ParticleKind::Fluid));
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

}  // namespace
}  // namespace hs::pbd
