// The blood's set-up from a scenario: where the particles start (lattice counts, a partial
// fill as a pool at the bottom, the inflow vessel inside the heart model) and the clear errors
// for starts that cannot be made; the fluid parameters that follow from the physical ones
// (m = rho0 d^3, XSPH c = gamma m / rho0, nu = mu / rho0, eps relative to a particle at rest);
// and the solver's refusals (explicit viscosity too stiff for dt, particles overlapping at rest).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "cardiac/anatomy/lv_model.h"
#include "cardiac/blood.h"
#include "pbd/core/tet_geometry.h"
#include "thrown_message.h"

namespace hs::cardiac {
namespace {

using hs::testing::thrownMessage;
using pbd::Real;

// A 5 x 3 x 2 cell block at spacing 0.1 m, in a container that holds it, no heart.
Scenario blockScenario() {
  Scenario s;
  s.heart = false;
  s.blood.enabled = true;
  s.blood.spacing = Real(0.1);
  s.blood.radius = Real(0.05);
  s.blood.supportRadius = Real(0.2);
  s.blood.blockMin = Vec3(0, 0, 0);
  s.blood.blockMax = Vec3(Real(0.5), Real(0.3), Real(0.2));
  s.blood.particles = 0;
  s.container.enabled = true;
  s.container.min = Vec3(-1, -1, -1);
  s.container.max = Vec3(1, 1, 1);
  return s;
}

TEST(BloodStart, FillsEveryCellOfTheBlockOnce) {
  const Scenario s = blockScenario();
  const std::vector<Vec3> x = bloodStartPositions(s);
  ASSERT_EQ(x.size(), 5u * 3u * 2u);
  const Real d = s.blood.spacing;
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      EXPECT_GT(x[i][a], s.blood.blockMin[a]);
      EXPECT_LT(x[i][a], s.blood.blockMax[a]);
    }
    // One particle per cell: none closer than a spacing to another.
    for (std::size_t j = 0; j < i; ++j) EXPECT_GE((x[i] - x[j]).norm(), d * Real(0.999));
  }
}

TEST(BloodStart, APartialFillIsAPoolAtTheBottom) {
  Scenario s = blockScenario();
  const std::vector<Vec3> all = bloodStartPositions(s);
  s.blood.particles = 13;  // one full bottom layer (5 x 2 = 10) and part of the next
  const std::vector<Vec3> x = bloodStartPositions(s);
  ASSERT_EQ(x.size(), 13u);
  EXPECT_TRUE(std::is_sorted(x.begin(), x.end(), [](const Vec3& p, const Vec3& q) { return p.y() < q.y(); }));
  // No site left empty lies lower than a site taken.
  const Real highestTaken = x.back().y();
  std::size_t below = 0;
  for (const Vec3& p : all) below += p.y() < highestTaken ? 1 : 0;
  EXPECT_EQ(below, 10u);
  EXPECT_EQ(std::count_if(x.begin(), x.end(), [&](const Vec3& p) { return p.y() < highestTaken; }), 10);
}

TEST(BloodStart, TooFewSitesIsAClearError) {
  Scenario s = blockScenario();
  s.blood.particles = 31;  // the block holds 30
  const std::string message = thrownMessage<std::invalid_argument>([&] { bloodStartPositions(s); });
  EXPECT_NE(message.find("blood.particles"), std::string::npos) << message;
  EXPECT_NE(message.find("holds 30 particles"), std::string::npos) << message;
  EXPECT_NE(message.find("enlarge blood.block_max"), std::string::npos) << message;
  s.blood.particles = 30;
  EXPECT_EQ(bloodStartPositions(s).size(), 30u);
}

TEST(BloodStart, BlockOutsideTheContainerIsAClearError) {
  Scenario s = blockScenario();
  s.container.max = Vec3(1, Real(0.25), 1);  // the block reaches y = 0.3
  const std::string message = thrownMessage<std::invalid_argument>([&] { bloodStartPositions(s); });
  EXPECT_NE(message.find("blood.block_min"), std::string::npos) << message;
  EXPECT_NE(message.find("must lie inside the container"), std::string::npos) << message;
  s.container.enabled = false;  // no container: nothing to lie inside
  EXPECT_EQ(bloodStartPositions(s).size(), 30u);
}

