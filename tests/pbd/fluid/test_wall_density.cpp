// The density a wall lends the fluid beside it (wall_density.h): its tables against brute-force
// sums over the half-space beyond a plane and against finite differences, the nearest-wall
// search against brute force, and a rest lattice beside a wall that reads at rest density.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <vector>

#include "pbd/fluid/fluid.h"
#include "pbd/fluid/wall_density.h"
#include "pbd/grid/neighbour_grid.h"

namespace hs::pbd {
namespace {

constexpr double kH = 0.0072;  // support radius of the real-size blood (m)

// Midpoint sum of f(r_vec) over the cells of a fine grid beyond the plane z = -d (the particle
// at the origin); cell centres are at half-steps, so no cell straddles the plane when d is a
// multiple of the step.
template <class F>
double sumBeyondPlane(double d, double step, F f) {
  const int n = int(std::ceil(kH / step));
  double sum = 0;
  for (int k = -n; k < n; ++k)
    for (int j = -n; j < n; ++j)
      for (int i = -n; i < n; ++i) {
        const Eigen::Vector3d r((i + 0.5) * step, (j + 0.5) * step, (k + 0.5) * step);
        if (r.z() < -d) sum += f(r) * step * step * step;
      }
  return sum;
}

TEST(WallDensityTable, DensityIsThePoly6KernelBeyondThePlane) {
  const SphKernels kernels = makeSphKernels(Real(kH));
  const WallDensityTable table(kernels);
  EXPECT_NEAR(table.density(0), 0.5, 1e-4) << "half of a normalised kernel lies beyond a plane through the particle";
  const double step = kH / 60;
  for (double share : {0.0, 0.25, 0.5, 0.75}) {
    const double d = share * kH;
    const double brute = sumBeyondPlane(d, step, [&](const Eigen::Vector3d& r) {
      return double(poly6(kernels, Real(r.squaredNorm())));
    });
    EXPECT_NEAR(table.density(Real(d)), brute, 2e-3) << "d = " << share << " h";
  }
  EXPECT_EQ(table.density(Real(kH)), 0);
  EXPECT_EQ(table.density(Real(2 * kH)), 0);
}

TEST(WallDensityTable, GradientIsTheSpikyGradientSummedBeyondThePlane) {
  const SphKernels kernels = makeSphKernels(Real(kH));
  const WallDensityTable table(kernels);
  const double step = kH / 60;
  for (double share : {0.0, 0.25, 0.5, 0.75}) {
    const double d = share * kH;
    // grad_i of W(p_i - q) summed over q beyond: points at the wall (-z); G is its length.
    const double brute = -sumBeyondPlane(d, step, [&](const Eigen::Vector3d& r) {
      const Vec3 rij = -r.cast<Real>();  // p_i - q with p_i at the origin
      return double(spikyGradient(kernels, rij, rij.norm()).z());
    });
    EXPECT_NEAR(table.gradient(Real(d)), brute, 2e-3 * table.gradient(0)) << "d = " << share << " h";
  }
}

// G(d) is the slope of the spiky kernel's share beyond the plane, S(d) = int_d^h W(r) 2 pi r (r - d) dr:
// moving the particle toward the wall raises S, so G = -dS/dd. Checked by central differences.
TEST(WallDensityTable, GradientMatchesFiniteDifferencesOfTheSpikyShare) {
  const SphKernels kernels = makeSphKernels(Real(kH));
  const WallDensityTable table(kernels, 2048);
  auto share = [&](double d) {
    const int n = 4000;
    const double dr = (kH - d) / n;
    double sum = 0;
    for (int k = 0; k < n; ++k) {
      const double r = d + (k + 0.5) * dr;
      sum += double(spiky(kernels, Real(r))) * 2 * std::numbers::pi * r * (r - d) * dr;
    }
    return sum;
  };
  for (double s : {0.1, 0.3, 0.5, 0.7, 0.9}) {
    const double d = s * kH, eps = 1e-3 * kH;
    const double slope = -(share(d + eps) - share(d - eps)) / (2 * eps);
    EXPECT_NEAR(table.gradient(Real(d)), slope, 2e-3 * table.gradient(0)) << "d = " << s << " h";
  }
}

// A closed box of 12 triangles (edge 2 cm) and points in and around it.
struct Box {
  std::vector<Vec3> x;
  std::vector<Triangle> faces;
};

Box boxMesh(Real edge) {
  Box b;
  for (int k = 0; k < 8; ++k) b.x.push_back(edge * Vec3(Real(k & 1), Real((k >> 1) & 1), Real((k >> 2) & 1)));
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    b.faces.push_back({Index(q[0]), Index(q[1]), Index(q[2])});
    b.faces.push_back({Index(q[0]), Index(q[2]), Index(q[3])});
  }
  return b;
}

TEST(FindNearestWalls, GridAgreesWithBruteForceBitwise) {
  const Box box = boxMesh(Real(0.02));
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(Real(-0.01), Real(0.03));
  std::vector<Vec3> points(3000);
  for (Vec3& p : points) p = Vec3(u(rng), u(rng), u(rng));
  points.push_back(Vec3(Real(0.01), Real(0.01), Real(0.01)));  // equally far from all six faces
  for (int threads : {1, 2}) {
    std::vector<WallProximity> found;
    findNearestWalls(box.x, box.faces, points, Real(kH), found, threads);
    ASSERT_EQ(found.size(), points.size());
    int near = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const WallProximity brute = nearestWallBruteForce(box.x, box.faces, points[i], Real(kH));
      EXPECT_EQ(found[i].distance, brute.distance) << "point " << i;
      EXPECT_EQ(found[i].normal, brute.normal) << "point " << i;
      near += brute.normal.squaredNorm() > 0;
    }
    EXPECT_GT(near, 1000) << "the test must exercise points near the walls";
  }
}

