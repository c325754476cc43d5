// The SPH kernels of sph_kernels.h: normalisation, support, sign and monotonicity, the spiky
// gradient against finite differences of the spiky kernel, and lattice sums.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "pbd/fluid/sph_kernels.h"

namespace hs::pbd {
namespace {

constexpr Real kSupportRadii[] = {Real(0.05), Real(0.1), Real(1), Real(2.5)};

// 4 pi int_0^h r^2 W(r) dr by the midpoint rule in double. The integrand is a polynomial on
// [0, h], so the midpoint error is O(h^2/n^2) ~ 1e-11 for n = 200000; what remains is the
// rounding of W in Real (relative 6e-8 in float), far below the 1e-3 tolerance.
template <class W>
double radialIntegral(Real h, W w) {
  constexpr int n = 200000;
  const double hd = static_cast<double>(h);
  const double dr = hd / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double r = (i + 0.5) * dr;
    sum += r * r * static_cast<double>(w(static_cast<Real>(r)));
  }
  return 4.0 * std::numbers::pi * sum * dr;
}

TEST(SphKernels, Poly6IntegratesToOne) {
  for (const Real h : kSupportRadii) {
    const SphKernels k = makeSphKernels(h);
    const double integral = radialIntegral(h, [&](Real r) { return poly6(k, r * r); });
    RecordProperty("poly6_integral_h" + std::to_string(h), std::to_string(integral));
    EXPECT_NEAR(integral, 1.0, 1e-3) << "h = " << h;
  }
}

TEST(SphKernels, SpikyIntegratesToOne) {
  for (const Real h : kSupportRadii) {
    const SphKernels k = makeSphKernels(h);
    const double integral = radialIntegral(h, [&](Real r) { return spiky(k, r); });
    RecordProperty("spiky_integral_h" + std::to_string(h), std::to_string(integral));
    EXPECT_NEAR(integral, 1.0, 1e-3) << "h = " << h;
  }
}

TEST(SphKernels, ZeroOutsideSupportPositiveInsideAndNonIncreasing) {
  for (const Real h : kSupportRadii) {
    const SphKernels k = makeSphKernels(h);
    EXPECT_EQ(poly6(k, h * h), Real(0));
    EXPECT_EQ(spiky(k, h), Real(0));
    EXPECT_EQ(spikyGradient(k, Vec3(h, 0, 0), h), Vec3::Zero());
    for (const Real s : {Real(1.0001), Real(1.5), Real(10)}) {
      const Real r = s * h;
      EXPECT_EQ(poly6(k, r * r), Real(0));
      EXPECT_EQ(spiky(k, r), Real(0));
      EXPECT_EQ(spikyGradient(k, Vec3(0, r, 0), r), Vec3::Zero());
    }
    EXPECT_EQ(spikyGradient(k, Vec3::Zero(), Real(0)), Vec3::Zero());

    // Sample [0, 1.2 h]: positive strictly inside (up to r = 0.999 h, where (1 - q)^3 = 1e-9
    // is still a normal float), zero outside, and never increasing.
    constexpr int n = 2400;
    Real prevPoly6 = std::numeric_limits<Real>::infinity();
    Real prevSpiky = std::numeric_limits<Real>::infinity();
    for (int i = 0; i <= n; ++i) {
      const Real r = h * Real(1.2) * static_cast<Real>(i) / Real(n);
      const Real wp = poly6(k, r * r);
      const Real ws = spiky(k, r);
      if (r <= Real(0.999) * h) {
        EXPECT_GT(wp, Real(0)) << "r/h = " << r / h;
        EXPECT_GT(ws, Real(0)) << "r/h = " << r / h;
      }
      if (r >= h) {
        EXPECT_EQ(wp, Real(0)) << "r/h = " << r / h;
        EXPECT_EQ(ws, Real(0)) << "r/h = " << r / h;
      }
      EXPECT_LE(wp, prevPoly6) << "r/h = " << r / h;
      EXPECT_LE(ws, prevSpiky) << "r/h = " << r / h;
      prevPoly6 = wp;
      prevSpiky = ws;
    }
  }
}

TEST(SphKernels, SpikyGradientMatchesFiniteDifferences) {
  std::mt19937 rng(1234);
  std::uniform_real_distribution<Real> unit(Real(-1), Real(1));
  for (const Real h : kSupportRadii) {
    const SphKernels k = makeSphKernels(h);
    auto w = [&](const Vec3& x) { return spiky(k, x.norm()); };
    // Central differences with step eps = 1e-3 h. Truncation error, relative to |grad W|:
    // ~ (eps/r)^2 from the curvature of |x| plus (eps/(h - r))^2 / 3 from W''', i.e. <= ~1.5e-4
    // at the sampled extremes r = 0.05 h and r = 0.9 h (measured worst: 1.4e-4 at r = 0.052 h).
    // Float rounding: u W / (eps |W'|) = u (1 - q) h / (3 eps) = 6e-8 / 3e-3 (1 - q) <= 2e-5. A relative
    // tolerance of 1e-3 on the whole vector covers both with margin, and still catches any wrong
    // constant, power or sign (those give O(1) errors).
    const Real eps = Real(1e-3) * h;
    int tested = 0;
    while (tested < 500) {
      const Vec3 x = h * Vec3(unit(rng), unit(rng), unit(rng));
      const Real r = x.norm();
      // Stay away from the cusp at r = 0 and the support edge, where |W'| -> 0.
      if (r < Real(0.05) * h || r > Real(0.9) * h) continue;
      ++tested;
      Vec3 fd;
      for (int a = 0; a < 3; ++a) {
        Vec3 xp = x, xm = x;
        xp[a] += eps;
        xm[a] -= eps;
        fd[a] = (w(xp) - w(xm)) / (xp[a] - xm[a]);  // exact step actually taken
      }
      const Vec3 g = spikyGradient(k, x, r);
      EXPECT_LE((fd - g).norm(), Real(1e-3) * g.norm())
          << "h = " << h << " x = " << x.transpose() << " g = " << g.transpose() << " fd = " << fd.transpose();
      // Points from x_i towards x_j (r_ij = x_i - x_j = x): opposite to r_ij.
      EXPECT_LT(g.dot(x), Real(0));
    }
  }
}

TEST(SphKernels, SpikyGradientIsAntisymmetric) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<Real> unit(Real(-1), Real(1));
  const SphKernels k = makeSphKernels(Real(0.1));
  for (int i = 0; i < 200; ++i) {
    const Vec3 x = Real(0.1) * Vec3(unit(rng), unit(rng), unit(rng));
    const Vec3 mx = -x;
    const Vec3 g = spikyGradient(k, x, x.norm());
    const Vec3 gm = spikyGradient(k, mx, mx.norm());
    // Negation is exact in floating point and |x| = |-x| bit for bit, so the results are
    // exact negatives of each other.
    EXPECT_EQ(g, -gm) << x.transpose();
  }
}

