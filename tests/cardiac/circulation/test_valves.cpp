// The valves (valves.h): which are open in each mode, and a closed valve as a wall that keeps
// a particle its radius on the side it started on, for the fluid solver's working points and
// for the particles' predictions alike. Open valves touch nothing.
#include <gtest/gtest.h>

#include <vector>

#include "cardiac/anatomy/lv_model.h"
#include "cardiac/blood/blood_settings.h"
#include "cardiac/circulation/valves.h"

namespace hs::cardiac {
namespace {

const FlowPath& path() {
  static const LvModel m = buildLvModel(LvGeometryParams{});
  return m.flowPath;
}

const Real kRadius = BloodSettings{}.radius;

Valves valves(ValveMode mode, bool cycleEnabled = true) {
  return Valves(path(), mode, cycleEnabled, kRadius);
}

// Pressures for a forward (upstream above downstream) or backward difference at each valve.
ValvePressures pressures(bool mitralForward, bool aorticForward) {
  ValvePressures p;
  p.mitralUpstream = mitralForward ? 200 : 100;
  p.mitralDownstream = mitralForward ? 100 : 200;
  p.aorticUpstream = aorticForward ? 300 : 100;
  p.aorticDownstream = aorticForward ? 100 : 300;
  return p;
}

TEST(Valves, TimingModeFollowsThePhase) {
  Valves v = valves(ValveMode::Timing);
  v.decide(Phase::Systole, pressures(true, false));  // pressures do not matter in timing mode
  EXPECT_FALSE(v.states().mitralOpen);
  EXPECT_TRUE(v.states().aorticOpen);
  v.decide(Phase::Diastole, pressures(false, true));
  EXPECT_TRUE(v.states().mitralOpen);
  EXPECT_FALSE(v.states().aorticOpen);
}

TEST(Valves, TimingModeWithTheCycleOffLeavesBothOpen) {
  Valves v = valves(ValveMode::Timing, false);
  for (Phase phase : {Phase::Systole, Phase::Diastole, Phase::Rest}) {
    v.decide(phase, pressures(false, false));
    EXPECT_TRUE(v.states().mitralOpen && v.states().aorticOpen) << phaseName(phase);
  }
}

TEST(Valves, OpenModeIsAlwaysOpen) {
  Valves v = valves(ValveMode::Open);
  for (Phase phase : {Phase::Systole, Phase::Diastole}) {
    v.decide(phase, pressures(false, false));
    EXPECT_TRUE(v.states().mitralOpen && v.states().aorticOpen) << phaseName(phase);
  }
}

TEST(Valves, PressureModeOpensOnlyForAForwardDifference) {
  Valves v = valves(ValveMode::Pressure);
  for (bool mitral : {false, true})
    for (bool aortic : {false, true})
      for (Phase phase : {Phase::Systole, Phase::Diastole}) {  // the phase does not matter
        v.decide(phase, pressures(mitral, aortic));
        EXPECT_EQ(v.states().mitralOpen, mitral);
        EXPECT_EQ(v.states().aorticOpen, aortic);
      }
  // No difference, no flow: closed (the first step, before any pressure is measured).
  v.decide(Phase::Diastole, ValvePressures{});
  EXPECT_FALSE(v.states().mitralOpen);
  EXPECT_FALSE(v.states().aorticOpen);
}

// A particle above the mitral disc (upstream) predicted below it: the closed valve puts it
// back on the disc's upstream side, one radius from it, moving along the disc's normal only.
TEST(Valves, ClosedOrificeHoldsACrossingParticleOnItsStartSide) {
  const Orifice& m = path().mitral;
  const Vec3 offset(Real(0.2), 0, Real(-0.1));
  const Vec3 x = m.centre + offset + Real(0.1) * Vec3::UnitY();
  Vec3 p = m.centre + offset + Real(0.05) * Vec3(1, -2, 0);
  ASSERT_EQ(m.side(x) < 0, m.side(p) > 0);  // it crosses
  EXPECT_TRUE(gateClosedOrifice(m, x, p, kRadius));
  EXPECT_NEAR(m.side(p), -kRadius, 1e-6);
  EXPECT_NEAR(p.x(), m.centre.x() + offset.x() + Real(0.05), 1e-6);
  EXPECT_NEAR(p.z(), m.centre.z() + offset.z(), 1e-6);
  // From below, moving up: held below.
  Vec3 q = x;
  EXPECT_TRUE(gateClosedOrifice(m, p - Real(0.3) * Vec3::UnitY(), q, kRadius));
  EXPECT_NEAR(m.side(q), kRadius, 1e-6);
}

TEST(Valves, ClosedOrificeLeavesClearPointsAndPointsBeyondItsRim) {
  const Orifice& a = path().aortic;
  const Vec3 x = a.centre - Real(0.5) * Vec3::UnitY();
  Vec3 clear = a.centre - 2 * kRadius * Vec3::UnitY();  // still a radius and more below
  EXPECT_FALSE(gateClosedOrifice(a, x, clear, kRadius));
  EXPECT_EQ(clear, a.centre - 2 * kRadius * Vec3::UnitY());
  const Vec3 beyondRim = a.centre + (a.radius + Real(0.1)) * Vec3::UnitZ();
  Vec3 p = beyondRim + Real(0.1) * Vec3::UnitY();
  EXPECT_FALSE(gateClosedOrifice(a, beyondRim - Real(0.1) * Vec3::UnitY(), p, kRadius));
  EXPECT_EQ(p, beyondRim + Real(0.1) * Vec3::UnitY());
}

// Open leaflets hang as a tube of the disc's radius: a particle inside it is held inside, one
// outside held outside, each its radius from the tube and moved across the axis only; above
// the disc and beyond the tips nothing is held.
TEST(Valves, OpenLeafletsHoldAParticleOnItsSideOfTheTube) {
  const Orifice& m = path().mitral;
  const Real length = Real(0.8), R = m.radius;
  const Vec3 down = m.forward, across = Vec3::UnitZ();
  ASSERT_NEAR(down.dot(across), 0, 1e-6);
  const Vec3 level = m.centre + Real(0.4) * down;
  {
    const Vec3 x = level + (R - Real(0.2)) * across;  // inside
    Vec3 p = level + (R + Real(0.1)) * across + Real(0.05) * down;
    EXPECT_TRUE(gateOpenLeaflets(m, length, x, p, kRadius));
    EXPECT_NEAR(m.radial(p), R - kRadius, 1e-5);
    EXPECT_NEAR(m.side(p), Real(0.45), 1e-5);  // along the axis as predicted
  }
  {
    const Vec3 x = level + (R + Real(0.2)) * across;  // outside
    Vec3 p = level + (R - Real(0.1)) * across;
    EXPECT_TRUE(gateOpenLeaflets(m, length, x, p, kRadius));
    EXPECT_NEAR(m.radial(p), R + kRadius, 1e-5);
  }
  {
    const Vec3 x = level;  // on the axis, well clear
    Vec3 p = level + Real(0.1) * across;
    EXPECT_FALSE(gateOpenLeaflets(m, length, x, p, kRadius));
    EXPECT_EQ(p, level + Real(0.1) * across);
  }
  for (const Real along : {Real(-0.1), length + Real(0.05)}) {  // above the disc, beyond the tips
    const Vec3 x = m.centre + along * down + (R - Real(0.2)) * across;
    Vec3 p = m.centre + along * down + R * across;
    EXPECT_FALSE(gateOpenLeaflets(m, length, x, p, kRadius));
    EXPECT_EQ(p, m.centre + along * down + R * across);
  }
}

// The valves hang the leaflets only while the mitral valve is open: closed, it is the disc.
TEST(Valves, LeafletsHangOnlyFromTheOpenMitralValve) {
  FlowPath withLeaflets = path();
  withLeaflets.mitralLeafletLength = Real(0.8);
  const Orifice& m = withLeaflets.mitral;
  pbd::Particles particles;
  const Vec3 level = m.centre + Real(0.4) * m.forward;
  particles.add(level + (m.radius - Real(0.2)) * Vec3::UnitZ(), 1, pbd::ParticleKind::Fluid);
  const Vec3 outward = level + m.radius * Vec3::UnitZ();
  Valves v(withLeaflets, ValveMode::Timing, true, kRadius);
  v.decide(Phase::Diastole, {});  // mitral open
  particles.predicted = {outward};
  v.gateParticles(particles, 0);
  EXPECT_NEAR(m.radial(particles.predicted[0]), m.radius - kRadius, 1e-5);
  v.decide(Phase::Systole, {});  // mitral closed: the disc holds, the tube is gone
  particles.predicted = {outward};
  v.gateParticles(particles, 0);
  EXPECT_EQ(particles.predicted[0], outward);
  // Without leaflets the open valve touches nothing.
  Valves bare = valves(ValveMode::Timing);
  bare.decide(Phase::Diastole, {});
  bare.gateParticles(particles, 0);
  EXPECT_EQ(particles.predicted[0], outward);
}

// A wall vertex, then three blood particles: one crossing the mitral disc downward, one
// crossing the aortic disc upward, one in the middle of the cavity.
struct Crossers {
  pbd::Particles particles;
  Index first = 0;
  Crossers() {
    const Vec3 up = Vec3::UnitY();
    const Vec3 m = path().mitral.centre, a = path().aortic.centre;
    particles.add(m + Real(0.05) * up, 0, pbd::ParticleKind::Tissue);  // inside the mitral disc too
    first = particles.add(m + Real(0.1) * up, 1, pbd::ParticleKind::Fluid);
    particles.add(a - Real(0.1) * up, 1, pbd::ParticleKind::Fluid);
    particles.add(Vec3(0, -2, 0), 1, pbd::ParticleKind::Fluid);
    particles.predicted = {m - Real(0.1) * up, m - Real(0.1) * up, a + Real(0.1) * up,
                           Vec3(0, Real(-2.1), 0)};
  }
};

TEST(Valves, GateParticlesHoldsOnlyTheBloodAtClosedValves) {
  const Orifice& m = path().mitral;
  const Orifice& a = path().aortic;
  {
    Crossers c;
    Valves v = valves(ValveMode::Timing);
    v.decide(Phase::Systole, {});  // mitral closed, aortic open
    v.gateParticles(c.particles, c.first);
    EXPECT_EQ(c.particles.predicted[0], m.centre - Real(0.1) * Vec3::UnitY());  // the wall is not blood
    EXPECT_NEAR(m.side(c.particles.predicted[1]), -kRadius, 1e-6);
    EXPECT_GT(a.side(c.particles.predicted[2]), 0);  // through the open aortic valve
    EXPECT_EQ(c.particles.predicted[3], Vec3(0, Real(-2.1), 0));
  }
  {
    Crossers c;
    Valves v = valves(ValveMode::Timing);
    v.decide(Phase::Diastole, {});  // mitral open, aortic closed
    v.gateParticles(c.particles, c.first);
    EXPECT_GT(m.side(c.particles.predicted[1]), 0);
    EXPECT_NEAR(a.side(c.particles.predicted[2]), -kRadius, 1e-6);
  }
}

TEST(Valves, OpenValvesLeaveEveryPointUntouched) {
  Crossers c;
  const std::vector<Vec3> before = c.particles.predicted;
  Valves v = valves(ValveMode::Open);
  v.decide(Phase::Systole, {});
  v.gateParticles(c.particles, c.first);
  EXPECT_EQ(c.particles.predicted, before);
  std::vector<Vec3> points(before.begin() + 1, before.end());
  const std::vector<Index> ids = {1, 2, 3};
  v.gatePoints(c.particles, points, ids);
  EXPECT_EQ(points, std::vector<Vec3>(before.begin() + 1, before.end()));
}

// The working points are in the solver's own order: points[k] belongs to particle ids[k], and
// its start side is that particle's position, not the k-th particle's.
TEST(Valves, GatePointsUsesThePointsOwnParticle) {
  Crossers c;
  const Orifice& m = path().mitral;
  Valves v = valves(ValveMode::Pressure);
  v.decide(Phase::Systole, {});  // both closed
  // Particle 3 (in the cavity) and particle 1 (above the mitral disc), both predicted more
  // than a radius below the mitral disc.
  const Vec3 below = m.centre - Real(0.2) * Vec3::UnitY();
  std::vector<Vec3> points = {below, below};
  const std::vector<Index> ids = {3, 1};
  v.gatePoints(c.particles, points, ids);
  EXPECT_EQ(points[0], below);                                                // came from below: stays
  EXPECT_NEAR(m.side(points[1]), -kRadius, 1e-6);                             // came from above: held above
  EXPECT_EQ(c.particles.predicted[1], m.centre - Real(0.1) * Vec3::UnitY());  // the particles untouched
}

}  // namespace
}  // namespace hs::cardiac