TEST(BloodStart, ChamberAndVesselNeedAHeart) {
  Scenario s = blockScenario();
  s.blood.start = BloodSettings::Start::Chamber;
  EXPECT_NE(thrownMessage<std::invalid_argument>([&] { bloodStartPositions(s); }).find("needs a heart"),
            std::string::npos);
  s.blood.start = BloodSettings::Start::Vessel;
  s.heart = true;  // a heart, but no model to find its vessel in
  EXPECT_NE(thrownMessage<std::invalid_argument>([&] { bloodStartPositions(s, nullptr); }).find("needs a heart"),
            std::string::npos);
}

TEST(BloodStart, VesselStartFillsTheInflowVesselFromItsBottomInsideTheModel) {
  Scenario s;  // the thesis-scale heart
  s.blood.enabled = true;
  s.blood.start = BloodSettings::Start::Vessel;
  s.blood.particles = 120;  // about three layers of the lumen
  const LvModel model = buildLvModel(s.geometry);
  const std::vector<Vec3> x = bloodStartPositions(s, &model);
  ASSERT_EQ(x.size(), 120u);
  Vec3 ring = Vec3::Zero();
  for (Index v : model.mitralRing) ring += model.mesh.vertices[v];
  ring /= Real(model.mitralRing.size());
  const Real d = s.blood.spacing;
  for (std::size_t i = 0; i < x.size(); ++i) {
    // In the lumen, a spacing in from the vessel wall, above the base plane.
    const Real radial = std::hypot(x[i].x() - ring.x(), x[i].z() - ring.z());
    EXPECT_LE(radial, s.geometry.mitralRadius - d + Real(1e-6)) << "particle " << i;
    EXPECT_GE(x[i].y(), ring.y()) << "particle " << i;
    EXPECT_LE(x[i].y(), ring.y() + s.geometry.baseThickness + s.geometry.inflowVesselLength);
    if (i > 0) {
      EXPECT_GE(x[i].y(), x[i - 1].y()) << "from the bottom up";
    }
    // Not inside the wall's material.
    for (const pbd::Tet& t : model.mesh.tets)
      ASSERT_FALSE(pbd::isPointInTet(pbd::tetPoints(model.mesh.vertices, t), x[i])) << "particle " << i;
  }
}

TEST(BloodFluid, ParticleMassIsRestDensityTimesSpacingCubed) {
  BloodSettings b;
  b.restDensity = 1060;  // blood
  b.spacing = Real(0.002);
  b.supportRadius = Real(0.004);
  const pbd::FluidSettings f = bloodFluidSettings(b);
  // One particle per lattice cell at rest: 1060 kg/m^3 x (2 mm)^3 = 8.48 mg.
  EXPECT_NEAR(double(f.particleMass), 8.48e-6, 8.48e-6 * 1e-5);
  EXPECT_EQ(f.restDensity, b.restDensity);
  EXPECT_EQ(f.supportRadius, b.supportRadius);
}

TEST(BloodFluid, ViscositiesFollowFromThePhysicalOnes) {
  BloodSettings b;
  b.restDensity = 1060;
  b.spacing = Real(0.002);
  b.supportRadius = Real(0.004);
  b.viscosity = Real(0.0035);  // Pa s, blood
  b.xsph = Real(0.25);
  const pbd::FluidSettings f = bloodFluidSettings(b);
  // XSPH c = gamma m / rho0 = gamma d^3 (thesis eq. 4.11): below m/rho0, the stability bound.
  EXPECT_NEAR(double(f.xsphViscosity), 0.25 * 8e-9, 8e-9 * 1e-5);
  EXPECT_LT(f.xsphViscosity, f.particleMass / f.restDensity);
  // nu = mu / rho0: 3.3e-6 m^2/s for blood.
  EXPECT_NEAR(double(f.kinematicViscosity), 0.0035 / 1060, 1e-6 * 0.0035 / 1060);
}

