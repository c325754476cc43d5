// The heart's rest-density sites and the vessels' fill measured on them (heart_sites.h,
// flow_path.h): a disc of lumenDiscSites holds about one site per spacing^2 with no two closer
// than most of a spacing, all inside the lumen less a particle radius; the blood colour's cell
// hash gives what a brute force over every particle gives and reads 1 inside blood at rest; a
// vessel full of blood reads full, and one with a void in it less.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "cardiac/anatomy/flow_path.h"
#include "cardiac/anatomy/lv_model.h"
#include "cardiac/heart_sites.h"
#include "pbd/fluid/sph_kernels.h"

namespace hs::cardiac {
namespace {

using pbd::Real;

constexpr Real kSpacing = Real(0.0036), kRadius = Real(0.0018);

TEST(LumenDiscSites, OneSitePerSpacingSquaredInsideTheLumen) {
  for (Real lumen : {Real(0.0125), Real(0.010), Real(0.006)}) {
    SCOPED_TRACE(lumen);
    const Orifice disc{Vec3(Real(0.01), 0, Real(-0.02)), Vec3::UnitY(), lumen};
    const Real reach = lumen - kRadius;
    const std::vector<Vec3> sites = lumenDiscSites(disc, Real(0.005), reach, kSpacing, false);
    // Each site stands for the d x d square around it; the disc to the wall is pi R^2.
    const double perSite = std::numbers::pi * double(lumen) * double(lumen) / double(sites.size());
    EXPECT_NEAR(perSite / double(kSpacing * kSpacing), 1.0, 0.25);
    double closest = 1e9;
    for (std::size_t i = 0; i < sites.size(); ++i) {
      EXPECT_NEAR(sites[i].y(), 0.005, 1e-9);
      EXPECT_LE(disc.radial(sites[i]), reach * (1 + 1e-5));
      for (std::size_t j = i + 1; j < sites.size(); ++j) closest = std::min(closest, double((sites[i] - sites[j]).norm()));
    }
    EXPECT_GT(closest, 0.8 * double(kSpacing)) << "no two sites crowd each other";
  }
}

// The colour's cell grid against a brute force over every particle (the same terms, summed in
// another order: equal to double rounding).
TEST(BloodColour, AgreesWithBruteForce) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> u(Real(-0.02), Real(0.02));
  std::vector<Vec3> sites(300), blood(900);
  for (Vec3& s : sites) s = Vec3(u(rng), u(rng), u(rng));
  for (Vec3& b : blood) b = Vec3(u(rng), u(rng), u(rng));
  const Real h = 2 * kSpacing;
  const std::vector<double> colour = bloodColour(sites, blood, kSpacing, h);
  const pbd::SphKernels kernels = pbd::makeSphKernels(h);
  const double volume = double(kSpacing) * double(kSpacing) * double(kSpacing);
  std::size_t nonzero = 0;
  for (std::size_t s = 0; s < sites.size(); ++s) {
    double sum = 0;
    for (const Vec3& b : blood) sum += double(pbd::poly6(kernels, (b - sites[s]).squaredNorm()));
    EXPECT_NEAR(colour[s], volume * sum, 1e-12 * (1 + volume * sum)) << "site " << s;
    nonzero += colour[s] > 0;
  }
  EXPECT_GT(nonzero, sites.size() / 2) << "the case must have blood near most sites";
}

// Deep inside blood at rest density the colour reads about 1.
TEST(BloodColour, ReadsAboutOneInsideBloodAtRest) {
  std::vector<Vec3> blood;
  for (int i = -6; i <= 6; ++i)
    for (int j = -6; j <= 6; ++j)
      for (int k = -6; k <= 6; ++k) blood.emplace_back(Real(i) * kSpacing, Real(j) * kSpacing, Real(k) * kSpacing);
  const std::vector<double> colour = bloodColour({Vec3::Zero(), Vec3(kRadius, 0, 0)}, blood, kSpacing, 2 * kSpacing);
  EXPECT_NEAR(colour[0], 1.0, 0.05);
  EXPECT_NEAR(colour[1], 1.0, 0.05);
}

Scenario realSizeHeart() {
  Scenario s;
  s.geometry.endoRadius = Real(0.032);
  s.geometry.endoLongAxis = Real(0.06);
  s.geometry.wallThickness = Real(0.01);
  s.geometry.baseThickness = Real(0.004);
  s.geometry.mitralRadius = Real(0.0125);
  s.geometry.aorticRadius = Real(0.010);
  s.geometry.vesselWallThickness = Real(0.002);
  s.geometry.inflowVesselLength = Real(0.03);
  s.geometry.outflowVesselLength = Real(0.03);
  s.blood.spacing = kSpacing;
  s.blood.radius = kRadius;
  s.blood.supportRadius = 2 * kSpacing;
  return s;
}

// Blood on every site fills the vessels; one particle moved away leaves no void; a void a few
// particles across, or the vessel's upper half empty, reads as such.
TEST(VesselFillShare, AFullVesselReadsFullAndAVoidLess) {
  const Scenario s = realSizeHeart();
  const LvModel model = buildLvModel(s.geometry);
  const VesselSites sites = vesselSites(s, model);
  ASSERT_FALSE(sites.inflow.empty());
  ASSERT_FALSE(sites.outflow.empty());
  ASSERT_EQ(sites.outflowFull.size(), sites.outflow.size());
  const std::vector<Vec3> full = heartSites(s, model);
  const Real h = s.blood.supportRadius;
  EXPECT_EQ(vesselFillShare(sites.outflow, sites.outflowFull, full, kSpacing, h), 1.0);
  EXPECT_EQ(vesselFillShare(sites.inflow, sites.inflowFull, full, kSpacing, h), 1.0);

  // The outflow's middle site: without the particle on it, still full; without a ball of 1.5
  // spacings around it, a void.
  Vec3 middle = sites.outflow[sites.outflow.size() / 2];
  std::vector<Vec3> oneGone, ballGone, lowerHalf;
  for (const Vec3& x : full) {
    if ((x - middle).norm() > Real(1e-6)) oneGone.push_back(x);
    if ((x - middle).norm() > Real(1.5) * kSpacing) ballGone.push_back(x);
  }
  EXPECT_EQ(vesselFillShare(sites.outflow, sites.outflowFull, oneGone, kSpacing, h), 1.0);
  EXPECT_LT(vesselFillShare(sites.outflow, sites.outflowFull, ballGone, kSpacing, h), 1.0);

  Real lowest = sites.outflow.front().y(), highest = lowest;
  for (const Vec3& x : sites.outflow) {
    lowest = std::min(lowest, x.y());
    highest = std::max(highest, x.y());
  }
  for (const Vec3& x : full)
    if (x.y() < Real(0.5) * (lowest + highest)) lowerHalf.push_back(x);
  const double half = vesselFillShare(sites.outflow, sites.outflowFull, lowerHalf, kSpacing, h);
  EXPECT_GT(half, 0.4);
  EXPECT_LT(half, 0.65);
  EXPECT_EQ(vesselFillShare(sites.inflow, sites.inflowFull, {}, kSpacing, h), 0.0);
}

// drop() keeps each remaining site with its own colour.
TEST(VesselSites, DropKeepsSitesWithTheirColours) {
  const Scenario s = realSizeHeart();
  const LvModel model = buildLvModel(s.geometry);
  const VesselSites all = vesselSites(s, model);
  VesselSites upper = all;
  const Real cut = Real(0.015);
  upper.drop([&](const Vec3& x) { return x.y() < cut; });
  ASSERT_FALSE(upper.outflow.empty());
  ASSERT_LT(upper.outflow.size(), all.outflow.size());
  for (std::size_t k = 0, j = 0; k < all.outflow.size(); ++k) {
    if (all.outflow[k].y() < cut) continue;
    EXPECT_EQ(upper.outflow[j], all.outflow[k]);
    EXPECT_EQ(upper.outflowFull[j], all.outflowFull[k]);
    ++j;
  }
}

}  // namespace
}  // namespace hs::cardiac