// Offsets d (a, b, c) of the integer lattice with |offset| < h, central particle excluded.
std::vector<Vec3> latticeNeighbours(Real d, Real h, bool includeSelf) {
  std::vector<Vec3> out;
  const int n = static_cast<int>(std::ceil(h / d));
  for (int a = -n; a <= n; ++a)
    for (int b = -n; b <= n; ++b)
      for (int c = -n; c <= n; ++c) {
        if (!includeSelf && a == 0 && b == 0 && c == 0) continue;
        const Vec3 o = d * Vec3(static_cast<Real>(a), static_cast<Real>(b), static_cast<Real>(c));
        if (o.squaredNorm() < h * h) out.push_back(o);
      }
  return out;
}

TEST(SphKernels, SpikyGradientSumsToZeroOverSymmetricLattice) {
  const Real d = Real(0.05);
  for (const Real ratio : {Real(2), Real(2.5), Real(3), Real(4)}) {
    const Real h = ratio * d;
    const SphKernels k = makeSphKernels(h);
    const Vec3 xi = Vec3(Real(0.3), Real(-0.2), Real(0.7));  // away from the origin on purpose
    Vec3 sum = Vec3::Zero();
    Vec3 halfSum = Vec3::Zero();  // neighbours with x_j.x > x_i.x only
    Real magnitudeSum = 0;
    const std::vector<Vec3> offsets = latticeNeighbours(d, h, /*includeSelf=*/true);
    for (const Vec3& o : offsets) {
      const Vec3 xj = xi + o;
      const Vec3 rij = xi - xj;
      const Vec3 g = spikyGradient(k, rij, rij.norm());
      sum += g;
      magnitudeSum += g.norm();
      if (o.x() > 0) halfSum += g;
    }
    ASSERT_GE(offsets.size(), 27u);  // h = 2d: self, 6 faces, 12 edges, 8 corners
    // Each +o is cancelled by -o; what remains is the rounding of x_j = x_i + o and of
    // x_i - x_j: ulp(0.7) / |o| <= 6e-8 / 0.05 ~ 1e-6 relative per gradient in float, and these
    // errors are independent, so the sum stays below 1e-6 of the summed magnitudes (measured:
    // <= 3.5e-8). A missing or unbalanced neighbour would give ~1/N ~ 1e-2.
    EXPECT_LE(sum.norm(), Real(1e-6) * magnitudeSum) << "h/d = " << ratio << " sum = " << sum.transpose();
    // Neighbours on one side only: the gradient points towards them (+x). For an isotropic
    // neighbourhood the x component is 1/4 of the summed magnitudes (mean of cos over a
    // hemisphere, halved); on these lattices it is 0.20-0.23.
    EXPECT_GT(halfSum.x(), Real(0.15) * magnitudeSum) << "h/d = " << ratio;
  }
}

TEST(SphKernels, Poly6LatticeDensityIsRestDensity) {
  // A cubic lattice of spacing d has number density 1/d^3; with particle volume d^3 (mass
  // rho0 d^3) the SPH density estimate sum_j W(x_i - x_j) d^3 should be ~1 (rho ~ rho0).
  const Real d = Real(0.025);
  const Real h = 4 * d;
  const SphKernels k = makeSphKernels(h);
  double sum = 0.0;
  for (const Vec3& o : latticeNeighbours(d, h, /*includeSelf=*/true)) sum += static_cast<double>(poly6(k, o.squaredNorm()));
  const double density = sum * static_cast<double>(d * d * d);
  RecordProperty("poly6_lattice_density_h4d", std::to_string(density));
  EXPECT_NEAR(density, 1.0, 0.02);
}

}  // namespace
}  // namespace hs::pbd
