// The vessels' rest-density sites and the fill measured on them (blood.h, flow_path.h): a disc
// of lumenDiscSites holds about one site per spacing^2 with no two closer than most of a spacing,
// all inside the lumen less a particle radius; vesselFillShare's cell hash gives what a brute
// force over every blood particle gives; and a vessel with a void in it reads less than full.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "cardiac/blood.h"
#include "cardiac/flow_path.h"
#include "cardiac/lv_model.h"

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

// The cell hash against a brute force over every particle, bitwise the same share.
TEST(VesselFillShare, AgreesWithBruteForce) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> u(Real(-0.02), Real(0.02));
  std::vector<Vec3> sites(400), blood(900);
  for (Vec3& s : sites) s = Vec3(u(rng), u(rng), u(rng));
  for (Vec3& b : blood) b = Vec3(u(rng), u(rng), u(rng));
  std::size_t covered = 0;
  for (const Vec3& s : sites) {
    bool found = false;
    for (const Vec3& b : blood) found = found || (b - s).squaredNorm() <= kSpacing * kSpacing;
    covered += found;
  }
  const double brute = double(covered) / double(sites.size());
  EXPECT_EQ(vesselFillShare(sites, blood, kSpacing), brute);
  EXPECT_GT(brute, 0.05);
  EXPECT_LT(brute, 0.95) << "the case must have both covered and uncovered sites";
}

TEST(VesselFillShare, AFullVesselReadsFullAndAVoidLess) {
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
  const LvModel model = buildLvModel(s.geometry);
  const VesselSites sites = vesselSites(s, model);
  ASSERT_FALSE(sites.inflow.empty());
  ASSERT_FALSE(sites.outflow.empty());
  // Blood on the sites themselves fills the vessel; without its upper half, half is empty.
  EXPECT_EQ(vesselFillShare(sites.outflow, sites.outflow, kSpacing), 1.0);
  Real lowest = sites.outflow.front().y(), highest = lowest;
  for (const Vec3& x : sites.outflow) {
    lowest = std::min(lowest, x.y());
    highest = std::max(highest, x.y());
  }
  std::vector<Vec3> lowerHalf;
  for (const Vec3& x : sites.outflow)
    if (x.y() < Real(0.5) * (lowest + highest)) lowerHalf.push_back(x);
  const double half = vesselFillShare(sites.outflow, lowerHalf, kSpacing);
  EXPECT_GT(half, 0.4);
  EXPECT_LT(half, 0.65);
  EXPECT_EQ(vesselFillShare(sites.inflow, {}, kSpacing), 0.0);
}

}  // namespace
}  // namespace hs::cardiac