// A grid kept between calls and updated as the surface moves (as the fluid solver keeps it
// step after step) answers as the brute force does on the surface where it is now.
TEST(FindNearestWalls, AKeptGridFollowsAMovingSurface) {
  Box box = boxMesh(Real(0.02));
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> u(Real(-0.01), Real(0.03));
  std::uniform_real_distribution<Real> wobble(Real(-0.004), Real(0.004));
  std::vector<Vec3> points(1500);
  for (Vec3& p : points) p = Vec3(u(rng), u(rng), u(rng));
  WallTriangleGrid grid;
  for (int step = 0; step < 4; ++step) {
    for (Vec3& v : box.x) v += Vec3(wobble(rng), wobble(rng), wobble(rng));
    grid.update(box.x, box.faces, Real(kH), 2);
    std::vector<WallProximity> found;
    findNearestWalls(grid, box.x, box.faces, points, found, 2);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const WallProximity brute = nearestWallBruteForce(box.x, box.faces, points[i], Real(kH));
      ASSERT_EQ(found[i].distance, brute.distance) << "step " << step << ", point " << i;
      ASSERT_EQ(found[i].normal, brute.normal) << "step " << step << ", point " << i;
    }
  }
}

TEST(FindNearestWalls, NoTrianglesMeansNoWall) {
  std::vector<WallProximity> found;
  const std::vector<Vec3> points{Vec3::Zero()};
  findNearestWalls({}, {}, points, Real(kH), found, 1);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].normal, Vec3::Zero());
}

// Particles `x` of the real-size blood (spacing 3.6 mm, h = 2 d) on a floor z = 0: the solver's
// inputs and each particle's nearest wall.
struct OnAFloor {
  static constexpr Real d = Real(0.0036), h = 2 * d, rho0 = 1060;
  std::vector<Vec3> x;
  FluidSettings settings;
  SphKernels kernels = makeSphKernels(h);
  NeighbourLists lists;
  std::vector<Index> all;
  WallDensityTable table{kernels};
  std::vector<WallProximity> proximity;
  WallDensityInput walls;

