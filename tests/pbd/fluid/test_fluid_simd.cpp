// The SIMD fluid kernels (fluid_simd.cpp) against the scalar reference (fluid.cpp).
//
// Tolerance: both paths evaluate every per-pair term with the same operations in the same order
// (so the per-pair gradient cache is bitwise equal) and differ only in how the n terms of each
// sum over neighbours are associated (sequentially vs eight lane sums added in a tree). Either
// order's rounding error is at most (n - 1) u sum_k |t_k| (u = 2^-24 for float; Higham,
// "Accuracy and Stability of Numerical Algorithms", eq. 4.4), so two results may differ by
// 2 (n - 1) u sum |t_k|. Each check allows 4 (n + 2) u A, A the sum of magnitudes that feeds
// the output (derived per output below): twice the bound, for the few roundings after the sums.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "pbd/fluid/fluid.h"
#include "pbd/fluid/fluid_loops.h"

#ifdef HS_HAVE_HIGHWAY
#include <hwy/highway.h>

#include "pbd/fluid/fluid_simd.h"

namespace hs::pbd {
namespace {

constexpr Real kH = Real(0.32);
constexpr Real kSpacing = Real(0.16);
constexpr double kU = double(std::numeric_limits<Real>::epsilon()) / 2;

struct Scene {
  std::vector<Vec3> x, v;
  NeighbourLists lists;
  std::vector<Index> all;
  WallDensityTable table{makeSphKernels(kH)};
  std::vector<WallProximity> proximity;
  std::vector<Vec3> start;
  WallDensityInput walls() const { return {&table, &proximity, &start}; }
};

// Particles at random in a box, about 30 neighbours each, a wall at x = 0 lending density to
// those within h of it, and two particles at the same place (r = 0). Random velocities with a
// swirl about the y axis so that the vorticity has a clear gradient.
Scene randomScene(std::size_t n, unsigned seed) {
  Scene s;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1.9);
  for (std::size_t i = 0; i < n; ++i) s.x.emplace_back(Real(u(rng)), Real(u(rng)), Real(u(rng)));
  s.x.push_back(s.x[5]);
  for (const Vec3& p : s.x) {
    const Vec3 noise(Real(u(rng)), Real(u(rng)), Real(u(rng)));
    s.v.push_back(Vec3(p.z() - Real(0.95), 0, Real(0.95) - p.x()) + Real(0.1) * noise);
  }
  NeighbourGrid grid;
  grid.build(s.x, kH);
  grid.buildNeighbourLists(s.x, kH, s.lists);
  s.all.resize(s.x.size());
  std::iota(s.all.begin(), s.all.end(), Index(0));
  s.proximity.resize(s.x.size());
  for (std::size_t i = 0; i < s.x.size(); ++i)
    if (s.x[i].x() < kH) s.proximity[i] = {s.x[i].x(), Vec3::UnitX()};
  s.start = s.x;
  return s;
}

// A cubic lattice at spacing d with h = 2d, slightly compressed and jittered.
Scene latticeScene(int n, unsigned seed) {
  Scene s;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.01, 0.01);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        s.x.push_back(Real(0.9) * kSpacing * Vec3(Real(i), Real(j), Real(k)) +
                      Vec3(Real(u(rng)), Real(u(rng)), Real(u(rng))));
  for (const Vec3& p : s.x) s.v.push_back(Vec3(-p.y(), p.x(), Real(0.3) * p.z()));
  NeighbourGrid grid;
  grid.build(s.x, kH);
  grid.buildNeighbourLists(s.x, kH, s.lists);
  s.all.resize(s.x.size());
  std::iota(s.all.begin(), s.all.end(), Index(0));
  s.proximity.resize(s.x.size());
  s.start = s.x;
  return s;
}

FluidSettings settingsWith(FluidKernelPath path) {
  FluidSettings s;
  s.restDensity = 1000;
  s.particleMass = particleMassFor(1000, kSpacing);
  s.supportRadius = kH;
  s.relaxation = Real(14.6);
  s.tensileCorrection = true;
  s.collisionRadius = Real(0.05);
  s.kinematicViscosity = Real(0.003);
  s.vorticityConfinement = Real(0.5);
  s.kernelPath = path;
  return s;
}

struct Outputs {
  std::vector<Real> rho, lambda, pairGradient;
  std::vector<Vec3> dp, dpFresh, vNew, omega, vConfined;
};

