// Solver behaviour: colouring correctness, free fall, shape recovery, thread determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "box_mesh.h"
#include "pbd/core/soft_body.h"
#include "pbd/core/solver.h"

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
  finalizeConstraints(w.constraints, w.particles.position);
  return w;
}

// Brute force: the particles touched by each block, and no two blocks of a colour share one.
template <class Group>
void addTouched(const Group& group, std::size_t block, std::set<Index>& touched) {
  for (std::size_t c = group.blockStart[block]; c < group.blockStart[block + 1]; ++c)
    for (Index p : group.constraints[c].particles) touched.insert(p);
}

void expectBlocksOfAColourAreIndependent(const ConstraintSet& set) {
  const BlockSchedule& s = set.schedule;
  for (std::size_t colour = 0; colour < s.colourCount(); ++colour) {
    std::set<Index> seen;
    for (std::size_t k = s.colourStart[colour]; k < s.colourStart[colour + 1]; ++k) {
      std::set<Index> touched;
      addTouched(set.distances, s.blockOrder[k], touched);
      addTouched(set.areas, s.blockOrder[k], touched);
      addTouched(set.volumes, s.blockOrder[k], touched);
      for (Index p : touched) EXPECT_TRUE(seen.insert(p).second) << "colour " << colour << " shares particle " << p;
    }
  }
}

TEST(Solver, BlockColouringGivesIndependentBlocksAndKeepsEveryConstraint) {
  const World w = makeBoxWorld(8);
  const TetMesh mesh = testing::makeBoxMesh(8, Real(0.1));
  EXPECT_EQ(w.constraints.volumes.size(), mesh.tets.size());
  EXPECT_EQ(w.constraints.volumes.blockStart.back(), mesh.tets.size());
  EXPECT_EQ(w.constraints.distances.blockStart.back(), uniqueEdges(mesh.tets).size());
  EXPECT_EQ(w.constraints.schedule.blockOrder.size(), w.constraints.schedule.blockCount);
  expectBlocksOfAColourAreIndependent(w.constraints);
  // Two regions (one colour, run side by side) and the seam between them (one more colour).
  EXPECT_EQ(w.constraints.schedule.regionCount, 2u);
  EXPECT_EQ(w.constraints.schedule.blockCount, 3u);
  EXPECT_EQ(w.constraints.schedule.colourCount(), 2u);
  EXPECT_EQ(w.constraints.schedule.colourStart[1], 2u);
}

TEST(Solver, LargerBodiesGetMoreRegionsAndStayIndependent) {
  const World w = makeBoxWorld(24);  // 15,625 particles
  EXPECT_EQ(w.constraints.schedule.regionCount, 4u);
  expectBlocksOfAColourAreIndependent(w.constraints);
  // The seams are a small share of the work.
  const auto& v = w.constraints.volumes;
  const auto& s = w.constraints.schedule;
  std::size_t inRegions = 0;
  for (std::size_t k = s.colourStart[0]; k < s.colourStart[1]; ++k)
    inRegions += v.blockStart[s.blockOrder[k] + 1] - v.blockStart[s.blockOrder[k]];
  EXPECT_GT(double(inRegions), 0.8 * double(v.size()));
}

TEST(Solver, GreedyColouringIsProper) {
  // A 5-cycle with a chord needs 3 colours; the greedy result must be a proper colouring.
  const std::vector<std::vector<Index>> graph = {{1, 4, 2}, {0, 2}, {1, 3, 0}, {2, 4}, {3, 0}};
  const std::vector<Index> colour = greedyColouring(graph);
  for (std::size_t v = 0; v < graph.size(); ++v)
    for (Index u : graph[v]) EXPECT_NE(colour[v], colour[u]) << v << "-" << u;
  EXPECT_EQ(*std::max_element(colour.begin(), colour.end()), 2u);
}

TEST(Solver, UnconstrainedParticleFallsLikeSymplecticEuler) {
  Particles p;
  p.add(Vec3::Zero(), 1, ParticleKind::Fluid);
  ConstraintSet none;
  SolverSettings s;
  const StepContext context = makeStepContext(Real(0.01), Vec3(0, Real(-9.81), 0), 1);
  for (int i = 0; i < 100; ++i) step(none, p, s, context);
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
  for (int i = 0; i < 400; ++i) step(c, p, s, makeStepContext(Real(0.005), Vec3(0, Real(-9.81), 0), 1));
  EXPECT_NEAR(p.position[0].y(), Real(0.05), 1e-5);
}

TEST(Solver, SquashedSoftBodyRecoversItsRestShape) {
  World w = makeBoxWorld(3, 0);
  const std::vector<Vec3> rest = w.particles.position;
  for (auto& x : w.particles.position) x.y() *= Real(0.7);  // squash toward the pinned floor
  SolverSettings s;
  s.damping = {5, 5};
  for (int i = 0; i < 400; ++i) step(w.constraints, w.particles, s, makeStepContext(Real(0.005), Vec3::Zero(), 1));
  Real worst = 0;
  for (std::size_t i = 0; i < rest.size(); ++i) worst = std::max(worst, (w.particles.position[i] - rest[i]).norm());
  EXPECT_LT(worst, Real(1e-3));
}

