// The filling pressure as a body force (filling_force.h): rho0 a L = P_a over the inflow
// vessel's length, applied as v += a dt toward the ventricle to the active blood in the
// inflow vessel and to nothing else.
#include <gtest/gtest.h>

#include <vector>

#include "cardiac/anatomy/lv_model.h"
#include "cardiac/blood/filling_force.h"
#include "thesis_model.h"

namespace hs::cardiac {
namespace {

const LvModel& model() { return testing::thesisModel(); }
const FlowPath& path() { return model().flowPath; }

const BloodSettings kBlood{};
const Vec3 kUp = Vec3::UnitY();
const Vec3 kStartVelocity(Real(0.1), Real(-0.2), Real(0.3));

TEST(FillingForce, AccelerationIsThePressureOverTheColumnsMass) {
  const Real mmHg = 8;
  const FillingForce f(path(), kBlood, mmHg);
  const double pa = double(mmHg) * 133.322;  // 1 mmHg = 133.322 Pa
  const double expected = pa / (double(kBlood.restDensity) * double(path().inflowLength));
  EXPECT_NEAR(double(f.acceleration()), expected, 1e-5 * expected);
  EXPECT_GT(f.acceleration(), 0);
}

// Twice the vessel, half the acceleration: the force per lumen area, rho0 a L, is the
// pressure whatever the vessel's length.
TEST(FillingForce, ForcePerAreaIsThePressureForAnyVesselLength) {
  LvGeometryParams longer;
  longer.inflowVesselLength = 2 * LvGeometryParams{}.inflowVesselLength;
  const LvModel other = buildLvModel(longer);
  const Real mmHg = 5;
  const FillingForce a(path(), kBlood, mmHg), b(other.flowPath, kBlood, mmHg);
  const double pa = double(mmHg) * kPascalPerMmHg;
  EXPECT_NEAR(double(kBlood.restDensity * a.acceleration() * path().inflowLength), pa, 1e-5 * pa);
  EXPECT_NEAR(double(kBlood.restDensity * b.acceleration() * other.flowPath.inflowLength), pa, 1e-5 * pa);
  EXPECT_LT(b.acceleration(), a.acceleration());
}

// A wall vertex in the inflow vessel's lumen, then blood: in the inflow vessel (two), in the
// ventricle, in the outflow vessel, parked in the inflow vessel, outside.
struct Scene {
  pbd::Particles particles;
  Index first = 0;
  Scene() {
    const Vec3 inflow = path().mitral.centre + Real(1.0) * kUp;
    particles.add(inflow, 1, pbd::ParticleKind::Tissue);
    first = Index(particles.size());
    for (const Vec3& x :
         {inflow, Vec3(path().mitral.centre + Real(0.1) * kUp), Vec3(0, -2, 0),
          Vec3(path().aortic.centre + Real(1.0) * kUp), Vec3(inflow + Real(0.3) * kUp), Vec3(10, 10, 10)})
      particles.add(x, 1, pbd::ParticleKind::Fluid);
    particles.state[first + 4] = pbd::ParticleState::Parked;
    for (Vec3& v : particles.velocity) v = kStartVelocity;
  }
};

TEST(FillingForce, PushesOnlyTheActiveBloodInTheInflowVesselTowardTheVentricle) {
  Scene s;
  const std::vector<Vec3> positions = s.particles.position;
  const FillingForce f(path(), kBlood, 10);
  const pbd::StepContext context = pbd::makeStepContext(Real(0.004), Vec3::Zero(), 1);
  f.apply(s.particles, s.first, context);
  const Vec3 pushed = kStartVelocity + f.acceleration() * Real(0.004) * path().mitral.forward;
  EXPECT_LT(pushed.y(), kStartVelocity.y());  // down the vessel, into the ventricle
  const std::vector<bool> inInflow = {false, true, true, false, false, false, false};
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    const Vec3& v = s.particles.velocity[i];
    if (inInflow[i]) {
      EXPECT_LT((v - pushed).norm(), Real(1e-6)) << i;
    } else {
      EXPECT_EQ(v, kStartVelocity) << i;
    }
  }
  EXPECT_EQ(s.particles.position, positions);  // an external force: velocities only
}

TEST(FillingForce, VelocityChangeIsProportionalToTheTimeStep) {
  const FillingForce f(path(), kBlood, 10);
  Scene a, b;
  f.apply(a.particles, a.first, pbd::makeStepContext(Real(0.002), Vec3::Zero(), 1));
  f.apply(b.particles, b.first, pbd::makeStepContext(Real(0.006), Vec3::Zero(), 1));
  const Vec3 da = a.particles.velocity[a.first] - kStartVelocity;
  const Vec3 db = b.particles.velocity[b.first] - kStartVelocity;
  EXPECT_GT(da.norm(), 0);
  EXPECT_LT((db - 3 * da).norm(), Real(1e-5) * db.norm());
}

TEST(FillingForce, ZeroPressureChangesNothing) {
  Scene s;
  const pbd::Particles before = s.particles;
  const FillingForce f(path(), kBlood, 0);
  EXPECT_EQ(f.acceleration(), 0);
  f.apply(s.particles, s.first, pbd::makeStepContext(Real(0.005), Vec3(0, Real(-9.81), 0), 1));
  EXPECT_EQ(s.particles.velocity, before.velocity);
  EXPECT_EQ(s.particles.position, before.position);
}

}  // namespace
}  // namespace hs::cardiac
