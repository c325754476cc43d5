// The ventricle's blood figures: the kinetic energy against a hand sum over the particles in the
// ventricle (by region, whatever their storage order), and the beat's events read from the
// heart's phase.
#include <gtest/gtest.h>

#include <vector>

#include "cardiac/blood/ventricle_blood.h"

namespace hs::cardiac {
namespace {

using pbd::ParticleKind;
using pbd::Real;
using pbd::Vec3;

TEST(VentricleBlood, KineticEnergyIsTheHandSumOverTheParticlesInTheVentricle) {
  pbd::Particles particles;
  particles.add(Vec3::Zero(), 0, ParticleKind::Tissue);  // a wall vertex: not blood
  const Real mass = Real(0.5);                             // kg
  for (int k = 0; k < 4; ++k) particles.add(Vec3::Zero(), 1 / mass, ParticleKind::Fluid);
  // The particles' own velocities are noise the energy must not read: the smoothed ones count.
  particles.velocity = {Vec3::Zero(), Vec3(9, 9, 9), Vec3(9, 9, 9), Vec3(9, 9, 9), Vec3(9, 9, 9)};
  const std::vector<Vec3> smoothed = {Vec3::Zero(), Vec3(1, 0, 0), Vec3(0, 2, 0), Vec3(0, Real(0.6), Real(0.8)),
                                      Vec3(4, 0, 0)};
  particles.state[4] = pbd::ParticleState::Parked;  // waiting in the loop: not counted
  VentricleBlood blood(particles, 1);
  const std::vector<FlowRegion> regions = {FlowRegion::Ventricle, FlowRegion::InflowVessel, FlowRegion::Ventricle,
                                           FlowRegion::Ventricle};
  const double energy = blood.observe(particles, regions, smoothed, HeartPhase::Filling, HeartPhase::Filling, 0.001);
  // Particles 1 (1 m/s) and 3 (|(0, 0.6, 0.8)| = 1 m/s) are in the ventricle: m (1 + 1) / 2.
  EXPECT_NEAR(energy, 0.5 * double(mass) * (1 + 1), 1e-6);
}

// The cycle's mean is the mean over its steps of the energy, from an end-diastole to the next;
// the filling peak the largest while filling.
TEST(VentricleBlood, CycleMeanAndFillingPeakAreTheHandSumsOverTheSteps) {
  pbd::Particles particles;
  particles.add(Vec3::Zero(), 1 / Real(2), ParticleKind::Fluid);  // 2 kg
  VentricleBlood blood(particles, 0);
  const std::vector<FlowRegion> inside = {FlowRegion::Ventricle};
  using P = HeartPhase;
  auto step = [&](Real speed, P before, P after, double t) {
    return blood.observe(particles, inside, std::vector<Vec3>{Vec3(speed, 0, 0)}, before, after, t);
  };
  step(5, P::Filling, P::Filling, 0.1);                  // before the first end-diastole: no cycle
  step(1, P::Filling, P::IsovolumicContraction, 0.2);    // end-diastole: E = 1 J
  step(2, P::IsovolumicContraction, P::Ejection, 0.3);   // 4 J
  step(0, P::Ejection, P::IsovolumicRelaxation, 0.4);    // 0 J
  step(3, P::IsovolumicRelaxation, P::Filling, 0.5);     // 9 J, filling
  step(1, P::Filling, P::Filling, 0.6);                  // 1 J, filling
  step(2, P::Filling, P::IsovolumicContraction, 0.7);    // the next end-diastole
  ASSERT_EQ(blood.cycles().size(), 1u);
  EXPECT_NEAR(blood.cycles()[0].mean, (1 + 4 + 0 + 9 + 1) / 5.0, 1e-12);
  EXPECT_NEAR(blood.cycles()[0].fillingPeak, 9, 1e-12);
}

// A beat: filling, end-diastole, ejection that empties the new blood, end-systole. The events
// come from the phase; the components and the cycle's energy follow.
TEST(VentricleBlood, TheBeatsEventsComeFromThePhase) {
  pbd::Particles particles;
  for (int k = 0; k < 2; ++k) particles.add(Vec3::Zero(), 1, ParticleKind::Fluid);
  VentricleBlood blood(particles, 0);
  using R = FlowRegion;
  using P = HeartPhase;
  double t = 0;
  const std::vector<Vec3> still(2, Vec3::Zero());
  auto step = [&](R a, R b, P before, P after) {
    blood.observe(particles, std::vector<R>{a, b}, still, before, after, t += 0.1);
  };
  step(R::Ventricle, R::InflowVessel, P::Filling, P::Filling);            // 0 there from the start
  step(R::Ventricle, R::Ventricle, P::Filling, P::IsovolumicContraction);  // 1 entered; end-diastole
  step(R::Ventricle, R::Ventricle, P::IsovolumicContraction, P::Ejection);
  step(R::Ventricle, R::OutflowVessel, P::Ejection, P::IsovolumicRelaxation);  // 1 ejected; end-systole
  ASSERT_EQ(blood.beats().size(), 1u);
  EXPECT_DOUBLE_EQ(blood.beats()[0].shares.direct, 0.5);
  EXPECT_DOUBLE_EQ(blood.beats()[0].shares.residual, 0.5);
  EXPECT_NEAR(blood.beats()[0].endDiastole, 0.2, 1e-12);
  EXPECT_TRUE(blood.cycles().empty()) << "a cycle closes at the next end-diastole";
  step(R::Ventricle, R::InflowVessel, P::IsovolumicRelaxation, P::Filling);
  step(R::Ventricle, R::Ventricle, P::Filling, P::IsovolumicContraction);
  ASSERT_EQ(blood.cycles().size(), 1u);
  EXPECT_NEAR(blood.cycles()[0].start, 0.2, 1e-12);
  EXPECT_NEAR(blood.cycles()[0].end, 0.6, 1e-12);
}

}  // namespace
}  // namespace hs::cardiac
