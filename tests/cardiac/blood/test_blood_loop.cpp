// The closed loop (blood_loop.h): blood past a vessel's far end is parked out of everybody's
// way, keeping its mass; waiting blood re-enters at free sites of the inflow vessel's far
// end, first in first out, wherever a reorder has moved it in the particle arrays.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "cardiac/anatomy/lv_model.h"
#include "cardiac/blood/blood_loop.h"
#include "thesis_model.h"

namespace hs::cardiac {
namespace {

const FlowPath& path() { return testing::thesisModel().flowPath; }

const BloodSettings kBlood{};
const Vec3 kUp = Vec3::UnitY();
constexpr Real kBloodInverseMass = Real(0.25);

// Two wall vertices, then `count` blood particles spread through the ventricle.
struct Scene {
  pbd::Particles particles;
  Index first = 0;
  explicit Scene(std::size_t count) {
    particles.add(Vec3(0, 5, 0), 0, pbd::ParticleKind::Tissue);
    particles.add(Vec3(0, 6, 0), 0, pbd::ParticleKind::Tissue);
    first = Index(particles.size());
    for (std::size_t k = 0; k < count; ++k) {
      const Real t = Real(k) / Real(std::max<std::size_t>(count, 1));
      particles.add(Vec3(Real(1.6) * t - Real(0.8), Real(-0.5) - 3 * t, Real(0.3)), kBloodInverseMass,
                    pbd::ParticleKind::Fluid);
      particles.velocity.back() = Vec3(Real(0.1), Real(0.2), Real(0.3));
    }
  }
  std::size_t blood() const { return particles.size() - first; }
  Index indexOfId(Index id) const {
    return Index(std::find(particles.id.begin(), particles.id.end(), id) - particles.id.begin());
  }
  // Active blood over the inflow vessel's far end on a lattice finer than a spacing: no site
  // there is free. Returns the first of them.
  Index blockInlet() {
    const Orifice& m = path().mitral;
    const Real pitch = Real(0.1);
    const Index firstBlocker = Index(particles.size());
    for (Real dx = -m.radius; dx <= m.radius; dx += pitch)
      for (Real dz = -m.radius; dz <= m.radius; dz += pitch) {
        const Vec3 x(m.centre.x() + dx, path().inflowTop - Real(0.5) * kBlood.spacing, m.centre.z() + dz);
        if (m.radial(x) <= m.radius) particles.add(x, kBloodInverseMass, pbd::ParticleKind::Fluid);
      }
    return firstBlocker;
  }
  // Moves blood particle i past the outflow vessel's end.
  void leaveThroughOutflow(Index i) {
    particles.position[i] =
        Vec3(path().aortic.centre.x(), path().outflowTop + Real(0.05), path().aortic.centre.z());
  }
};

bool parked(const pbd::Particles& p, Index i) { return p.state[i] == pbd::ParticleState::Parked; }

Real highestVesselEnd() { return std::max(path().inflowTop, path().outflowTop); }

TEST(BloodLoop, StartWaitingParksTheLastParticles) {
  Scene s(10);
  const std::vector<Vec3> before = s.particles.position;
  BloodLoop loop(path(), kBlood);
  loop.startWaiting(s.particles, s.first, 4);
  EXPECT_EQ(loop.waiting(), 4u);
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    const bool last = i >= s.particles.size() - 4;
    EXPECT_EQ(parked(s.particles, Index(i)), last) << i;
    if (!last) {
      EXPECT_EQ(s.particles.position[i], before[i]) << i;
    }
  }
}

// Parked: state Parked, mass kept, at rest, above the vessels and more than a kernel support
// from any other parked particle (nobody's neighbour). More than one layer of the lot.
TEST(BloodLoop, ParkedBloodWaitsOutOfEverybodysWay) {
  const std::size_t n = 150;
  Scene s(n);
  BloodLoop loop(path(), kBlood);
  loop.startWaiting(s.particles, s.first, n);
  for (std::size_t i = s.first; i < s.particles.size(); ++i) {
    EXPECT_TRUE(parked(s.particles, Index(i)));
    EXPECT_EQ(s.particles.inverseMass[i], kBloodInverseMass);
    EXPECT_EQ(s.particles.velocity[i], Vec3::Zero());
    EXPECT_EQ(s.particles.predicted[i], s.particles.position[i]);
    EXPECT_GT(s.particles.position[i].y() - highestVesselEnd(), kBlood.supportRadius) << i;
    EXPECT_EQ(path().classify(s.particles.position[i], kBlood.radius, kBlood.spacing), FlowRegion::Outside);
    for (std::size_t j = s.first; j < i; ++j)
      ASSERT_GT((s.particles.position[i] - s.particles.position[j]).norm(), kBlood.supportRadius)
          << i << " " << j;
  }
}

TEST(BloodLoop, BloodPastEitherVesselEndIsParked) {
  Scene s(4);
  const Index inflowBlocker = s.blockInlet();  // keep the parked blood from re-entering at once
  BloodLoop loop(path(), kBlood);
  s.leaveThroughOutflow(s.first + 1);
  s.particles.position[s.first + 2] =
      Vec3(path().mitral.centre.x(), path().inflowTop + Real(0.05), path().mitral.centre.z());
  s.particles.position[s.first + 3] = path().aortic.centre + Real(1.0) * kUp;  // in the vessel: stays
  const BloodLoop::Turnover t = loop.circulate(s.particles, s.first);
  EXPECT_EQ(t.returned, 2u);
  EXPECT_EQ(t.reentered, 0u);
  EXPECT_EQ(loop.waiting(), 2u);
  EXPECT_FALSE(parked(s.particles, s.first));
  EXPECT_TRUE(parked(s.particles, s.first + 1));
  EXPECT_TRUE(parked(s.particles, s.first + 2));
  EXPECT_FALSE(parked(s.particles, s.first + 3));
  for (Index i : {s.first + 1, s.first + 2}) {
    EXPECT_EQ(s.particles.inverseMass[i], kBloodInverseMass);
    EXPECT_EQ(s.particles.velocity[i], Vec3::Zero());
    EXPECT_GT(s.particles.position[i].y() - highestVesselEnd(), kBlood.supportRadius);
  }
  for (std::size_t i = inflowBlocker; i < s.particles.size(); ++i)
    EXPECT_FALSE(parked(s.particles, Index(i)));
}

TEST(BloodLoop, WaitingBloodReentersAtTheInflowVesselsFarEnd) {
  Scene s(8);
  BloodLoop loop(path(), kBlood);
  loop.startWaiting(s.particles, s.first, 3);
  const BloodLoop::Turnover t = loop.circulate(s.particles, s.first);
  EXPECT_EQ(t.returned, 0u);
  EXPECT_EQ(t.reentered, 3u);
  EXPECT_EQ(loop.waiting(), 0u);
  const Orifice& m = path().mitral;
  for (std::size_t i = s.particles.size() - 3; i < s.particles.size(); ++i) {
    const Vec3& x = s.particles.position[i];
    EXPECT_FALSE(parked(s.particles, Index(i)));
    EXPECT_EQ(s.particles.predicted[i], x);
    EXPECT_EQ(s.particles.inverseMass[i], kBloodInverseMass);
    EXPECT_EQ(path().classify(x, kBlood.radius, kBlood.spacing), FlowRegion::InflowVessel);
    EXPECT_LE(m.radial(x), m.radius - kBlood.radius + Real(1e-5));  // a radius inside the lumen wall
    EXPECT_LE(x.y(), path().inflowTop);
    EXPECT_GE(x.y(), path().inflowTop - kBlood.spacing);
    EXPECT_EQ(s.particles.velocity[i], Vec3::Zero());  // nothing there to move with
    for (std::size_t j = s.particles.size() - 3; j < i; ++j)
      EXPECT_GE((x - s.particles.position[j]).norm(), kBlood.spacing - Real(1e-5));
  }
}

// Re-entering blood joins the column at the far end: its velocity along the vessel, never
// back out of it.
TEST(BloodLoop, ReenteringBloodMovesWithTheBloodThere) {
  const Orifice& m = path().mitral;
  const Vec3 nearEnd(m.centre.x(), path().inflowTop - Real(0.5) * kBlood.spacing, m.centre.z());
  for (const Real speed : {Real(0.5), Real(-0.5)}) {
    Scene s(3);
    s.particles.position[s.first] = nearEnd;
    s.particles.velocity[s.first] = speed * m.forward + Real(0.2) * Vec3::UnitX();
    BloodLoop loop(path(), kBlood);
    loop.startWaiting(s.particles, s.first, 1);
    ASSERT_EQ(loop.circulate(s.particles, s.first).reentered, 1u);
    const Vec3& v = s.particles.velocity[s.first + 2];
    const Vec3 expected = std::max(speed, Real(0)) * m.forward;
    EXPECT_LT((v - expected).norm(), Real(1e-6)) << "speed " << speed;
    EXPECT_GE((s.particles.position[s.first + 2] - nearEnd).norm(), Real(0.5) * kBlood.spacing);
  }
}

TEST(BloodLoop, NoReentryOntoAnOccupiedSite) {
  Scene s(5);
  s.blockInlet();
  BloodLoop loop(path(), kBlood);
  loop.startWaiting(s.particles, s.first, 2);
  const std::vector<Vec3> before = s.particles.position;
  for (int step = 0; step < 3; ++step) {
    const BloodLoop::Turnover t = loop.circulate(s.particles, s.first);
    EXPECT_EQ(t.returned, 0u);
    EXPECT_EQ(t.reentered, 0u);
    EXPECT_EQ(loop.waiting(), 2u);
  }
  EXPECT_EQ(s.particles.position, before);
}

// Re-entering blood keeps clear of the blood already at the far end and of each other.
TEST(BloodLoop, ReenteringBloodDoesNotLandOnOtherBlood) {
  const Orifice& m = path().mitral;
  Scene s(60);
  std::mt19937 rng(5);
  std::uniform_real_distribution<Real> u(-1, 1);
  const std::size_t crowd = 12;
  for (std::size_t k = 0; k < crowd; ++k) {
    Vec3 x;
    do {
      x = Vec3(m.centre.x() + m.radius * u(rng), path().inflowTop - kBlood.spacing * (1 + u(rng)),
               m.centre.z() + m.radius * u(rng));
    } while (m.radial(x) > m.radius - kBlood.radius);
    s.particles.position[s.first + k] = x;
  }
  BloodLoop loop(path(), kBlood);
  loop.startWaiting(s.particles, s.first, s.blood() - crowd);
  const BloodLoop::Turnover t = loop.circulate(s.particles, s.first);
  EXPECT_GT(t.reentered, 0u);
  EXPECT_EQ(t.reentered + loop.waiting(), s.blood() - crowd);
  for (std::size_t i = s.first + crowd; i < s.particles.size(); ++i) {
    if (parked(s.particles, Index(i))) continue;
    for (std::size_t j = s.first; j < s.particles.size(); ++j) {
      if (j == i || parked(s.particles, Index(j))) continue;
      EXPECT_GT((s.particles.position[i] - s.particles.position[j]).norm(), Real(0.5) * kBlood.spacing)
          << i << " " << j;
    }
  }
}

// Parked in two groups, the later group with the lower indices; more waiting than the far end
// has sites: the ones still waiting are the last ones parked.
TEST(BloodLoop, FirstParkedFirstToReenter) {
  const std::size_t group = 40;  // fewer than the far end has sites, two groups more
  Scene s(2 * group);
  const Index blockers = s.blockInlet();
  BloodLoop loop(path(), kBlood);
  std::vector<Index> parkOrder;  // ids
  for (const std::size_t start : {group, std::size_t(0)}) {
    for (std::size_t k = start; k < start + group; ++k) {
      s.leaveThroughOutflow(Index(s.first + k));
      parkOrder.push_back(s.particles.id[s.first + k]);
    }
    ASSERT_EQ(loop.circulate(s.particles, s.first).returned, group);
  }
  ASSERT_EQ(loop.waiting(), 2 * group);
  for (std::size_t i = blockers; i < s.particles.size(); ++i)
    s.particles.position[i].y() -= 1;  // clear the end
  const std::size_t reentered = loop.circulate(s.particles, s.first).reentered;
  const std::size_t left = loop.waiting();
  ASSERT_GT(reentered, 0u);
  ASSERT_GT(left, 0u);
  ASSERT_LT(left, group);
  for (std::size_t k = 0; k < parkOrder.size(); ++k)
    EXPECT_EQ(parked(s.particles, s.indexOfId(parkOrder[k])), k >= parkOrder.size() - left)
        << "parked " << k << "th";
}

// The ids, not the indices, say who waits: reordering the blood between parking and re-entry
// (as HeartSimulation does every kReorderInterval steps) re-enters the same particles, each
// with all its columns.
TEST(BloodLoop, ReentryFollowsTheIdThroughAReorder) {
  Scene s(20);
  s.blockInlet();
  BloodLoop loop(path(), kBlood);
  const std::vector<Index> leaving = {s.first + 3, s.first + 11};
  std::vector<Index> ids;
  for (Index i : leaving) {
    s.leaveThroughOutflow(i);
    s.particles.inverseMass[i] = Real(0.5);  // marks them: the mass must travel with the id
    ids.push_back(s.particles.id[i]);
  }
  ASSERT_EQ(loop.circulate(s.particles, s.first).returned, 2u);
  std::vector<Index> order(s.blood());
  std::iota(order.begin(), order.end(), Index(0));
  std::shuffle(order.begin(), order.end(), std::mt19937(11));
  pbd::permuteRange(s.particles, s.first, order);
  for (std::size_t i = s.first; i < s.particles.size(); ++i)  // clear the far end
    if (!parked(s.particles, Index(i)) && s.particles.position[i].y() > path().inflowTop - 1)
      s.particles.position[i].y() -= 1;
  const std::vector<Vec3> before = s.particles.position;
  ASSERT_EQ(loop.circulate(s.particles, s.first).reentered, 2u);
  for (std::size_t i = s.first; i < s.particles.size(); ++i) {
    const bool reentered = std::find(ids.begin(), ids.end(), s.particles.id[i]) != ids.end();
    EXPECT_FALSE(parked(s.particles, Index(i)));
    if (reentered) {
      EXPECT_EQ(s.particles.inverseMass[i], Real(0.5));
      EXPECT_EQ(path().classify(s.particles.position[i], kBlood.radius, kBlood.spacing),
                FlowRegion::InflowVessel);
    } else {
      EXPECT_EQ(s.particles.position[i], before[i]) << i;
    }
  }
}

}  // namespace
}  // namespace hs::cardiac