  explicit OnAFloor(std::vector<Vec3> particles) : x(std::move(particles)) {
    settings.restDensity = rho0;
    settings.particleMass = particleMassFor(rho0, d);
    settings.supportRadius = h;
    NeighbourGrid grid;
    grid.build(x, h);
    grid.buildNeighbourLists(x, h, lists);
    all.resize(x.size());
    std::iota(all.begin(), all.end(), Index(0));
    const std::vector<Vec3> floor{Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0)};
    const std::vector<Triangle> faces{{0, 1, 2}, {0, 2, 3}};
    findNearestWalls(floor, faces, x, h, proximity, 1);
    walls = {&table, &proximity, &x};
  }
};

// A rest lattice on a floor (its first layer half a spacing above z = 0): without the wall the
// first layers read under-dense; with it, at rest density, so the unilateral constraint holds
// them as firmly as the interior.
TEST(WallDensity, RestLatticeOnAFloorReadsAtRestDensity) {
  const Real d = OnAFloor::d;
  std::vector<Vec3> lattice;
  const int n = 12, layers = 6;
  for (int k = 0; k < layers; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) lattice.push_back(d * Vec3(Real(i), Real(j), Real(k) + Real(0.5)));
  const OnAFloor f(lattice);
  std::vector<Real> bare, lent, lambda;
  computeLambdas(f.x, f.lists, f.all, f.kernels, f.settings, bare, lambda, 1);
  computeLambdas(f.x, f.lists, f.all, f.kernels, f.settings, lent, lambda, 1, nullptr, &f.walls);
  // A column in the middle, away from the lattice's sides: its bottom particle and the one
  // above it.
  const Index bottom = Index((0 * n + n / 2) * n + n / 2), second = Index((1 * n + n / 2) * n + n / 2);
  const Index deep = Index((4 * n + n / 2) * n + n / 2);
  EXPECT_LT(bare[bottom], Real(0.85) * bare[deep]) << "without the wall the bottom layer misses its support beyond";
  EXPECT_NEAR(lent[bottom], lent[deep], Real(0.03) * lent[deep]);
  EXPECT_NEAR(lent[second], lent[deep], Real(0.03) * lent[deep]);
  EXPECT_EQ(lent[deep], bare[deep]) << "a wall beyond the support lends nothing";
}

// The wall's share pushes particles squeezed against it off it, along its normal: against the
// same solve without the wall, the bottom particle of a compressed slab reads denser and is
// moved up (its neighbours above still push it down; the wall contact keeps it out).
TEST(WallDensity, CompressedParticleAtAWallIsPushedOff) {
  const Real d = OnAFloor::d;
  std::vector<Vec3> slab;
  for (int j = -2; j <= 2; ++j)
    for (int i = -2; i <= 2; ++i)
      for (int k = 0; k < 3; ++k) slab.push_back(Real(0.8) * d * Vec3(Real(i), Real(j), Real(k) + Real(0.5)));
  const OnAFloor f(slab);
  const std::vector<Vec3>& x = f.x;
  std::vector<Real> rho, lambda, rhoBare, lambdaBare;
  std::vector<Vec3> dp, dpBare;
  computeLambdas(x, f.lists, f.all, f.kernels, f.settings, rho, lambda, 1, nullptr, &f.walls);
  computeDensityCorrections(x, f.lists, f.all, f.kernels, f.settings, lambda, dp, 1, nullptr, &f.walls);
  computeLambdas(x, f.lists, f.all, f.kernels, f.settings, rhoBare, lambdaBare, 1);
  computeDensityCorrections(x, f.lists, f.all, f.kernels, f.settings, lambdaBare, dpBare, 1);
  const Index centreBottom = Index(((2 * 5) + 2) * 3 + 0);
  ASSERT_NEAR(x[centreBottom].x(), 0, 1e-9);
  ASSERT_NEAR(x[centreBottom].y(), 0, 1e-9);
  EXPECT_GT(rho[centreBottom], rhoBare[centreBottom]);
  EXPECT_LT(lambda[centreBottom], lambdaBare[centreBottom]) << "more compressed with the wall's share";
  EXPECT_GT(dp[centreBottom].z(), dpBare[centreBottom].z()) << "pushed off the floor";
  EXPECT_NEAR(dp[centreBottom].x(), 0, 1e-7);
  EXPECT_NEAR(dp[centreBottom].y(), 0, 1e-7);
}

}  // namespace
}  // namespace hs::pbd
