// Every kernel's gradient against central finite differences, and one projection reduces |C|.
#include <gtest/gtest.h>

#include <random>

#include "pbd/constraints.h"

namespace hs::pbd {
namespace {

template <std::size_t N>
std::array<Vec3, N> randomPoints(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::array<Vec3, N> x;
  for (auto& p : x) p = Vec3(Real(u(rng)), Real(u(rng)), Real(u(rng)));
  return x;
}

// Central differences of C with step h; compares with the analytic gradient.
template <std::size_t N, class Eval>
void expectGradientMatchesFiniteDifferences(const std::array<Vec3, N>& x, Eval eval) {
  const ConstraintEval<N> analytic = eval(x);
  const Real h = std::is_same_v<Real, float> ? Real(2e-3) : Real(1e-6);
  const Real tolerance = std::is_same_v<Real, float> ? Real(5e-3) : Real(1e-7);
  Real scale = 1;
  for (const auto& g : analytic.gradient) scale = std::max(scale, g.norm());
  for (std::size_t i = 0; i < N; ++i) {
    for (int d = 0; d < 3; ++d) {
      auto plus = x;
      auto minus = x;
      plus[i][d] += h;
      minus[i][d] -= h;
      const Real numeric = (eval(plus).value - eval(minus).value) / (2 * h);
      EXPECT_NEAR(analytic.gradient[i][d], numeric, tolerance * scale)
          << "particle " << i << " axis " << d;
    }
  }
}

TEST(ConstraintKernels, TetVolumeGradientMatchesFiniteDifferences) {
  std::mt19937 rng(1);
  for (int trial = 0; trial < 50; ++trial) {
    expectGradientMatchesFiniteDifferences<4>(
        randomPoints<4>(rng), [](const auto& x) { return evaluateTetVolume(x, Real(0.1)); });
  }
}

TEST(ConstraintKernels, TriangleAreaGradientMatchesFiniteDifferences) {
  std::mt19937 rng(2);
  for (int trial = 0; trial < 50; ++trial) {
    expectGradientMatchesFiniteDifferences<3>(
        randomPoints<3>(rng), [](const auto& x) { return evaluateTriangleArea(x, Real(0.2)); });
  }
}

TEST(ConstraintKernels, DistanceGradientMatchesFiniteDifferences) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 50; ++trial) {
    expectGradientMatchesFiniteDifferences<2>(
        randomPoints<2>(rng), [](const auto& x) { return evaluateDistance(x, Real(0.5)); });
  }
}

TEST(ConstraintKernels, PlaneGradientMatchesFiniteDifferences) {
  std::mt19937 rng(4);
  const Plane plane{Vec3(1, 2, 2).normalized(), Real(0.3)};
  for (int trial = 0; trial < 20; ++trial) {
    expectGradientMatchesFiniteDifferences<1>(randomPoints<1>(rng), [&](const auto& x) {
      return evaluatePlaneCollision(x[0], plane, Real(0.05));
    });
  }
}

TEST(ConstraintKernels, TetVolumeValueIsSignedVolumeMinusRest) {
  const std::array<Vec3, 4> x{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  EXPECT_NEAR(evaluateTetVolume(x, 0).value, Real(1.0 / 6.0), Real(1e-7));
  const std::array<Vec3, 4> flipped{x[0], x[2], x[1], x[3]};
  EXPECT_NEAR(evaluateTetVolume(flipped, 0).value, Real(-1.0 / 6.0), Real(1e-7));
}

// A full-stiffness, zero-compliance projection zeroes the linearised constraint
// (thesis eq. 3.1: C + grad C . dx = 0) and, for these smooth constraints, reduces |C|.
template <std::size_t N, class Eval>
void expectProjectionReducesViolation(std::array<Vec3, N> x, const std::array<Real, N>& w,
                                      Eval eval) {
  const ConstraintEval<N> c = eval(x);
  const Real before = std::abs(c.value);
  ASSERT_GT(before, Real(1e-3));
  const Projection<N> r = projectXpbd(c, w, ProjectionParams{0, 1}, 0);
  Real linearised = c.value;
  for (std::size_t i = 0; i < N; ++i) linearised += c.gradient[i].dot(r.dx[i]);
  EXPECT_NEAR(linearised, 0, 1e-5 * std::max(Real(1), before));
  for (std::size_t i = 0; i < N; ++i) x[i] += r.dx[i];
  EXPECT_LT(std::abs(eval(x).value), before);
}

TEST(ConstraintKernels, OneProjectionReducesViolation) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    expectProjectionReducesViolation<4>(randomPoints<4>(rng), {1, 2, Real(0.5), 1}, [](const auto& x) {
      return evaluateTetVolume(x, Real(0.05));
    });
    expectProjectionReducesViolation<3>(randomPoints<3>(rng), {1, 1, 3}, [](const auto& x) {
      return evaluateTriangleArea(x, Real(0.3));
    });
    expectProjectionReducesViolation<2>(randomPoints<2>(rng), {1, Real(0.25)}, [](const auto& x) {
      return evaluateDistance(x, Real(0.4));
    });
  }
}

