// Solver behaviour: colouring correctness, free fall, shape recovery, thread determinism.
#include <gtest/gtest.h>

#include <set>

#include "box_mesh.h"
#include "pbd/soft_body.h"
#include "pbd/solver.h"

namespace hs::pbd {
namespace {

struct World {
  Particles particles;
  ConstraintSet constraints;
};

World makeBoxWorld(int n, int pinnedLayer = -1) {
  World w;
  const TetMesh mesh = testing::makeBoxMesh(n, Real(0.1));
  SoftBodySettings settings;
  addSoftBody(w.particles, w.constraints, mesh, boundaryFaces(mesh.tets), settings);
  if (pinnedLayer >= 0) {
    for (std::size_t i = 0; i < w.particles.size(); ++i)
      if (std::abs(w.particles.position[i].y() - Real(pinnedLayer) * Real(0.1)) < Real(1e-6))
        w.particles.inverseMass[i] = 0;
  }
  finalizeConstraints(w.constraints, w.particles.size());
  return w;
}

template <class Group>
void expectColoursAreIndependent(const Group& group) {
  for (std::size_t colour = 0; colour < group.colourCount(); ++colour) {
    std::set<Index> seen;
    for (std::size_t c = group.colourStart[colour]; c < group.colourStart[colour + 1]; ++c)
      for (Index p : group.constraints[c].particles)
        EXPECT_TRUE(seen.insert(p).second) << "colour " << colour << " shares particle " << p;
  }
}

TEST(Solver, ColouringGivesIndependentSetsAndKeepsEveryConstraint) {
  const World w = makeBoxWorld(4);
  const TetMesh mesh = testing::makeBoxMesh(4, Real(0.1));
  EXPECT_EQ(w.constraints.volumes.size(), mesh.tets.size());
  EXPECT_EQ(w.constraints.volumes.colourStart.back(), mesh.tets.size());
  expectColoursAreIndependent(w.constraints.volumes);
  expectColoursAreIndependent(w.constraints.areas);
  expectColoursAreIndependent(w.constraints.distances);
  EXPECT_GT(w.constraints.volumes.colourCount(), 1u);
}

TEST(Solver, UnconstrainedParticleFallsLikeSymplecticEuler) {
  Particles p;
  p.add(Vec3::Zero(), 1, ParticleKind::Fluid);
  ConstraintSet none;
  SolverSettings s;
  s.dt = Real(0.01);
  for (int i = 0; i < 100; ++i) step(none, p, s);
  // Symplectic Euler: v_n = n g dt, x_n = g dt^2 n (n + 1) / 2.
  EXPECT_NEAR(p.velocity[0].y(), Real(-9.81), 1e-4);
  EXPECT_NEAR(p.position[0].y(), Real(-9.81 * 0.0001 * 100 * 101 / 2), 1e-3);
}

TEST(Solver, PlaneStopsAFallingParticle) {
  Particles p;
  p.add(Vec3(0, 1, 0), 1, ParticleKind::Fluid);
  ConstraintSet c;
  c.planes.push_back({Vec3::UnitY(), 0});
  c.collisionRadius = Real(0.05);
  SolverSettings s;
  for (int i = 0; i < 400; ++i) step(c, p, s);
  EXPECT_NEAR(p.position[0].y(), Real(0.05), 1e-5);
}

TEST(Solver, SquashedSoftBodyRecoversItsRestShape) {
  World w = makeBoxWorld(3, 0);
  const std::vector<Vec3> rest = w.particles.position;
  for (auto& x : w.particles.position) x.y() *= Real(0.7);  // squash toward the pinned floor
  SolverSettings s;
  s.gravity.setZero();
  s.damping = 5;
  for (int i = 0; i < 400; ++i) step(w.constraints, w.particles, s);
  Real worst = 0;
  for (std::size_t i = 0; i < rest.size(); ++i) worst = std::max(worst, (w.particles.position[i] - rest[i]).norm());
  EXPECT_LT(worst, Real(1e-3));
}

TEST(Solver, SameStateForOneAndTwoThreads) {
  auto run = [](int threads) {
    World w = makeBoxWorld(8, 0);  // large enough to take the parallel path
    SolverSettings s;
    s.threads = threads;
    for (auto& x : w.particles.position) x += Vec3(Real(0.03) * x.y(), 0, 0);  // shear
    for (int i = 0; i < 50; ++i) step(w.constraints, w.particles, s);
    return stateHash(w.particles);
  };
  const std::uint64_t one = run(1);
  EXPECT_EQ(one, run(2));
  EXPECT_EQ(one, run(1));
}

TEST(Solver, StateHashSeesEveryBit) {
  Particles p;
  p.add(Vec3(1, 2, 3), 1, ParticleKind::Tissue);
  const std::uint64_t before = stateHash(p);
  p.velocity[0].z() = std::nextafter(Real(0), Real(1));
  EXPECT_NE(before, stateHash(p));
}

}  // namespace
}  // namespace hs::pbd