// Every kernel on one path; the corrections take `lambdaIn` (the scalar path's lambdas) so
// that each kernel is compared on the same inputs.
Outputs runKernels(const Scene& s, FluidKernelPath path, int threads, const std::vector<Real>* lambdaIn) {
  const FluidSettings f = settingsWith(path);
  const SphKernels k = makeSphKernels(kH);
  const WallDensityInput walls = s.walls();
  Outputs o;
  computeLambdas(s.x, s.lists, s.all, k, f, o.rho, o.lambda, threads, &o.pairGradient, &walls);
  const std::vector<Real>& lambdas = lambdaIn ? *lambdaIn : o.lambda;
  computeDensityCorrections(s.x, s.lists, s.all, k, f, lambdas, o.dp, threads, &o.pairGradient, &walls);
  computeDensityCorrections(s.x, s.lists, s.all, k, f, lambdas, o.dpFresh, threads, nullptr, &walls);
  applyViscosity(s.x, s.v, s.lists, s.all, k, f, Real(0.005), o.vNew, threads);
  applyVorticityConfinement(s.x, s.v, s.lists, s.all, k, f, Real(0.005), o.omega, o.vConfined, threads);
  return o;
}

template <class T>
bool bitwiseEqual(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

// The first n entries (outputs outside the subset are left as they were: uninitialised Vec3s).
template <class T>
bool bitwiseEqualPrefix(const std::vector<T>& a, const std::vector<T>& b, std::size_t n) {
  return a.size() >= n && b.size() >= n && std::memcmp(a.data(), b.data(), n * sizeof(T)) == 0;
}

double tolerance(std::size_t n, double magnitude) { return 4 * double(n + 2) * kU * magnitude; }

// Sums of magnitudes per particle (in double, from the scalar path's own per-pair values).
struct Magnitudes {
  double gradAbs = 0;     // sum_j |g_j|, g_j = (m/rho0) s_ij r_ij
  double correction = 0;  // (m/rho0) sum_j |w_ij s_ij r_ij| + sum_j |push_ij|
  double viscosity = 0;   // c sum_j W |v_ij| + laplace sum_j |a_ij grad W|
  double curl = 0;        // (m/rho0) sum_j |v_ij| |grad W|
  double eta = 0;         // (m/rho0) sum_j | |omega_j| - |omega_i| | |grad W|
};

Magnitudes magnitudesOf(const Scene& s, Index i, const Outputs& ref, const FluidSettings& f) {
  const SphKernels k = makeSphKernels(kH);
  const double scale = double(f.particleMass / f.restDensity);
  const double laplace = 0.005 * 10 * double(f.kinematicViscosity) * scale;
  Magnitudes m;
  for (Index e = s.lists.offsets[i]; e < s.lists.offsets[i + 1]; ++e) {
    const Index j = s.lists.indices[e];
    const Vec3 r = s.x[i] - s.x[j];
    const double rn = double(r.norm());
    const double gradW = double(spikyGradient(k, r, r.norm()).norm());
    const double vij = double((s.v[i] - s.v[j]).norm());
    m.gradAbs += scale * std::abs(double(ref.pairGradient[e])) * rn;
    // |w| <= |lambda_i| + |lambda_j| + k (tensile ratio <= W(0)/W(dq), ^4); push <= 2r.
    const double ratio = double(poly6(k, 0)) / double(poly6(k, Real(0.04) * k.h2));
    const double w = std::abs(double(ref.lambda[i])) + std::abs(double(ref.lambda[j])) +
                     double(f.tensileK) * std::pow(ratio, f.tensileN);
    m.correction += scale * w * std::abs(double(ref.pairGradient[e])) * rn + 2 * double(f.collisionRadius);
    m.viscosity += double(f.xsphViscosity) * double(poly6(k, r.squaredNorm())) * vij +
                   laplace * vij * rn / (rn * rn + 0.01 * double(k.h2)) * gradW;
    m.curl += scale * vij * gradW;
    m.eta += scale * std::abs(double(ref.omega[j].norm()) - double(ref.omega[i].norm())) * gradW;
  }
  return m;
}

void expectSimdMatchesScalar(const Scene& s, bool withWalls) {
  const Outputs ref = runKernels(s, FluidKernelPath::Scalar, 1, nullptr);
  const Outputs out = runKernels(s, FluidKernelPath::Simd, 1, &ref.lambda);
  const FluidSettings f = settingsWith(FluidKernelPath::Scalar);
  // Same per-pair expressions: the pair-gradient cache is bitwise the same.
  EXPECT_TRUE(bitwiseEqual(ref.pairGradient, out.pairGradient));
  int confinementChecked = 0, walled = 0;
  for (const Index i : s.all) {
    const std::size_t n = s.lists.offsets[i + 1] - s.lists.offsets[i];
    const Magnitudes m = magnitudesOf(s, i, ref, f);
    walled += s.proximity[i].normal.squaredNorm() > 0 ? 1 : 0;
    // rho: a sum of positive terms, A = rho.
    EXPECT_NEAR(double(out.rho[i]), double(ref.rho[i]), tolerance(n, double(ref.rho[i]))) << i;
    // lambda = -C/D: dC = drho/rho0, and D = |grad_i C|^2 + sum_j |g_j|^2 + eps moves by at
    // most 2 |grad_i C| dgrad + dsumSq, so A = (rho/rho0 + |lambda| (2 |grad_i| G + G^2)) / D with
    // G = sum |g_j| (|grad_i| <= G, sum |g_j|^2 <= G^2; the wall term adds to neither bound).
    const double rhoRel = double(ref.rho[i]) / double(f.restDensity);
    const double lambdaRef = double(ref.lambda[i]), c = rhoRel - 1;
    const double denominator = lambdaRef != 0 ? std::abs(c / lambdaRef) : 0;
    if (denominator > 0) {
      const WallProximity& wall = s.proximity[i];
      const double g = m.gradAbs + (wall.normal.squaredNorm() > 0 ? double(s.table.gradient(wall.distance)) : 0);
      const double a = (rhoRel + std::abs(lambdaRef) * 3 * g * g) / denominator + std::abs(lambdaRef);
      EXPECT_NEAR(double(out.lambda[i]), lambdaRef, tolerance(n, a)) << i;
    }
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_NEAR(double(out.dp[i][axis]), double(ref.dp[i][axis]), tolerance(n, m.correction)) << i;
      EXPECT_NEAR(double(out.dpFresh[i][axis]), double(ref.dpFresh[i][axis]), tolerance(n, m.correction)) << i;
      const double v = double(s.v[i].norm()) + m.viscosity;
      EXPECT_NEAR(double(out.vNew[i][axis]), double(ref.vNew[i][axis]), tolerance(n, v)) << i;
      EXPECT_NEAR(double(out.omega[i][axis]), double(ref.omega[i][axis]), tolerance(n, m.curl)) << i;
    }
    // v += dt eps (eta/|eta|) x omega: the direction eta/|eta| amplifies eta's error by
    // A_eta/|eta| and omega's by 1. Checked where eta is not mostly cancellation.
    const double etaNorm = double((ref.vConfined[i] - s.v[i]).norm());
    if (etaNorm > 0) {
      const Vec3 eta = [&] {
        Vec3 e = Vec3::Zero();
        const SphKernels k = makeSphKernels(kH);
        for (Index q = s.lists.offsets[i]; q < s.lists.offsets[i + 1]; ++q) {
          const Index j = s.lists.indices[q];
          const Vec3 r = s.x[i] - s.x[j];
          e += (ref.omega[j].norm() - ref.omega[i].norm()) * spikyGradient(k, r, r.norm());
        }
        return Vec3((f.particleMass / f.restDensity) * e);
      }();
      const double condition = m.eta / double(eta.norm());
      if (condition < 100) {
        ++confinementChecked;
        const double kick = 0.005 * double(f.vorticityConfinement) * double(ref.omega[i].norm());
        const double a = double(s.v[i].norm()) + kick * (condition + 1 + m.curl / double(ref.omega[i].norm()));
        for (int axis = 0; axis < 3; ++axis)
          EXPECT_NEAR(double(out.vConfined[i][axis]), double(ref.vConfined[i][axis]), tolerance(n, a)) << i;
      }
    }
  }
  // The checks above saw the terms that matter.
  EXPECT_GT(confinementChecked, int(s.all.size()) / 2);
  double sumDp = 0, sumVisc = 0;
  for (const Index i : s.all) {
    sumDp += double(ref.dp[i].norm());
    sumVisc += double((ref.vNew[i] - s.v[i]).norm());
  }
  EXPECT_GT(sumDp, 0.0);
  EXPECT_GT(sumVisc, 0.0);
  EXPECT_EQ(walled > 0, withWalls);
}

