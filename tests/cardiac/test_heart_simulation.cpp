// The coupled step (heart_simulation.h): what it builds for heart only, blood only and both,
// the clock, the blood's identity through reorders, determinism across thread counts, and a
// wall that beats.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "cardiac/heart_simulation.h"
#include "pbd/core/solver.h"
#include "thrown_message.h"

namespace hs::cardiac {
namespace {

// The thesis-scale heart with a little blood, starting in the inflow vessel.
Scenario heartWithBlood(int particles) {
  Scenario s;
  s.blood.enabled = true;
  s.blood.start = BloodSettings::Start::Vessel;
  s.blood.particles = particles;
  return s;
}

// The blood's ids, sorted: [first, end) when they are a permutation of the blood's slots.
std::vector<Index> sortedBloodIds(const HeartSimulation& sim) {
  std::vector<Index> ids(sim.particles().id.begin() + sim.firstBloodParticle(), sim.particles().id.end());
  std::sort(ids.begin(), ids.end());
  return ids;
}

std::vector<Index> range(Index first, Index end) {
  std::vector<Index> r(end - first);
  std::iota(r.begin(), r.end(), first);
  return r;
}

TEST(HeartSimulation, NothingToSimulateIsAClearError) {
  Scenario s;
  s.heart = false;
  s.blood.enabled = false;
  const std::string message =
      hs::testing::thrownMessage<std::invalid_argument>([&] { HeartSimulation sim(s, 1); });
  EXPECT_NE(message.find("nothing to simulate"), std::string::npos) << message;
}

TEST(HeartSimulation, HeartOnlyIsTheModelsVertices) {
  const HeartSimulation sim(Scenario{}, 1);
  ASSERT_TRUE(sim.hasHeart());
  EXPECT_FALSE(sim.hasBlood());
  EXPECT_EQ(sim.circulation(), nullptr);
  EXPECT_TRUE(sim.pressures().empty());
  const std::size_t vertices = sim.model().mesh.vertices.size();
  EXPECT_EQ(sim.particles().size(), vertices);
  EXPECT_EQ(sim.firstBloodParticle(), vertices);
  for (std::size_t v = 0; v < vertices; ++v) {
    EXPECT_EQ(sim.particles().kind[v], pbd::ParticleKind::Tissue);
    EXPECT_EQ(sim.particles().position[v], sim.model().mesh.vertices[v]);  // particle = model vertex
  }
  for (Index v : sim.model().pinned) EXPECT_EQ(sim.particles().inverseMass[v], 0) << v;
  EXPECT_NEAR(sim.restDeviationRelative(), 0, 1e-9);
}

TEST(HeartSimulation, BloodOnlyIsTheBlood) {
  Scenario s;
  s.heart = false;
  s.blood.enabled = true;
  s.blood.particles = 200;
  HeartSimulation sim(s, 1);
  EXPECT_FALSE(sim.hasHeart());
  ASSERT_TRUE(sim.hasBlood());
  EXPECT_EQ(sim.circulation(), nullptr);
  EXPECT_EQ(sim.firstBloodParticle(), 0u);
  EXPECT_EQ(sim.particles().size(), 200u);
  for (std::size_t i = 0; i < sim.particles().size(); ++i) {
    EXPECT_EQ(sim.particles().kind[i], pbd::ParticleKind::Fluid);
    EXPECT_TRUE(sim.bloodActive(Index(i)));
    EXPECT_EQ(sim.bloodOrigin(Index(i)), FlowRegion::Outside);  // no heart, no flow path
    // Inside the start block.
    const Vec3& x = sim.particles().position[i];
    for (int a = 0; a < 3; ++a) {
      EXPECT_GE(x[a], s.blood.blockMin[a] - Real(1e-5));
      EXPECT_LE(x[a], s.blood.blockMax[a] + Real(1e-5));
    }
  }
  sim.step();
  EXPECT_EQ(sim.pressures().size(), sim.particles().size());
}

TEST(HeartSimulation, HeartAndBloodAreTheWallThenTheBlood) {
  const HeartSimulation sim(heartWithBlood(300), 1);
  ASSERT_TRUE(sim.hasHeart() && sim.hasBlood());
  ASSERT_NE(sim.circulation(), nullptr);
  const Index first = sim.firstBloodParticle();
  EXPECT_EQ(first, sim.model().mesh.vertices.size());
  EXPECT_EQ(sim.particles().size(), std::size_t(first) + 300);
  for (std::size_t i = 0; i < sim.particles().size(); ++i) {
    const bool blood = i >= first;
    EXPECT_EQ(sim.particles().kind[i], blood ? pbd::ParticleKind::Fluid : pbd::ParticleKind::Tissue) << i;
    if (!blood) {
      EXPECT_EQ(sim.particles().id[i], i);  // the wall is never reordered
    }
  }
  EXPECT_EQ(sortedBloodIds(sim), range(first, Index(sim.particles().size())));
  // Started in the inflow vessel: every particle there, by the flow path's own test.
  const FlowPath& path = sim.model().flowPath;
  for (std::size_t i = first; i < sim.particles().size(); ++i) {
    EXPECT_TRUE(sim.bloodActive(Index(i)));
    EXPECT_EQ(
        path.classify(sim.particles().position[i], sim.scenario().blood.radius, sim.scenario().blood.spacing),
        FlowRegion::InflowVessel);
  }
}

TEST(HeartSimulation, TimeIsStepsTimesTheTimeStep) {
  Scenario s;
  s.simulation.dt = Real(0.004);
  HeartSimulation sim(s, 1);
  EXPECT_EQ(sim.stepCount(), 0);
  EXPECT_EQ(sim.time(), 0.0);
  for (int k = 1; k <= 7; ++k) {
    sim.step();
    EXPECT_EQ(sim.stepCount(), k);
    EXPECT_DOUBLE_EQ(sim.time(), k * double(s.simulation.dt));
  }
}

// The closed loop and the reorders move the blood around, but every particle stays, and the
// blood's ids stay a permutation of its slots.
TEST(HeartSimulation, BloodKeepsItsCountAndIdsThroughReorders) {
  HeartSimulation sim(heartWithBlood(300), 1);
  const std::size_t size = sim.particles().size();
  const Index first = sim.firstBloodParticle();
  const std::vector<Index> ids = range(first, Index(size));
  bool reordered = false;
  std::vector<Index> previous(sim.particles().id);
  for (int k = 0; k < 2 * HeartSimulation::kReorderInterval + 2; ++k) {
    sim.step();
    ASSERT_EQ(sim.particles().size(), size) << "step " << k;
    ASSERT_EQ(sim.firstBloodParticle(), first);
    ASSERT_EQ(sortedBloodIds(sim), ids) << "step " << k;
    reordered = reordered || sim.particles().id != previous;
    previous = sim.particles().id;
    const auto& count = sim.circulation()->meter.lastStep().count;
    ASSERT_EQ(std::accumulate(count.begin(), count.end(), std::size_t(0)), size - first) << "step " << k;
  }
  EXPECT_TRUE(reordered);
  for (std::size_t i = 0; i < first; ++i) EXPECT_EQ(sim.particles().id[i], i);
}

// bloodOrigin is where a particle started (its region at t = 0), whichever slot it is in now.
// The vessel start fills the inflow vessel first, then the ventricle: with a few particles
// more than the vessel holds, both origins occur.
TEST(HeartSimulation, BloodOriginFollowsTheParticleThroughAReorder) {
  Scenario s = heartWithBlood(0);
  const LvModel model = buildLvModel(s.geometry);
  std::size_t inVessel = 0;
  for (const Vec3& x : bloodStartPositions(s, &model))
    inVessel += model.flowPath.classify(x, s.blood.radius, s.blood.spacing) == FlowRegion::InflowVessel;
  s.blood.particles = int(inVessel) + 40;
  HeartSimulation sim(s, 1);
  const Index first = sim.firstBloodParticle();
  std::vector<FlowRegion> originById(sim.particles().size(), FlowRegion::Outside);
  for (std::size_t i = first; i < sim.particles().size(); ++i) {
    const FlowRegion r =
        model.flowPath.classify(sim.particles().position[i], s.blood.radius, s.blood.spacing);
    EXPECT_EQ(sim.bloodOrigin(Index(i)), r) << i;
    originById[sim.particles().id[i]] = r;
  }
  EXPECT_EQ(std::size_t(std::count(originById.begin(), originById.end(), FlowRegion::InflowVessel)),
            inVessel);
  EXPECT_EQ(std::count(originById.begin(), originById.end(), FlowRegion::Ventricle), 40);
  const std::vector<Index> idsAtStart(sim.particles().id);
  for (int k = 0; k <= HeartSimulation::kReorderInterval; ++k) sim.step();
  ASSERT_NE(sim.particles().id, idsAtStart);  // a reorder happened
  for (std::size_t i = first; i < sim.particles().size(); ++i)
    EXPECT_EQ(sim.bloodOrigin(Index(i)), originById[sim.particles().id[i]]) << i;
}

TEST(HeartSimulation, SameStateOnOneAndTwoThreads) {
  const Scenario s = heartWithBlood(300);
  HeartSimulation one(s, 1), two(s, 2);
  two.governThreads({.adaptive = false});  // every step on both threads, however busy the machine
  for (int k = 0; k < 60; ++k) {
    one.step();
    two.step();
  }
  EXPECT_EQ(pbd::stateHash(one.particles()), pbd::stateHash(two.particles()));
  EXPECT_EQ(one.particles().id, two.particles().id);
}

// The thread governor changes the count between steps (here every two or three steps: probes of
// two steps on each count, holds of one): the state is the one thread's, bit for bit.
TEST(HeartSimulation, TheThreadCountMayChangeBetweenStepsWithoutChangingTheState) {
  const Scenario s = heartWithBlood(300);
  HeartSimulation one(s, 1), governed(s, 2);
  governed.governThreads({.probeSteps = 2, .holdSteps = 1, .holdSeconds = 0, .maxHoldScale = 1});
  for (int k = 0; k < 60; ++k) {
    one.step();
    governed.step();
  }
  EXPECT_EQ(pbd::stateHash(one.particles()), pbd::stateHash(governed.particles()));
  EXPECT_EQ(one.particles().id, governed.particles().id);
  // Both counts were used: each probe of one thread is 2 of every 5 steps.
  EXPECT_GE(governed.threadGovernor().reducedSteps(), 60 * 2 / 5 - 2);
  EXPECT_LT(governed.threadGovernor().reducedSteps(), 60);
}

// Thesis cycle: the myocardium is moved inward every systolic step, so the cavity is smaller
// than at rest throughout the first systole and at least a tenth smaller at its smallest; in
// the diastole that follows the wall is released and the cavity grows again.
TEST(HeartSimulation, TheWallBeats) {
  Scenario s;
  HeartSimulation sim(s, 1);
  const Real rest = sim.cavityVolume();
  EXPECT_GT(rest, 0);
  Real smallest = rest;
  for (int k = 0; k < s.cycle.beatingDuration; ++k) {
    sim.step();
    EXPECT_EQ(sim.lastPhase(), Phase::Systole) << "step " << k;
    EXPECT_LT(sim.cavityVolume(), rest) << "step " << k;
    smallest = std::min(smallest, sim.cavityVolume());
  }
  EXPECT_LT(smallest, Real(0.9) * rest);
  Real largest = 0;
  for (int k = 0; k < s.cycle.beatingDuration; ++k) {
    sim.step();
    EXPECT_EQ(sim.lastPhase(), Phase::Diastole) << "step " << k;
    largest = std::max(largest, sim.cavityVolume());
  }
  EXPECT_GT(largest, Real(0.95) * rest);
  const TissueStats tissue = sim.tissueStats();
  EXPECT_TRUE(tissue.finite);
  EXPECT_EQ(tissue.invertedTets, 0u);
}

// Physiological cycle: the wall follows a prescribed inward path for the whole systole, so
// the cavity shrinks at every step of it and is smallest when it ends.
TEST(HeartSimulation, PhysiologicalSystoleShrinksTheCavityEveryStep) {
  Scenario s;
  s.cycle.mode = TimingMode::Physiological;
  s.geometry.resolution = Real(0.5);  // the cycle does not depend on the mesh; keep it quick
  HeartSimulation sim(s, 1);
  Real previous = sim.cavityVolume();
  const Real rest = previous;
  int systoleSteps = 0;
  for (sim.step(); sim.lastPhase() == Phase::Systole; sim.step()) {
    EXPECT_LT(sim.cavityVolume(), previous) << "step " << sim.stepCount();
    previous = sim.cavityVolume();
    ++systoleSteps;
  }
  const double expectedSteps =
      60.0 / double(s.cycle.heartRateBpm) * double(s.cycle.systolicFraction) / double(s.simulation.dt);
  EXPECT_NEAR(systoleSteps, expectedSteps, 1.5);
  EXPECT_LT(previous, Real(0.9) * rest);
  EXPECT_EQ(sim.lastPhase(), Phase::Diastole);
}

// The held shell (cycle.base_held) is kinematic: its beating vertices have no mass, reach their
// end-systolic targets when the systole ends whatever the constraints would say, and are back at
// rest when the relaxation ends, staying there to the next systole.
TEST(HeartSimulation, AHeldWallFollowsItsPathAndComesBackToRest) {
  Scenario s;
  s.cycle.mode = TimingMode::Physiological;
  s.cycle.baseHeld = true;
  s.geometry.resolution = Real(0.5);
  HeartSimulation sim(s, 1);
  const BeatingRegion& region = sim.cycle().regions().front();
  for (Index p : region.particles) ASSERT_EQ(sim.particles().inverseMass[p], 0) << "particle " << p;
  auto farthest = [&](const std::vector<Vec3>& goal) {
    double d = 0;
    for (std::size_t k = 0; k < region.particles.size(); ++k)
      d = std::max(d, double((sim.particles().position[region.particles[k]] - goal[k]).norm()));
    return d;
  };
  sim.step();
  while (sim.lastPhase() == Phase::Systole) {
    const double before = farthest(region.target);
    sim.step();
    if (sim.lastPhase() == Phase::Systole) {
      EXPECT_LT(farthest(region.target), before);
    }
  }
  const double scale = double(s.geometry.endoRadius);
  EXPECT_LT(farthest(region.target), 1e-3 * scale) << "the systole ended at its targets";
  const Real rest = cardiac::cavityVolume(sim.model(), sim.model().mesh.vertices);
  EXPECT_LT(sim.cavityVolume(), Real(0.8) * rest);
  while (sim.lastPhase() == Phase::Diastole) {
    sim.step();
    // The relaxation takes 0.8 of the diastole, over by 0.73 s of the 0.83 s beat.
    if (sim.lastPhase() == Phase::Diastole && double(sim.time()) > 0.9 * 60 / double(s.cycle.heartRateBpm)) {
      EXPECT_LT(farthest(region.rest), 1e-6 * scale) << "at rest after the relaxation, t = " << sim.time();
    }
  }
  EXPECT_EQ(sim.lastPhase(), Phase::Systole);
  EXPECT_EQ(sim.tissueStats().invertedTets, 0u);
}

}  // namespace
}  // namespace hs::cardiac
