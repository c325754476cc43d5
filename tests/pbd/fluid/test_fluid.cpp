// Over 400 lines on purpose: one test file per module, its cases sharing the file's set-up helpers.
// Position Based Fluids (fluid.h): particle mass, rest-lattice density at h = 2d and h = 4d,
// compressed-lattice correction direction and one Jacobi iteration, momentum of the
// corrections, XSPH viscosity, and bitwise determinism across thread counts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "pbd/fluid/fluid.h"

namespace hs::pbd {
namespace {

constexpr Real kSpacing = Real(0.16);  // thesis: particle radius 0.08 m, spacing 2 radii
constexpr Real kRho0 = 1000;           // thesis: rest density 1000 kg/m^3

struct Lattice {
  std::vector<Vec3> x;
  int n = 0;
  Real spacing = 0;
  Index at(int i, int j, int k) const { return Index((k * n + j) * n + i); }
  // Distance, in lattice steps, from particle (i,j,k) to the nearest lattice face.
  int depth(Index p) const {
    const int i = int(p) % n, j = (int(p) / n) % n, k = int(p) / (n * n);
    return std::min({i, j, k, n - 1 - i, n - 1 - j, n - 1 - k});
  }
  Vec3 centre() const { return Vec3::Constant(Real(n - 1) * spacing / 2); }
};

Lattice cubicLattice(int n, Real spacing) {
  Lattice l;
  l.n = n;
  l.spacing = spacing;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) l.x.emplace_back(Real(i) * spacing, Real(j) * spacing, Real(k) * spacing);
  return l;
}

NeighbourLists listsFor(const std::vector<Vec3>& x, Real h, int threads = 1) {
  NeighbourGridSettings gs;
  gs.threads = threads;
  NeighbourGrid grid(gs);
  grid.build(x, h);
  NeighbourLists lists;
  grid.buildNeighbourLists(x, h, lists);
  return lists;
}

std::vector<Index> allOf(std::size_t n) {
  std::vector<Index> s(n);
  std::iota(s.begin(), s.end(), Index(0));
  return s;
}

// sum_k |grad_{p_k} C_i|^2 of PBF eq. 8 in double, over all particles (no neighbour lists):
// |(m/rho0) sum_j grad W_ij|^2 + sum_j |(m/rho0) grad W_ij|^2.
double gradientSquaredSum(const std::vector<Vec3>& x, Index i, const SphKernels& kernels,
                          const FluidSettings& s) {
  const double scale = double(s.particleMass) / double(s.restDensity);
  Eigen::Vector3d gi = Eigen::Vector3d::Zero();
  double sumJ = 0;
  for (Index j = 0; j < x.size(); ++j) {
    if (j == i) continue;
    const Vec3 r = x[i] - x[j];
    const Eigen::Vector3d g = scale * spikyGradient(kernels, r, r.norm()).cast<double>();
    gi += g;
    sumJ += g.squaredNorm();
  }
  return gi.squaredNorm() + sumJ;
}

FluidSettings settingsFor(Real h, Real spacing) {
  FluidSettings s;
  s.restDensity = kRho0;
  s.particleMass = particleMassFor(kRho0, spacing);
  s.supportRadius = h;
  // 1/m^2; next to sum |grad C|^2 = 0.37/d^2 = 14.5/m^2 of a full neighbourhood at h = 2d
  // (measured below), so it changes lambda by under 1%.
  s.relaxation = Real(0.1);
  // The papers' bilateral constraint: these tests check PBF's equations as written. The
  // one-sided clamp the solver uses is tested on its own below.
  s.unilateralDensity = false;
  return s;
}

// One Jacobi pass of the density solve: densities, constraints, lambdas, corrections.
struct DensitySolve {
  std::vector<Real> rho, c, lambda;
  std::vector<Vec3> dp;
};

DensitySolve solveDensityOnce(const std::vector<Vec3>& x, const NeighbourLists& lists,
                              const std::vector<Index>& subset, const SphKernels& kernels,
                              const FluidSettings& s) {
  DensitySolve out;
  // computeLambdas computes the densities it uses; C comes from those, so the lambda check
  // below compares like with like (computeDensities sums in another order).
  computeLambdas(x, lists, subset, kernels, s, out.rho, out.lambda);
  computeDensityConstraints(out.rho, subset, s, out.c);
  computeDensityCorrections(x, lists, subset, kernels, s, out.lambda, out.dp);
  return out;
}

TEST(Fluid, ParticleMassIsRestDensityTimesSpacingCubed) {
  // Relative tolerance of a few float ulps: the test also runs in the double build.
  EXPECT_NEAR(double(particleMassFor(1000, Real(0.16))), 4.096, 4.096 * 1e-6);
  EXPECT_NEAR(double(particleMassFor(1060, Real(0.5))), 132.5, 132.5 * 1e-6);
  EXPECT_EQ(particleMassFor(2, 3), Real(54));
}

// Rest lattice at spacing d with mass rho0 d^3: the lattice sum of poly6 approximates its unit
// integral, so particles with a full neighbourhood (at least h from every face) have
// rho ~ rho0. Analytically, h = 2d gives 315/(512 pi) (1 + 6 (3/4)^3 + 12 (1/2)^3 + 8 (1/4)^3)
// = 1.0097 rho0, so the tolerance on |C| is 2% (discretisation error of the lattice sum, not
// rounding). Particles at least 2h deep see only full-neighbourhood neighbours with equal
// lambdas, so by symmetry their correction vanishes.
class FluidRestLattice : public ::testing::TestWithParam<int> {};

TEST_P(FluidRestLattice, InteriorDensityIsRestDensityAndCorrectionVanishes) {
  const int ratio = GetParam();  // h / d
  const Real d = kSpacing;
  const Real h = Real(ratio) * d;
  const Lattice lat = cubicLattice(4 * ratio + 3, d);  // 1 particle layer deeper than 2h on each side
  const FluidSettings s = settingsFor(h, d);
  const SphKernels kernels = makeSphKernels(h);
  const NeighbourLists lists = listsFor(lat.x, h);
  const std::vector<Index> all = allOf(lat.x.size());

  const DensitySolve solve = solveDensityOnce(lat.x, lists, all, kernels, s);
  const std::vector<Real>& rho = solve.rho;
  const std::vector<Real>& c = solve.c;
  const std::vector<Real>& lambda = solve.lambda;
  const std::vector<Vec3>& dp = solve.dp;

  int interior = 0, deep = 0;
  Real maxC = 0, maxDeepDp = 0;
  double minSumSq = 1e30;
  for (Index p = 0; p < lat.x.size(); ++p) {
    if (lat.depth(p) < ratio) continue;
    ++interior;
    maxC = std::max(maxC, std::abs(c[p]));
    EXPECT_NEAR(rho[p], kRho0, Real(0.02) * kRho0) << "particle " << p;
    // lambda = -C/(S + eps) with S = sum_k |grad_{p_k} C|^2 recomputed here by brute force
    // (PBF eq. 8, 11); lambda ~ 0 in the sense that the position change it implies,
    // |lambda| sqrt(S) = |C|/sqrt(S), is below 3% of the spacing (|C| <= 2% and, at h = 2d,
    // sqrt(S) = 0.61/d; at h = 4d C is ~1e-6).
    const double sumSq = gradientSquaredSum(lat.x, p, kernels, s);
    EXPECT_NEAR(double(lambda[p]), -double(c[p]) / (sumSq + double(s.relaxation)),
                1e-4 * std::abs(double(lambda[p])) + 1e-12) << "particle " << p;
    EXPECT_LT(std::abs(double(lambda[p])) * std::sqrt(sumSq), 0.03 * double(d)) << "particle " << p;
    minSumSq = std::min(minSumSq, sumSq);
    if (lat.depth(p) >= 2 * ratio) {
      ++deep;
      maxDeepDp = std::max(maxDeepDp, dp[p].norm());
      EXPECT_LT(dp[p].norm(), Real(1e-4) * d) << "particle " << p;
    }
  }
  EXPECT_GT(deep, 0);
  std::printf("h = %dd: %d interior particles, rho/rho0 - 1 = %.3g (max |C| %.3g), "
              "sum|grad C|^2 d^2 = %.4f, max deep |dp|/d = %.3g\n",
              ratio, interior, double(c[lat.at(lat.n / 2, lat.n / 2, lat.n / 2)]), double(maxC),
              minSumSq * double(d * d), double(maxDeepDp / d));
}

INSTANTIATE_TEST_SUITE_P(SupportOverSpacing, FluidRestLattice, ::testing::Values(2, 4));

// Lattice compressed by 10% (spacing 0.9 d, mass still rho0 d^3): rho ~ rho0/0.729.
TEST(Fluid, CompressedLatticeIsPushedApartAndOneIterationReducesC) {
  const Real d = kSpacing;
  const Real h = 2 * d;
  const Lattice lat = cubicLattice(11, Real(0.9) * d);
  const FluidSettings s = settingsFor(h, d);
  const SphKernels kernels = makeSphKernels(h);
  const std::vector<Index> all = allOf(lat.x.size());
  NeighbourLists lists = listsFor(lat.x, h);

  DensitySolve solve = solveDensityOnce(lat.x, lists, all, kernels, s);
  std::vector<Real>& rho = solve.rho;
  std::vector<Real>& c = solve.c;
  const std::vector<Vec3>& dp = solve.dp;

  // Interior: full neighbourhood (the support 2d spans 2.2 steps of 0.9 d, so 3 layers deep).
  std::vector<Index> interior;
  for (Index p = 0; p < lat.x.size(); ++p)
    if (lat.depth(p) >= 3) interior.push_back(p);
  double meanC0 = 0;
  for (const Index p : interior) {
    EXPECT_GT(c[p], Real(0.2)) << "particle " << p;
    meanC0 += std::abs(double(c[p]));
  }
  meanC0 /= double(interior.size());

  // Every compressed particle (C > 0) away from the centre is pushed outwards.
  const Vec3 centre = lat.centre();
  int outward = 0, checked = 0;
  for (Index p = 0; p < lat.x.size(); ++p) {
    const Vec3 fromCentre = lat.x[p] - centre;
    if (c[p] <= 0 || fromCentre.norm() < Real(0.5) * lat.spacing) continue;
    // Deep particles have equal-lambda neighbourhoods on all sides: dp = 0 up to rounding.
    EXPECT_GT(dp[p].dot(fromCentre), Real(-1e-5) * d * d) << "particle " << p << " C " << c[p];
    if (dp[p].norm() < Real(1e-4) * d) continue;
    ++checked;
    if (dp[p].dot(fromCentre) > 0) ++outward;
    EXPECT_GT(dp[p].dot(fromCentre), Real(0)) << "particle " << p << " C " << c[p];
  }
  EXPECT_GT(checked, 100);

  // One Jacobi iteration: p <- p + dp for all particles, then re-evaluate C.
  std::vector<Vec3> x1 = lat.x;
  for (Index p = 0; p < x1.size(); ++p) x1[p] += dp[p];
  lists = listsFor(x1, h);
  computeDensities(x1, lists, all, kernels, s, rho);
  computeDensityConstraints(rho, all, s, c);
  double meanC1 = 0;
  for (const Index p : interior) meanC1 += std::abs(double(c[p]));
  meanC1 /= double(interior.size());
  // One Jacobi iteration relieves the compression only from the free surface inwards (the
  // deep particles have dp = 0), so the interior mean drops by a small amount.
  EXPECT_LT(meanC1, 0.99 * meanC0);
  std::printf("compressed lattice: %d/%d compressed particles pushed outwards; interior mean |C| %.4f -> %.4f\n",
              outward, checked, meanC0, meanC1);
}

// Pair terms are antisymmetric: (lambda_i + lambda_j) grad W(p_i - p_j) = -(lambda_j + lambda_i)
// grad W(p_j - p_i) exactly, so sum_i dp_i vanishes up to the rounding of the per-particle sums.
TEST(Fluid, CorrectionsConserveMomentum) {
  const Real d = kSpacing;
  const Real h = 2 * d;
  const Lattice lat = cubicLattice(9, Real(0.9) * d);
  std::vector<Vec3> x = lat.x;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  std::vector<Vec3> jittered = x;
  for (auto& p : jittered) p += Vec3(Real(u(rng)), Real(u(rng)), Real(u(rng))) * d;

  for (const auto* cloud : {&x, &jittered}) {
    const FluidSettings s = settingsFor(h, d);
    const SphKernels kernels = makeSphKernels(h);
    const std::vector<Index> all = allOf(cloud->size());
    const NeighbourLists lists = listsFor(*cloud, h);
    std::vector<Real> rho, lambda;
    std::vector<Vec3> dp;
    computeDensities(*cloud, lists, all, kernels, s, rho);
    computeLambdas(*cloud, lists, all, kernels, s, rho, lambda);
    computeDensityCorrections(*cloud, lists, all, kernels, s, lambda, dp);
    Eigen::Vector3d total = Eigen::Vector3d::Zero();
    double magnitude = 0;
    for (const Vec3& v : dp) {
      total += v.cast<double>();
      magnitude += double(v.norm());
    }
    EXPECT_GT(magnitude, 1e-3 * double(d));
    EXPECT_LT(total.norm(), 1e-5 * magnitude) << (cloud == &x ? "lattice" : "jittered");
  }
}

TEST(Fluid, XsphDampsRelativeVelocityAndConservesMomentum) {
  const Real h = Real(0.32);
  FluidSettings s = settingsFor(h, kSpacing);
  s.xsphViscosity = Real(0.01);  // m^3; c W_poly6(0.5 h) = 0.01 * 47.8 * 0.42 ~ 0.2
  const SphKernels kernels = makeSphKernels(h);
  // Pair A inside each other's support, pair B just beyond it.
  const std::vector<Vec3> x{Vec3(0, 0, 0), Vec3(Real(0.5) * h, 0, 0), Vec3(10, 0, 0),
                            Vec3(10 + Real(1.01) * h, 0, 0)};
  const std::vector<Vec3> v{Vec3(1, Real(0.5), 0), Vec3(-1, Real(-0.5), 0), Vec3(2, 0, 1), Vec3(-2, 0, -1)};
  const NeighbourLists lists = listsFor(x, h);
  const std::vector<Index> all = allOf(x.size());
  std::vector<Vec3> vNew;
  applyViscosity(x, v, lists, all, kernels, s, Real(0.005), vNew);

  const Real before = (v[0] - v[1]).norm(), after = (vNew[0] - vNew[1]).norm();
  // Each velocity moves by c W (v_j - v_i), so the relative velocity shrinks by (1 - 2 c W).
  const Real cw = s.xsphViscosity * poly6(kernels, (x[1] - x[0]).squaredNorm());
  EXPECT_LT(after, before);
  EXPECT_NEAR(after, (1 - 2 * cw) * before, Real(1e-5));
  EXPECT_GT((vNew[0] - vNew[1]).dot(v[0] - v[1]), Real(0));  // damped, not reversed
  EXPECT_GT((vNew[0] - v[0]).norm(), Real(1e-4));
  const Vec3 momentum = vNew[0] + vNew[1];
  EXPECT_LT(momentum.norm(), Real(4) * std::numeric_limits<Real>::epsilon());
  EXPECT_EQ(vNew[2], v[2]);
  EXPECT_EQ(vNew[3], v[3]);
  std::printf("XSPH: |v1 - v2| %.6f -> %.6f\n", double(before), double(after));
}

TEST(Fluid, ResultsAreBitwiseIdenticalForOneAndTwoThreads) {
  const Real h = Real(0.32);
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(0, 2.0);
  std::vector<Vec3> x(2000), v(2000);
  for (auto& p : x) p = Vec3(Real(u(rng)), Real(u(rng)), Real(u(rng)));
  for (auto& q : v) q = Vec3(Real(u(rng)), Real(u(rng)), Real(u(rng)));
  FluidSettings s = settingsFor(h, kSpacing);
  s.tensileCorrection = true;
  const SphKernels kernels = makeSphKernels(h);
  const std::vector<Index> all = allOf(x.size());

  struct Out {
    std::vector<Real> rho, lambda;
    std::vector<Vec3> dp, vNew;
  };
  auto run = [&](int threads) {
    Out o;
    const NeighbourLists lists = listsFor(x, h, threads);
    computeDensities(x, lists, all, kernels, s, o.rho, threads);
    computeLambdas(x, lists, all, kernels, s, o.rho, o.lambda, threads);
    computeDensityCorrections(x, lists, all, kernels, s, o.lambda, o.dp, threads);
    applyViscosity(x, v, lists, all, kernels, s, Real(0.005), o.vNew, threads);
    return o;
  };
  const Out a = run(1), b = run(2);
  ASSERT_EQ(a.rho.size(), x.size());
  EXPECT_EQ(std::memcmp(a.rho.data(), b.rho.data(), a.rho.size() * sizeof(Real)), 0);
  EXPECT_EQ(std::memcmp(a.lambda.data(), b.lambda.data(), a.lambda.size() * sizeof(Real)), 0);
  EXPECT_EQ(std::memcmp(a.dp.data(), b.dp.data(), a.dp.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(std::memcmp(a.vNew.data(), b.vNew.data(), a.vNew.size() * sizeof(Vec3)), 0);
  // Non-trivial outputs (the comparison would pass on all-zero arrays).
  double sumDp = 0;
  for (const Vec3& q : a.dp) sumDp += double(q.norm());
  EXPECT_GT(sumDp, 0.0);
}

TEST(Fluid, UnilateralDensityOnlyPushesApart) {
  // A lattice whose outer particles are under-dense (C < 0): bilateral lambdas are positive
  // there (pull together), unilateral ones are clamped to 0; compressed interiors agree.
  const Real h = Real(0.32);
  const Lattice lat = cubicLattice(7, Real(0.9) * kSpacing);
  FluidSettings bilateral = settingsFor(h, kSpacing);
  FluidSettings unilateral = bilateral;
  unilateral.unilateralDensity = true;
  const SphKernels kernels = makeSphKernels(h);
  const NeighbourLists lists = listsFor(lat.x, h);
  const std::vector<Index> all = allOf(lat.x.size());
  std::vector<Real> rho, lambdaB, lambdaU;
  computeLambdas(lat.x, lists, all, kernels, bilateral, rho, lambdaB);
  computeLambdas(lat.x, lists, all, kernels, unilateral, rho, lambdaU);
  int pulled = 0, pushed = 0;
  for (Index p = 0; p < lat.x.size(); ++p) {
    EXPECT_LE(lambdaU[p], Real(0)) << "particle " << p;
    if (lambdaB[p] > 0) {
      ++pulled;
      EXPECT_EQ(lambdaU[p], Real(0));
    } else {
      ++pushed;
      EXPECT_EQ(lambdaU[p], lambdaB[p]);
    }
  }
  EXPECT_GT(pulled, 0);
  EXPECT_GT(pushed, 0);
}

TEST(Fluid, ParticleCollisionSeparatesOverlappingPairs) {
  // Thesis eq. 4.6: two particles 0.5 r apart with collision radius r end 2r apart after one
  // correction (each moves half the overlap), lambdas zero so only the collision acts.
  FluidSettings s = settingsFor(Real(0.32), kSpacing);
  s.collisionRadius = Real(0.08);
  const SphKernels kernels = makeSphKernels(s.supportRadius);
  const std::vector<Vec3> x{Vec3(0, 0, 0), Vec3(Real(0.04), 0, 0)};
  const NeighbourLists lists = listsFor(x, s.supportRadius);
  const std::vector<Real> lambda(2, Real(0));
  std::vector<Vec3> dp;
  computeDensityCorrections(x, lists, allOf(2), kernels, s, lambda, dp);
  EXPECT_NEAR(double(((x[1] + dp[1]) - (x[0] + dp[0])).norm()), 0.16, 1e-6);
  EXPECT_NEAR(double((dp[0] + dp[1]).norm()), 0.0, 1e-7);  // momentum
}

TEST(Fluid, LaplacianViscosityDampsShearAndConservesMomentum) {
  // A sheared lattice (v_x = k y): one viscous step at nu > 0 reduces the velocity spread of
  // interior particles towards their neighbours and keeps the total momentum.
  const Real h = Real(0.32);
  const Lattice lat = cubicLattice(7, kSpacing);
  FluidSettings s = settingsFor(h, kSpacing);
  s.xsphViscosity = 0;
  s.kinematicViscosity = Real(0.5);  // m^2/s; dt = 5 ms is below 0.125 h^2 / nu = 0.026 s
  const SphKernels kernels = makeSphKernels(h);
  const NeighbourLists lists = listsFor(lat.x, h);
  std::vector<Vec3> v(lat.x.size());
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = Vec3(lat.x[i].y() * lat.x[i].y(), 0, 0);  // curved profile
  std::vector<Vec3> vNew;
  applyViscosity(lat.x, v, lists, allOf(v.size()), kernels, s, Real(0.005), vNew);
  Vec3 before = Vec3::Zero(), after = Vec3::Zero();
  for (std::size_t i = 0; i < v.size(); ++i) {
    before += v[i];
    after += vNew[i];
  }
  EXPECT_LT((after - before).norm(), Real(1e-4) * before.norm());
  // lap(y^2) = 2 > 0: interior particles accelerate along +x by about dt nu 2.
  const Index centre = lat.at(lat.n / 2, lat.n / 2, lat.n / 2);
  const double dv = double(vNew[centre].x() - v[centre].x());
  EXPECT_GT(dv, 0.0);
  EXPECT_NEAR(dv, 0.005 * 0.5 * 2.0, 0.5 * 0.005 * 0.5 * 2.0);  // SPH Laplacian within 50%
}

TEST(Fluid, VorticityConfinementAddsRotationAlongTheCurl) {
  // A rigid rotation about z with a vorticity magnitude growing with radius: confinement adds
  // a velocity perpendicular to both grad|omega| and omega, and nothing when eps = 0.
  const Real h = Real(0.32);
  const Lattice lat = cubicLattice(9, kSpacing);
  FluidSettings s = settingsFor(h, kSpacing);
  const SphKernels kernels = makeSphKernels(h);
  const NeighbourLists lists = listsFor(lat.x, h);
  const Vec3 c = lat.x[lat.at(lat.n / 2, lat.n / 2, lat.n / 2)];
  std::vector<Vec3> v(lat.x.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3 r = lat.x[i] - c;
    v[i] = (Real(1) + r.x()) * Vec3(-r.y(), r.x(), 0);  // swirl stronger towards +x
  }
  std::vector<Vec3> omega, vOff, vOn;
  s.vorticityConfinement = 0;
  applyVorticityConfinement(lat.x, v, lists, allOf(v.size()), kernels, s, Real(0.005), omega, vOff);
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_EQ(vOff[i], v[i]);
  const Index centre = lat.at(lat.n / 2, lat.n / 2, lat.n / 2);
  EXPECT_GT(double(omega[centre].z()), 0.0);  // counter-clockwise about +z
  s.vorticityConfinement = Real(1);
  applyVorticityConfinement(lat.x, v, lists, allOf(v.size()), kernels, s, Real(0.005), omega, vOn);
  // N points to +x (stronger swirl), omega to +z: N x omega points to -y.
  EXPECT_LT(double(vOn[centre].y() - v[centre].y()), 0.0);
}

TEST(Fluid, SubsetWritesOnlyItsOwnEntries) {
  const Real h = Real(0.32);
  const Lattice lat = cubicLattice(5, kSpacing);
  const FluidSettings s = settingsFor(h, kSpacing);
  const SphKernels kernels = makeSphKernels(h);
  const NeighbourLists lists = listsFor(lat.x, h);
  const std::vector<Index> subset{3, 62, 100};
  std::vector<Real> rho(lat.x.size(), Real(-7)), rhoAll;
  computeDensities(lat.x, lists, subset, kernels, s, rho);
  computeDensities(lat.x, lists, allOf(lat.x.size()), kernels, s, rhoAll);
  for (Index p = 0; p < lat.x.size(); ++p) {
    const bool in = p == 3 || p == 62 || p == 100;
    EXPECT_EQ(rho[p], in ? rhoAll[p] : Real(-7)) << "particle " << p;
  }
}

}  // namespace
}  // namespace hs::pbd
