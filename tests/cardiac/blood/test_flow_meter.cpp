// The flow meter (flow_meter.h): a particle moved across an orifice disc between begin() and
// measure() is one crossing in its direction; parked blood is not measured; the regions
// share out the active blood; pressures are means; flows are crossings times a particle's
// volume.
#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "cardiac/anatomy/lv_model.h"
#include "cardiac/blood.h"
#include "cardiac/blood/flow_meter.h"
#include "thesis_model.h"

namespace hs::cardiac {
namespace {

const FlowPath& path() { return testing::thesisModel().flowPath; }

const BloodSettings kBlood{};
const Vec3 kUp = Vec3::UnitY();

// A wall vertex first (as in HeartSimulation), then the blood at `blood`.
struct Scene {
  pbd::Particles particles;
  Index first = 0;
  explicit Scene(const std::vector<Vec3>& blood) {
    particles.add(path().mitral.centre + Real(0.1) * kUp, 0, pbd::ParticleKind::Tissue);
    first = Index(particles.size());
    for (const Vec3& x : blood) particles.add(x, 1, pbd::ParticleKind::Fluid);
  }
  // Moves blood particle k (0-based within the blood) to x at the end of the step.
  void move(std::size_t k, const Vec3& x) {
    particles.position[first + k] = particles.predicted[first + k] = x;
  }
};

const std::vector<Real> kNoPressure;

FlowStep measureMove(const std::vector<Vec3>& from, const std::vector<Vec3>& to) {
  Scene s(from);
  FlowMeter meter(path(), kBlood, 0);
  meter.begin(s.particles, s.first);
  for (std::size_t k = 0; k < to.size(); ++k) s.move(k, to[k]);
  meter.measure(s.particles, s.first, kNoPressure, ValveStates{});
  return meter.lastStep();
}

TEST(FlowMeter, OneParticleAcrossTheMitralDiscIsOneForwardCrossing) {
  const Vec3 above = path().mitral.centre + Real(0.1) * kUp, below = path().mitral.centre - Real(0.1) * kUp;
  const FlowStep down = measureMove({above}, {below});
  EXPECT_EQ(down.mitralForward, 1u);
  EXPECT_EQ(down.mitralBackward + down.aorticForward + down.aorticBackward, 0u);
  const FlowStep up = measureMove({below}, {above});
  EXPECT_EQ(up.mitralBackward, 1u);
  EXPECT_EQ(up.mitralForward + up.aorticForward + up.aorticBackward, 0u);
}

TEST(FlowMeter, AcrossTheAorticDiscUpIsForward) {
  const Vec3 below = path().aortic.centre - Real(0.1) * kUp, above = path().aortic.centre + Real(0.1) * kUp;
  const FlowStep out =
      measureMove({below, below + Real(0.2) * Vec3::UnitZ()}, {above, above + Real(0.2) * Vec3::UnitZ()});
  EXPECT_EQ(out.aorticForward, 2u);
  EXPECT_EQ(out.aorticBackward + out.mitralForward + out.mitralBackward, 0u);
  EXPECT_EQ(measureMove({above}, {below}).aorticBackward, 1u);
}

TEST(FlowMeter, NoCrossingWithoutMovingThroughADisc) {
  const Vec3 ventricle(0, -2, 0);
  const FlowStep still = measureMove({ventricle}, {ventricle + Real(0.1) * Vec3::UnitX()});
  EXPECT_EQ(still.mitralForward + still.mitralBackward + still.aorticForward + still.aorticBackward, 0u);
  // Down through the base plate beside the mitral disc: not through the orifice.
  const Vec3 beside = path().mitral.centre + (path().mitral.radius + Real(0.2)) * Vec3::UnitZ();
  const FlowStep plate = measureMove({beside + Real(0.1) * kUp}, {beside - Real(0.1) * kUp});
  EXPECT_EQ(plate.mitralForward, 0u);
}

TEST(FlowMeter, ParkedBloodIsNotMeasured) {
  const Vec3 above = path().mitral.centre + Real(0.1) * kUp, below = path().mitral.centre - Real(0.1) * kUp;
  Scene s({above, above + Real(0.2) * Vec3::UnitZ()});
  FlowMeter meter(path(), kBlood, 0);
  meter.begin(s.particles, s.first);
  s.move(0, below);
  s.move(1, below + Real(0.2) * Vec3::UnitZ());
  s.particles.state[s.first + 1] = pbd::ParticleState::Parked;
  meter.measure(s.particles, s.first, kNoPressure, ValveStates{});
  EXPECT_EQ(meter.lastStep().mitralForward, 1u);
  const auto& count = meter.lastStep().count;
  EXPECT_EQ(std::accumulate(count.begin(), count.end(), std::size_t(0)), 1u);
}

// The Doppler readings (echo_velocities.h): the mean of the smoothed velocity along each disc's
// forward normal over the active blood within one spacing of the disc and inside its rim.
TEST(FlowMeter, DopplerReadsTheSlabsMeanSmoothedVelocityAlongTheNormal) {
  const Orifice& aortic = path().aorticValve();
  const Orifice& mitral = path().mitralValve();
  const Real d = kBlood.spacing;
  const Vec3 side = aortic.forward.unitOrthogonal();
  Scene s({aortic.centre + Real(0.5) * d * aortic.forward,                             // in the slab
           aortic.centre - Real(0.9) * d * aortic.forward + Real(0.5) * aortic.radius * side,  // in
           aortic.centre + Real(1.5) * d * aortic.forward,                             // beyond one spacing
           aortic.centre + Real(1.1) * aortic.radius * side,                           // outside the rim
           aortic.centre,                                                              // parked
           mitral.centre + Real(0.2) * d * mitral.forward});                           // the mitral slab
  s.particles.state[s.first + 4] = pbd::ParticleState::Parked;
  std::vector<Vec3> smoothed(s.particles.size(), Vec3::Zero());
  smoothed[s.first + 0] = Real(1.2) * aortic.forward + Real(5) * side;  // the side component is not read
  smoothed[s.first + 1] = Real(0.8) * aortic.forward;
  smoothed[s.first + 2] = smoothed[s.first + 3] = smoothed[s.first + 4] = Real(40) * aortic.forward;
  smoothed[s.first + 5] = Real(0.7) * mitral.forward;
  // Particles' own velocities are not read.
  for (Vec3& v : s.particles.velocity) v = Vec3::Constant(99);
  FlowMeter meter(path(), kBlood, 0);
  meter.begin(s.particles, s.first);
  meter.measure(s.particles, s.first, kNoPressure, ValveStates{}, 1, smoothed);
  EXPECT_NEAR(meter.lastStep().aorticEcho, (1.2 + 0.8) / 2, 1e-5);
  EXPECT_NEAR(meter.lastStep().mitralEcho, 0.7, 1e-5);
  // Without the smoothed field there is no reading.
  meter.measure(s.particles, s.first, kNoPressure, ValveStates{});
  EXPECT_EQ(meter.lastStep().aorticEcho, 0.0);
  // A stenotic valve's opening (a central disc of a third of the rim): only the blood in it.
  meter.narrowAorticOpening(aortic.radius / 3);
  meter.measure(s.particles, s.first, kNoPressure, ValveStates{}, 1, smoothed);
  EXPECT_NEAR(meter.lastStep().aorticEcho, 1.2, 1e-5);
}

// Blood in known places: 2 in the inflow vessel, 3 in the ventricle, 1 in the outflow vessel,
// 1 outside, 1 parked; the wall vertex is not blood.
struct Regions {
  std::vector<Vec3> at = {path().mitral.centre + Real(1.0) * kUp,
                          path().mitral.centre + Real(1.5) * kUp,
                          Vec3(0, -1, 0),
                          Vec3(0, -2, 0),
                          Vec3(0, -3, 0),
                          path().aortic.centre + Real(1.0) * kUp,
                          Vec3(20, 0, 0),
                          Vec3(0, -1, Real(0.5))};
  // Pa, by particle index: the wall's, then the blood's.
  std::vector<Real> pressure = {999, 10, 30, 100, 200, 600, 70, 5, 12345};
};

// The step measured on Regions, its last particle parked.
FlowStep measureRegions() {
  const Regions r;
  Scene s(r.at);
  s.particles.state[s.first + 7] = pbd::ParticleState::Parked;
  FlowMeter meter(path(), kBlood, 0);
  meter.begin(s.particles, s.first);
  meter.measure(s.particles, s.first, r.pressure, ValveStates{});
  return meter.lastStep();
}

TEST(FlowMeter, RegionCountsShareOutTheActiveBlood) {
  const FlowStep f = measureRegions();
  EXPECT_EQ(f.count[std::size_t(FlowRegion::InflowVessel)], 2u);
  EXPECT_EQ(f.count[std::size_t(FlowRegion::Ventricle)], 3u);
  EXPECT_EQ(f.count[std::size_t(FlowRegion::OutflowVessel)], 1u);
  EXPECT_EQ(f.count[std::size_t(FlowRegion::Outside)], 1u);
  EXPECT_EQ(f.count[std::size_t(FlowRegion::Parked)], 0u);  // the loop's business (recordLoop)
  EXPECT_EQ(std::accumulate(f.count.begin(), f.count.end(), std::size_t(0)), 7u);
}

TEST(FlowMeter, MeanPressurePerRegion) {
  const FlowStep f = measureRegions();
  EXPECT_DOUBLE_EQ(f.pressure[std::size_t(FlowRegion::InflowVessel)], 20);
  EXPECT_DOUBLE_EQ(f.pressure[std::size_t(FlowRegion::Ventricle)], 300);
  EXPECT_DOUBLE_EQ(f.pressure[std::size_t(FlowRegion::OutflowVessel)], 70);
  EXPECT_DOUBLE_EQ(f.pressure[std::size_t(FlowRegion::Outside)], 5);
  EXPECT_DOUBLE_EQ(f.pressure[std::size_t(FlowRegion::Parked)], 0);
}

// The pressures the valves compare: blood just before and just after each disc; the mitral
// valve's upstream side also carries the (unmodelled) atrium's pressure.
TEST(FlowMeter, ValvePressuresAreMeansBesideEachDisc) {
  const Orifice& m = path().mitral;
  const Orifice& a = path().aortic;
  const Real near = Real(0.1), far = Real(1.0);
  const std::vector<Vec3> at = {m.centre + near * kUp, m.centre + near * kUp + Real(0.2) * Vec3::UnitZ(),
                                m.centre - near * kUp, a.centre - near * kUp,
                                a.centre + near * kUp, m.centre + far * kUp,  // too far from the disc
                                a.centre - far * kUp};
  const std::vector<Real> pressure = {0, 400, 600, 300, 800, 100, 1e6, 1e6};
  Scene s(at);
  const double atrial = 5 * kPascalPerMmHg;
  FlowMeter meter(path(), kBlood, atrial);
  meter.begin(s.particles, s.first);
  meter.measure(s.particles, s.first, pressure, ValveStates{});
  const ValvePressures& v = meter.lastStep().valvePressures;
  EXPECT_NEAR(v.mitralUpstream, 500 + atrial, 1e-9);
  EXPECT_NEAR(v.mitralDownstream, 300, 1e-9);
  EXPECT_NEAR(v.aorticUpstream, 800, 1e-9);
  EXPECT_NEAR(v.aorticDownstream, 100, 1e-9);
}

TEST(FlowMeter, FlowsAreCrossingsTimesTheParticleVolume) {
  // One particle carries m / rho0 of blood: the spacing cubed.
  const pbd::FluidSettings fluid = bloodFluidSettings(kBlood);
  FlowMeter meter(path(), kBlood, 0);
  EXPECT_NEAR(meter.particleVolume(), fluid.particleMass / kBlood.restDensity, 1e-9);
  EXPECT_NEAR(meter.particleVolume(), kBlood.spacing * kBlood.spacing * kBlood.spacing, 1e-9);

  const Vec3 dz = Real(0.2) * Vec3::UnitZ();
  const Vec3 mAbove = path().mitral.centre + Real(0.1) * kUp, mBelow = path().mitral.centre - Real(0.1) * kUp;
  const Vec3 aBelow = path().aortic.centre - Real(0.1) * kUp, aAbove = path().aortic.centre + Real(0.1) * kUp;
  Scene s({mAbove, mAbove + dz, mAbove - dz, aAbove});
  meter.begin(s.particles, s.first);
  s.move(0, mBelow);
  s.move(1, mBelow + dz);
  s.move(2, mBelow - dz);
  s.move(3, aBelow);
  meter.measure(s.particles, s.first, kNoPressure, ValveStates{});
  const ValveFlows flows = meter.lastStepFlows();
  const double v = double(meter.particleVolume());
  EXPECT_DOUBLE_EQ(flows.mitralForward, 3 * v);
  EXPECT_DOUBLE_EQ(flows.mitralBackward, 0);
  EXPECT_DOUBLE_EQ(flows.aorticForward, 0);
  EXPECT_DOUBLE_EQ(flows.aorticBackward, v);
}

TEST(FlowMeter, RecordsTheValvesAndTheLoop) {
  const Regions r;
  Scene s(r.at);
  FlowMeter meter(path(), kBlood, 0);
  meter.begin(s.particles, s.first);
  meter.measure(s.particles, s.first, r.pressure, ValveStates{false, true});
  EXPECT_FALSE(meter.lastStep().valves.mitralOpen);
  EXPECT_TRUE(meter.lastStep().valves.aorticOpen);
  const auto before = meter.lastStep().count;
  meter.recordLoop(3, 2, 4);
  const FlowStep& f = meter.lastStep();
  EXPECT_EQ(f.returned, 3u);
  EXPECT_EQ(f.reentered, 2u);
  EXPECT_EQ(f.count[std::size_t(FlowRegion::Parked)], 4u);
  for (FlowRegion region :
       {FlowRegion::InflowVessel, FlowRegion::Ventricle, FlowRegion::OutflowVessel, FlowRegion::Outside})
    EXPECT_EQ(f.count[std::size_t(region)], before[std::size_t(region)]);
}

}  // namespace
}  // namespace hs::cardiac