TEST(BloodFluid, EpsilonIsRelativeToAParticleAtRest) {
  BloodSettings b;
  b.spacing = Real(0.16);
  b.supportRadius = Real(0.32);
  b.relaxation = Real(0.1);
  const double eps = double(bloodFluidSettings(b).relaxation);
  EXPECT_GT(eps, 0);
  // Twice the relaxation, twice eps.
  b.relaxation = Real(0.2);
  EXPECT_NEAR(double(bloodFluidSettings(b).relaxation), 2 * eps, 2 * eps * 1e-5);
  // sum |grad C|^2 is in 1/m^2: the same lattice at half the size has four times eps, so the
  // relaxation means the same at any scale.
  b.relaxation = Real(0.1);
  b.spacing = Real(0.08);
  b.supportRadius = Real(0.16);
  EXPECT_NEAR(double(bloodFluidSettings(b).relaxation), 4 * eps, 4 * eps * 1e-4);
}

TEST(BloodFluid, CollisionRadiusOnlyWithParticleCollision) {
  BloodSettings b;
  b.radius = Real(0.07);
  b.particleCollision = false;
  EXPECT_EQ(bloodFluidSettings(b).collisionRadius, 0);
  b.particleCollision = true;
  EXPECT_EQ(bloodFluidSettings(b).collisionRadius, Real(0.07));
}

TEST(BloodSolver, ContainerWallsArePlanesOrAMesh) {
  Scenario s = blockScenario();
  const pbd::FluidStepSettings planes = bloodSolverSettings(s);
  EXPECT_EQ(planes.walls.size(), 6u);
  EXPECT_FALSE(planes.mesh);
  s.container.mesh = true;
  const pbd::FluidStepSettings mesh = bloodSolverSettings(s);
  EXPECT_TRUE(mesh.walls.empty());
  EXPECT_TRUE(mesh.mesh);
  EXPECT_EQ(mesh.fluid.particleMass, bloodFluidSettings(s.blood).particleMass);
}

TEST(BloodSolver, ViscosityTooStiffForTheTimeStepIsAClearError) {
  // Explicit viscosity is stable for dt <= 0.125 h^2 / nu (Monaghan 2005, 6.3): with h = 4 mm,
  // rho0 = 1060 and dt = 1 ms, mu may reach 0.125 (0.004)^2 1060 / 0.001 = 2.12 Pa s.
  Scenario s = blockScenario();
  s.simulation.dt = Real(0.001);
  s.blood.spacing = Real(0.002);
  s.blood.radius = Real(0.001);
  s.blood.supportRadius = Real(0.004);
  s.blood.restDensity = 1060;
  s.blood.viscosity = Real(2.0);
  EXPECT_NO_THROW(bloodSolverSettings(s));
  s.blood.viscosity = Real(2.3);
  const std::string message = thrownMessage<std::invalid_argument>([&] { bloodSolverSettings(s); });
  EXPECT_NE(message.find("blood.viscosity"), std::string::npos) << message;
  EXPECT_NE(message.find("too viscous"), std::string::npos) << message;
}

TEST(BloodSolver, ParticlesOverlappingAtRestAreAClearError) {
  Scenario s = blockScenario();  // spacing 0.1 m
  s.blood.particleCollision = true;
  s.blood.radius = Real(0.05);  // two radii = spacing: touching, allowed
  EXPECT_NO_THROW(bloodSolverSettings(s));
  s.blood.radius = Real(0.06);
  const std::string message = thrownMessage<std::invalid_argument>([&] { bloodSolverSettings(s); });
  EXPECT_NE(message.find("blood.radius"), std::string::npos) << message;
  EXPECT_NE(message.find("overlap at rest"), std::string::npos) << message;
  s.blood.particleCollision = false;  // without collisions the radius is only the wall distance
  EXPECT_NO_THROW(bloodSolverSettings(s));
}

}  // namespace
}  // namespace hs::cardiac