TEST(FluidSimd, MatchesScalarOnRandomParticles) { expectSimdMatchesScalar(randomScene(1500, 7), true); }

TEST(FluidSimd, MatchesScalarOnACompressedLattice) { expectSimdMatchesScalar(latticeScene(12, 11), false); }

TEST(FluidSimd, ResultsAreBitwiseIdenticalForOneAndTwoThreads) {
  const Scene s = randomScene(2000, 21);
  const Outputs a = runKernels(s, FluidKernelPath::Simd, 1, nullptr);
  const Outputs b = runKernels(s, FluidKernelPath::Simd, 2, nullptr);
  EXPECT_TRUE(bitwiseEqual(a.rho, b.rho));
  EXPECT_TRUE(bitwiseEqual(a.lambda, b.lambda));
  EXPECT_TRUE(bitwiseEqual(a.pairGradient, b.pairGradient));
  EXPECT_TRUE(bitwiseEqual(a.dp, b.dp));
  EXPECT_TRUE(bitwiseEqual(a.dpFresh, b.dpFresh));
  EXPECT_TRUE(bitwiseEqual(a.vNew, b.vNew));
  EXPECT_TRUE(bitwiseEqual(a.omega, b.omega));
  EXPECT_TRUE(bitwiseEqual(a.vConfined, b.vConfined));
}

