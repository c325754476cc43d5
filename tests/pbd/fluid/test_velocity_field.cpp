// The smoothed velocity field (velocity_field.h): a constant field reproduced to rounding
// everywhere (the Shepard denominator), a linear field reproduced in the interior of a lattice,
// white noise damped by the kernel's effective neighbour count, the lists against every pair,
// the same bits on 1 and 2 threads, and the solver's by-particle wrapper.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "pbd/fluid/fluid_setup.h"
#include "pbd/fluid/fluid_solver.h"
#include "pbd/fluid/velocity_field.h"

namespace hs::pbd {
namespace {

constexpr Real kSpacing = Real(0.0036);  // normal's blood spacing (m)
constexpr Real kSupport = 2 * kSpacing;  // and its support radius h = 2 d
constexpr Real kEps = std::numeric_limits<Real>::epsilon();

struct Cloud {
  std::vector<Vec3> x;
  std::vector<int> depth;  // lattice steps to the nearest face
};

// An n^3 lattice of spacing kSpacing, each point moved by up to `jitter` spacings per axis.
Cloud lattice(int n, Real jitter = 0, unsigned seed = 1) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-jitter, jitter);
  Cloud c;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        c.x.push_back(kSpacing * Vec3(Real(i) + u(rng), Real(j) + u(rng), Real(k) + u(rng)));
        c.depth.push_back(std::min({i, j, k, n - 1 - i, n - 1 - j, n - 1 - k}));
      }
  return c;
}

NeighbourLists listsFor(const std::vector<Vec3>& x, int threads = 1) {
  NeighbourGridSettings gs;
  gs.threads = threads;
  NeighbourGrid grid(gs);
  grid.build(x, kSupport);
  NeighbourLists lists;
  grid.buildNeighbourLists(x, kSupport, lists);
  return lists;
}

std::vector<Index> allOf(std::size_t n) {
  std::vector<Index> s(n);
  std::iota(s.begin(), s.end(), Index(0));
  return s;
}

std::vector<Vec3> smooth(const std::vector<Vec3>& x, const std::vector<Vec3>& v, const std::vector<Real>& volume,
                         int threads = 1) {
  std::vector<Vec3> out;
  shepardAverage(x, v, volume, listsFor(x, threads), allOf(x.size()), makeSphKernels(kSupport), out, threads);
  return out;
}

TEST(VelocityField, ConstantFieldIsReproducedToRoundingEverywhere) {
  // Boundary particles lack half their neighbours: without the Shepard denominator they would
  // read about half the speed.
  const Cloud c = lattice(8, Real(0.2));
  const Vec3 u(Real(1.3), Real(-0.4), Real(2.1));
  const std::vector<Vec3> out = smooth(c.x, std::vector<Vec3>(c.x.size(), u), std::vector<Real>(c.x.size(), 1));
  // Rounding of two sums of at most ~40 terms each: well inside 64 eps of the value.
  for (const Vec3& v : out) EXPECT_LE((v - u).norm(), 64 * kEps * u.norm());
}

TEST(VelocityField, LinearFieldIsReproducedInTheInteriorOfALattice) {
  // v = A x + b. Where the neighbourhood is whole and symmetric the weighted mean of x_j is x_i,
  // so v~_i = v(x_i) up to rounding; at a face it is not (one-sided neighbourhood: v~ lags by
  // A times the centroid's shift, up to ~h/2).
  const Cloud c = lattice(9);
  Eigen::Matrix<Real, 3, 3> a;
  a << 10, -3, 2, 4, 7, -5, 1, 2, 30;  // 1/s: shear rates of a jet's edge
  const Vec3 b(Real(0.5), Real(-1), Real(0.2));
  std::vector<Vec3> v;
  for (const Vec3& x : c.x) v.push_back(a * x + b);
  const std::vector<Vec3> out = smooth(c.x, v, std::vector<Real>(c.x.size(), 1));
  const Real scale = (a * c.x.back()).norm() + b.norm();
  Real interiorError = 0, faceError = 0;
  for (std::size_t i = 0; i < c.x.size(); ++i) {
    const Real e = (out[i] - v[i]).norm();
    if (c.depth[i] >= 2) interiorError = std::max(interiorError, e);  // h = 2 d: whole at depth 2
    if (c.depth[i] == 0) faceError = std::max(faceError, e);
  }
  EXPECT_LE(interiorError, 64 * kEps * scale);
  // The face's error is real (the test would not see a missing denominator otherwise).
  EXPECT_GT(faceError, Real(1e-3) * a.norm() * kSpacing);
}

