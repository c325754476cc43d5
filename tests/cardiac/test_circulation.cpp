// The blood's path (circulation.h): closed valves are walls, crossings are counted by
// direction, timing mode opens the right valve, pressure mode opens a valve only for a
// forward pressure difference, and the closed loop keeps every particle.
#include <gtest/gtest.h>

#include <random>

#include "cardiac/circulation.h"
#include "cardiac/heart_simulation.h"

namespace hs::cardiac {
namespace {

Orifice disc() {
  Orifice o;
  o.centre = Vec3(1, 0, 0);
  o.forward = -Vec3::UnitY();  // forward is down, like the mitral orifice
  o.radius = Real(0.5);
  return o;
}

TEST(Valve, ClosedOrificeIsAWallFromBothSides) {
  const Orifice o = disc();
  const Real r = Real(0.08);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1, 1);
  for (int k = 0; k < 2000; ++k) {
    const Vec3 x = o.centre + Vec3(Real(0.4) * u(rng), u(rng), Real(0.4) * u(rng));
    Vec3 p = x + Vec3(Real(0.1) * u(rng), u(rng), Real(0.1) * u(rng));
    gateClosedOrifice(o, x, p, r);
    if (o.radial(p) >= o.radius) continue;  // beyond the rim: the wall's business
    // p stays on x's side, at least r from the disc.
    const Real from = o.side(x) >= 0 ? Real(1) : Real(-1);
    EXPECT_GE(from * o.side(p), r - Real(1e-5)) << "case " << k;
    EXPECT_EQ(crossing(o, x, p), 0) << "case " << k;
  }
}

TEST(Valve, CrossingsAreCountedByDirectionInsideTheDiscOnly) {
  const Orifice o = disc();
  const Vec3 above = o.centre + Vec3(Real(0.1), Real(0.2), 0);
  const Vec3 below = o.centre + Vec3(Real(0.1), Real(-0.2), 0);
  EXPECT_EQ(crossing(o, above, below), 1);   // down = forward
  EXPECT_EQ(crossing(o, below, above), -1);  // up = backward
  EXPECT_EQ(crossing(o, above, above + Vec3(0, Real(0.05), 0)), 0);
  const Vec3 outside(Real(0.6), 0, 0);  // 0.6 m beside the axis: past the rim
  EXPECT_EQ(crossing(o, o.centre + outside + Vec3(0, 1, 0), o.centre + outside - Vec3(0, 1, 0)), 0);
}

TEST(Valve, TimingModeOpensMitralInDiastoleAndAorticInSystole) {
  EXPECT_FALSE(timedValves(true, Phase::Systole).mitralOpen);
  EXPECT_TRUE(timedValves(true, Phase::Systole).aorticOpen);
  EXPECT_TRUE(timedValves(true, Phase::Diastole).mitralOpen);
  EXPECT_FALSE(timedValves(true, Phase::Diastole).aorticOpen);
  EXPECT_TRUE(timedValves(false, Phase::Systole).mitralOpen && timedValves(false, Phase::Systole).aorticOpen);
}

Scenario heartWithBlood(int particles) {
  Scenario s;
  s.blood.enabled = true;
  s.blood.start = BloodSettings::Start::Vessel;
  s.blood.particles = particles;
  s.blood.xsph = Real(0.3);
  return s;
}

// Pressure mode, the ventricle full and squeezed (systole) with the mitral valve between it
// and an empty inflow vessel: the valve must stay shut, so no blood goes back up.
TEST(Valve, PressureModeKeepsBackflowOut) {
  Scenario s = heartWithBlood(0);
  s.blood.start = BloodSettings::Start::Chamber;
  s.blood.particles = 1200;
  s.circulation.valveMode = ValveMode::Pressure;
  s.cycle.beatingDuration = 20;
  HeartSimulation sim(s, 1);
  std::size_t backward = 0, closedSteps = 0;
  for (int k = 0; k < 40; ++k) {  // two systoles' worth of squeezing
    sim.step();
    backward += sim.circulation()->meter.lastStep().mitralBackward;
    closedSteps += !sim.circulation()->meter.lastStep().valves.mitralOpen;
  }
  EXPECT_GT(closedSteps, 0u);
  EXPECT_EQ(backward, 0u);
}

// Blood leaving through the outflow vessel's end re-enters the inflow vessel: over a run
// with all valves open, the count never changes, nothing is lost, and some blood made the
// trip (it is pushed up the outflow vessel by the beating wall).
TEST(Circulation, ClosedLoopKeepsEveryParticle) {
  Scenario s = heartWithBlood(1000);
  s.circulation.valveMode = ValveMode::Open;
  HeartSimulation sim(s, 2);
  const std::size_t total = sim.particles().size() - sim.firstBloodParticle();
  std::size_t returned = 0, reentered = 0;
  for (int k = 0; k < 200; ++k) {
    sim.step();
    const FlowStep& f = sim.circulation()->meter.lastStep();
    returned += f.returned;
    reentered += f.reentered;
    std::size_t counted = 0;
    for (std::size_t c : f.count) counted += c;
    ASSERT_EQ(counted, total) << "step " << k;
  }
  const BloodStats stats = sim.bloodStats();
  EXPECT_EQ(stats.particles, total);
  EXPECT_EQ(stats.lost, 0u);
  std::printf("returned %zu, re-entered %zu\n", returned, reentered);
}

}  // namespace
}  // namespace hs::cardiac