// Eight fixed lanes and no fused operations: every instruction set Highway compiled for and
// this machine runs (AVX-512, AVX2, SSE4, SSSE3, the emulated fallback) gives the same bits.
TEST(FluidSimd, EveryInstructionSetGivesTheSameBits) {
  const Scene s = randomScene(600, 5);
  const std::int64_t available = hwy::SupportedTargets() & HWY_TARGETS;
  std::vector<std::string> names;
  Outputs first;
  for (std::int64_t targets = available; targets != 0; targets &= targets - 1) {
    const std::int64_t target = targets & -targets;
    hwy::SetSupportedTargetsForTest(target);
    names.emplace_back(simd::targetName());
    EXPECT_EQ(names.back(), hwy::TargetName(target));
    const Outputs o = runKernels(s, FluidKernelPath::Simd, 1, nullptr);
    if (names.size() == 1) {
      first = o;
      continue;
    }
    EXPECT_TRUE(bitwiseEqual(first.rho, o.rho)) << names.back() << " vs " << names.front();
    EXPECT_TRUE(bitwiseEqual(first.lambda, o.lambda)) << names.back();
    EXPECT_TRUE(bitwiseEqual(first.dp, o.dp)) << names.back();
    EXPECT_TRUE(bitwiseEqual(first.dpFresh, o.dpFresh)) << names.back();
    EXPECT_TRUE(bitwiseEqual(first.vNew, o.vNew)) << names.back();
    EXPECT_TRUE(bitwiseEqual(first.vConfined, o.vConfined)) << names.back();
  }
  hwy::SetSupportedTargetsForTest(0);
  EXPECT_GE(names.size(), 2u);
  for (const std::string& n : names) std::printf("fluid SIMD target checked: %s\n", n.c_str());
}

// A support radius for which r/h and r^2/h^2 round to just under 1 at r = h, where a clamp of
// 1 - r/h alone would leave a tiny non-zero kernel.
Real roundingSupportRadius() {
  for (Real h = Real(0.3); h < Real(0.4); h = std::nextafter(h, Real(1))) {
    const SphKernels k = makeSphKernels(h);
    if (Real(1) - k.h2 * k.invH2 > 0 && Real(1) - std::sqrt(k.h2) * k.invH > 0) return h;
  }
  return 0;
}