// The projection lists the constraints that can move something once and keeps the list while
// the inverse masses stay as they were: a body made kinematic and then given its mass back must
// be projected again (a stale list would leave it squashed).
TEST(Solver, ConstraintsFollowTheInverseMassesWhenTheyChange) {
  World w = makeBoxWorld(3, 0);
  const std::vector<Vec3> rest = w.particles.position;
  const std::vector<Real> masses = w.particles.inverseMass;
  SolverSettings s;
  s.damping = {5, 5};
  std::fill(w.particles.inverseMass.begin(), w.particles.inverseMass.end(), Real(0));  // all kinematic
  for (auto& x : w.particles.position) x.y() *= Real(0.7);
  const std::vector<Vec3> squashed = w.particles.position;
  for (int i = 0; i < 10; ++i) step(w.constraints, w.particles, s, makeStepContext(Real(0.005), Vec3::Zero(), 1));
  EXPECT_EQ(w.particles.position, squashed);  // nothing to move
  w.particles.inverseMass = masses;
  for (int i = 0; i < 400; ++i) step(w.constraints, w.particles, s, makeStepContext(Real(0.005), Vec3::Zero(), 1));
  Real worst = 0;
  for (std::size_t i = 0; i < rest.size(); ++i) worst = std::max(worst, (w.particles.position[i] - rest[i]).norm());
  EXPECT_LT(worst, Real(1e-3));
}

// A sheared box falling for 50 steps on `threads` threads, its vertices below `freeAbove` (m)
// kinematic, as a state hash.
std::uint64_t shearedBoxHash(int threads, Real freeAbove) {
  World w = makeBoxWorld(8, 0);
  for (std::size_t i = 0; i < w.particles.size(); ++i)
    if (w.particles.position[i].y() < freeAbove) w.particles.inverseMass[i] = 0;
  SolverSettings s;
  for (auto& x : w.particles.position) x += Vec3(Real(0.03) * x.y(), 0, 0);  // shear
  for (int i = 0; i < 50; ++i)
    step(w.constraints, w.particles, s, makeStepContext(Real(0.005), Vec3(0, Real(-9.81), 0), threads, i));
  return stateHash(w.particles);
}

TEST(Solver, SameStateForOneAndTwoThreads) {
  const std::uint64_t one = shearedBoxHash(1, 0);  // all but the floor free: the parallel path
  EXPECT_EQ(one, shearedBoxHash(2, 0));
  EXPECT_EQ(one, shearedBoxHash(1, 0));
}

// A few movable constraints are swept on one thread, many on all: the same state either way.
TEST(Solver, AFewMovableConstraintsGiveTheSameStateOnOneAndTwoThreads) {
  const Real topLayersOnly = Real(0.65);
  EXPECT_EQ(shearedBoxHash(1, topLayersOnly), shearedBoxHash(2, topLayersOnly));
  EXPECT_NE(shearedBoxHash(1, topLayersOnly), shearedBoxHash(1, 0));  // the pinning took
}

TEST(Solver, AWorldListsTheStagesAndAMovedPredictionBecomesVelocity) {
  Particles p;
  p.add(Vec3::Zero(), 1, ParticleKind::Fluid);
  ConstraintSet none;
  SolverSettings s;
  const StepContext context = makeStepContext(Real(0.005), Vec3::Zero(), 1);
  applyExternalForces(p, s, context);
  predictPositions(p, context);
  p.predicted[0].x() += Real(0.001);  // a world's own stage between prediction and update
  projectConstraints(none, p, s, context);
  updateVelocities(p, s, context);
  EXPECT_NEAR(p.velocity[0].x(), Real(0.001) / context.dt, 1e-4);
  EXPECT_NEAR(p.position[0].x(), 0.001, 1e-7);
}

// A parked particle keeps its mass but no stage moves it; a pinned one (w = 0) feels no force.
TEST(Solver, ParkedAndPinnedParticlesStayPut) {
  Particles p;
  p.add(Vec3(0, 1, 0), 1, ParticleKind::Fluid);
  p.add(Vec3(1, 1, 0), 0, ParticleKind::Tissue);
  p.add(Vec3(2, 1, 0), 1, ParticleKind::Fluid);
  p.state[0] = ParticleState::Parked;
  ConstraintSet c;
  c.planes.push_back({Vec3::UnitY(), Real(2)});  // would push every free particle up
  SolverSettings s;
  for (int i = 0; i < 10; ++i) step(c, p, s, makeStepContext(Real(0.01), Vec3(0, Real(-9.81), 0), 1, i));
  EXPECT_EQ(p.position[0], Vec3(0, 1, 0));
  EXPECT_EQ(p.velocity[0], Vec3::Zero());
  EXPECT_EQ(p.position[1], Vec3(1, 1, 0));
  EXPECT_EQ(p.inverseMass[0], Real(1));
  EXPECT_GT(p.position[2].y(), Real(1.9));  // the free one did move
}

TEST(Particles, ReorderingMovesIdentityAndState) {
  Particles p;
  for (int k = 0; k < 4; ++k) p.add(Vec3(Real(k), 0, 0), 1, ParticleKind::Fluid);
  p.state[3] = ParticleState::Parked;
  permuteRange(p, 1, {2, 0, 1});  // slots 1..3 receive old 3, 1, 2
  EXPECT_EQ(p.id, (std::vector<Index>{0, 3, 1, 2}));
  EXPECT_EQ(p.position[1].x(), Real(3));
  EXPECT_FALSE(p.active(1));
  EXPECT_TRUE(p.active(2) && p.active(3));
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