TEST(VelocityField, WhiteNoiseVarianceFallsByTheKernelsEffectiveNeighbourCount) {
  // Independent velocities of variance s^2: v~_i = sum w_j v_j / sum w_j has variance
  // s^2 sum w_j^2 / (sum w_j)^2. On the lattice with h = 2 d (26 neighbours, poly6) that is
  // s^2 / 11.8; the test asks at least a factor 8 over the interior.
  const Cloud c = lattice(14);
  std::mt19937 rng(7);
  std::normal_distribution<Real> noise(0, Real(0.5));  // m/s: PBF's particle noise in a heart
  std::vector<Vec3> v;
  for (std::size_t i = 0; i < c.x.size(); ++i) v.emplace_back(noise(rng), noise(rng), noise(rng));
  const std::vector<Vec3> out = smooth(c.x, v, std::vector<Real>(c.x.size(), 1));
  double raw = 0, smoothed = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < c.x.size(); ++i) {
    if (c.depth[i] < 2) continue;
    raw += double(v[i].squaredNorm());
    smoothed += double(out[i].squaredNorm());
    ++n;
  }
  ASSERT_GE(n, 1000u);
  const double factor = raw / smoothed;
  EXPECT_GT(factor, 8.0) << factor;
  EXPECT_LT(factor, 16.0);  // and not a field flattened to nothing by a wrong weight
}

TEST(VelocityField, ListsAgreeWithEveryPair) {
  // Random points (some crowded, some alone), random velocities, some volumes 0 (parked).
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> at(0, 6 * kSpacing), speed(-2, 2), pick(0, 1);
  std::vector<Vec3> x, v;
  std::vector<Real> volume;
  for (int i = 0; i < 600; ++i) {
    x.emplace_back(at(rng), at(rng), at(rng));
    v.emplace_back(speed(rng), speed(rng), speed(rng));
    volume.push_back(pick(rng) < Real(0.1) ? Real(0) : Real(1) + pick(rng));
  }
  x.push_back(Vec3::Constant(100 * kSpacing));  // alone and weightless: keeps its own velocity
  v.emplace_back(1, 2, 3);
  volume.push_back(0);
  const std::vector<Vec3> lists = smooth(x, v, volume);
  const std::vector<Vec3> brute = smoothVelocitiesBruteForce(x, v, volume, makeSphKernels(kSupport));
  ASSERT_EQ(lists.size(), brute.size());
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_LE((lists[i] - brute[i]).norm(), Real(2e-6)) << i;  // m/s: rounding of sums in another order
  EXPECT_EQ(lists.back(), v.back());
}

TEST(VelocityField, SameBitsOnOneAndTwoThreads) {
  const Cloud c = lattice(12, Real(0.3), 5);
  std::mt19937 rng(11);
  std::normal_distribution<Real> noise(0, 1);
  std::vector<Vec3> v;
  for (std::size_t i = 0; i < c.x.size(); ++i) v.emplace_back(noise(rng), noise(rng), noise(rng));
  const std::vector<Real> volume(c.x.size(), 1);
  const std::vector<Vec3> one = smooth(c.x, v, volume, 1), two = smooth(c.x, v, volume, 2);
  for (std::size_t i = 0; i < one.size(); ++i) ASSERT_EQ(one[i], two[i]) << i;
}

TEST(VelocityField, SolverSmoothsByParticleOverItsLastLists) {
  // A block of fluid after one step: every particle given the same velocity reads it back
  // (by particle index), a parked one weighs nothing, and `wanted` limits the work.
  FluidStepSettings settings;
  settings.fluid.supportRadius = kSupport;
  settings.fluid.particleMass = particleMassFor(settings.fluid.restDensity, kSpacing);
  Particles particles;
  for (const Vec3& x : fluidBlock(Vec3::Zero(), Vec3::Constant(8 * kSpacing), kSpacing))
    particles.add(x, Real(1) / settings.fluid.particleMass, ParticleKind::Fluid);
  settings.particleRadius = kSpacing / 2;
  FluidSolver solver(settings);
  std::vector<Vec3> before;
  solver.smoothedVelocities(particles, before, 1);
  EXPECT_TRUE(std::all_of(before.begin(), before.end(), [](const Vec3& v) { return v.isZero(); }));
  solver.step(particles, makeStepContext(Real(0.001), Vec3::Zero(), 1));
  const Vec3 u(0, Real(0.8), 0);
  for (Vec3& v : particles.velocity) v = u;
  particles.velocity[0] = Vec3(50, 0, 0);
  particles.state[0] = ParticleState::Parked;
  std::vector<Vec3> out;
  solver.smoothedVelocities(particles, out, 2);
  ASSERT_EQ(out.size(), particles.size());
  EXPECT_TRUE(out[0].isZero()) << "a parked particle is not evaluated";
  for (std::size_t i = 1; i < out.size(); ++i) EXPECT_LE((out[i] - u).norm(), 64 * kEps) << i;
  std::vector<std::uint8_t> wanted(particles.size(), 0);
  wanted[5] = 1;
  solver.smoothedVelocities(particles, out, 1, wanted);
  EXPECT_LE((out[5] - u).norm(), 64 * kEps);
  EXPECT_TRUE(out[6].isZero());
}

}  // namespace
}  // namespace hs::pbd