// Lists may hold pairs beyond h (a skin): entries at r >= h, appended to every list, change
// no output, bitwise, on either path (appended entries take lanes after all real ones).
TEST(FluidSimd, PairsAtOrBeyondTheSupportContributeNothing) {
  const Real h = roundingSupportRadius();
  ASSERT_GT(h, Real(0));
  Scene s = randomScene(400, 3);
  // Rescale the scene to support h and add, for each particle, partners at exactly h and beyond.
  NeighbourGrid grid;
  grid.build(s.x, h);
  grid.buildNeighbourLists(s.x, h, s.lists);
  const std::size_t n = s.x.size();
  NeighbourLists skin;
  skin.offsets.push_back(0);
  // Partners along x and y at the first representable |r|^2 >= h^2 (as the kernels compute
  // it), and one along z at 1.5 h.
  const std::vector<Real> reach{h, h, Real(1.5) * h};
  const Real h2 = h * h;
  for (std::size_t i = 0; i < n; ++i) {
    for (int axis = 0; axis < 3; ++axis) {
      Vec3 partner = s.x[i];
      partner[axis] += reach[std::size_t(axis)];
      while ((s.x[i] - partner).squaredNorm() < h2)
        partner[axis] = std::nextafter(partner[axis], std::numeric_limits<Real>::infinity());
      s.x.push_back(partner);
      s.v.push_back(Vec3(1, 2, 3));
    }
  }
  const std::vector<int> offsets{0, 1, 2};
  s.proximity.resize(s.x.size());
  s.start = s.x;
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    if (i < n) {
      skin.indices.insert(skin.indices.end(), s.lists.indices.begin() + s.lists.offsets[i],
                          s.lists.indices.begin() + s.lists.offsets[i + 1]);
      for (std::size_t e = 0; e < offsets.size(); ++e) skin.indices.push_back(Index(n + 3 * i + e));
    }
    skin.offsets.push_back(Index(skin.indices.size()));
  }
  NeighbourLists plain;
  plain.offsets.assign(s.x.size() + 1, 0);
  for (std::size_t i = 0; i <= n; ++i) plain.offsets[i] = s.lists.offsets[i];
  for (std::size_t i = n + 1; i <= s.x.size(); ++i) plain.offsets[i] = s.lists.offsets[n];
  plain.indices = s.lists.indices;
  s.all.resize(n);
  std::iota(s.all.begin(), s.all.end(), Index(0));
  for (const FluidKernelPath path : {FluidKernelPath::Scalar, FluidKernelPath::Simd}) {
    FluidSettings f = settingsWith(path);
    f.supportRadius = h;
    f.collisionRadius = 0;  // the push is not a kernel: it acts below 2 r < h only
    const SphKernels k = makeSphKernels(h);
    std::vector<Real> rhoA, rhoB, lambdaA, lambdaB, pairA, pairB;
    std::vector<Vec3> dpA, dpB, vA, vB, oA, oB, cA, cB;
    computeLambdas(s.x, plain, s.all, k, f, rhoA, lambdaA, 1, &pairA);
    computeLambdas(s.x, skin, s.all, k, f, rhoB, lambdaB, 1, &pairB);
    EXPECT_TRUE(bitwiseEqualPrefix(rhoA, rhoB, n));
    EXPECT_TRUE(bitwiseEqualPrefix(lambdaA, lambdaB, n));
    for (std::size_t i = 0; i < n; ++i)
      for (Index e = skin.offsets[i + 1] - 3; e < skin.offsets[i + 1]; ++e) EXPECT_EQ(pairB[e], Real(0));
    computeDensityCorrections(s.x, plain, s.all, k, f, lambdaA, dpA, 1, &pairA);
    computeDensityCorrections(s.x, skin, s.all, k, f, lambdaA, dpB, 1, &pairB);
    EXPECT_TRUE(bitwiseEqualPrefix(dpA, dpB, n));
    computeDensityCorrections(s.x, skin, s.all, k, f, lambdaA, dpB, 1, nullptr);
    EXPECT_TRUE(bitwiseEqualPrefix(dpA, dpB, n));
    applyViscosity(s.x, s.v, plain, s.all, k, f, Real(0.005), vA, 1);
    applyViscosity(s.x, s.v, skin, s.all, k, f, Real(0.005), vB, 1);
    EXPECT_TRUE(bitwiseEqualPrefix(vA, vB, n));
    applyVorticityConfinement(s.x, s.v, plain, s.all, k, f, Real(0.005), oA, cA, 1);
    applyVorticityConfinement(s.x, s.v, skin, s.all, k, f, Real(0.005), oB, cB, 1);
    EXPECT_TRUE(bitwiseEqualPrefix(oA, oB, n));
    EXPECT_TRUE(bitwiseEqualPrefix(cA, cB, n));
  }
}

}  // namespace
}  // namespace hs::pbd
#endif  // HS_HAVE_HIGHWAY