TEST(ConstraintKernels, PinnedParticlesDoNotMoveAndMomentumIsKept) {
  std::array<Vec3, 2> x{Vec3(0, 0, 0), Vec3(2, 0, 0)};
  const auto c = evaluateDistance(x, 1);
  const auto pinned = projectXpbd<2>(c, {0, 1}, ProjectionParams{0, 1}, 0);
  EXPECT_EQ(pinned.dx[0], Vec3::Zero());
  EXPECT_NEAR(pinned.dx[1].x(), -1, 1e-6);
  // Equal masses: corrections are equal and opposite (no net momentum change).
  const auto both = projectXpbd<2>(c, {1, 1}, ProjectionParams{0, 1}, 0);
  EXPECT_NEAR((both.dx[0] + both.dx[1]).norm(), 0, 1e-7);
}

TEST(ConstraintKernels, StiffnessScalesThePbdCorrection) {
  std::array<Vec3, 2> x{Vec3(0, 0, 0), Vec3(2, 0, 0)};
  const auto c = evaluateDistance(x, 1);
  const auto full = projectXpbd<2>(c, {1, 1}, ProjectionParams{0, 1}, 0);
  const auto half = projectXpbd<2>(c, {1, 1}, ProjectionParams{0, Real(0.5)}, 0);
  EXPECT_NEAR(half.dx[1].x(), Real(0.5) * full.dx[1].x(), 1e-7);
}

TEST(ConstraintKernels, ComplianceSoftensAndLambdaAccumulates) {
  // XPBD with compliance alpha: after converging, C = -alphaTilde * lambda (a spring).
  std::array<Vec3, 2> x{Vec3(0, 0, 0), Vec3(2, 0, 0)};
  const std::array<Real, 2> w{0, 1};
  const ProjectionParams params{Real(1), Real(1)};
  Real lambda = 0;
  for (int i = 0; i < 100; ++i) {
    const auto r = projectXpbd<2>(evaluateDistance(x, 1), w, params, lambda);
    lambda += r.deltaLambda;
    x[1] += r.dx[1];
  }
  const Real c = evaluateDistance(x, 1).value;
  EXPECT_NEAR(c, -params.alphaTilde * lambda, 1e-5);
  EXPECT_NEAR(c, Real(0.5), 1e-4);  // w = 1, alphaTilde = 1: half of the violation remains
}

TEST(ConstraintKernels, PlaneCollisionPushesOutOnlyWhenPenetrating) {
  const Plane floor{Vec3::UnitY(), 0};
  EXPECT_EQ(projectPlaneCollision(Vec3(0, 1, 0), 1, floor, Real(0.1)), Vec3::Zero());
  const Vec3 dx = projectPlaneCollision(Vec3(0, Real(-0.2), 0), 1, floor, Real(0.1));
  EXPECT_NEAR(dx.y(), Real(0.3), 1e-6);
  EXPECT_EQ(projectPlaneCollision(Vec3(0, Real(-0.2), 0), 0, floor, Real(0.1)), Vec3::Zero());
}

}  // namespace
}  // namespace hs::pbd
