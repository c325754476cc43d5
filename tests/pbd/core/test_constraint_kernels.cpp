// Every kernel's gradient against central finite differences, and one projection zeroes the
// linearised constraint and reduces |C|.
#include <gtest/gtest.h>

#include <random>

#include "pbd/core/constraints.h"

namespace hs::pbd {
namespace {

// The kernels as functions of an array of points, so one checker serves them all.
template <std::size_t N>
struct Eval {
  Real value;
  std::array<Vec3, N> gradient;
};
template <std::size_t N>
struct Corr {
  std::array<Vec3, N> dx;
};

Eval<4> tet(const std::array<Vec3, 4>& x, Real rest) {
  const TetVolumeEval c = evaluateTetVolume(x[0], x[1], x[2], x[3], rest);
  return {c.value, {c.g0, c.g1, c.g2, c.g3}};
}
Eval<3> tri(const std::array<Vec3, 3>& x, Real rest) {
  const TriangleAreaEval c = evaluateTriangleArea(x[0], x[1], x[2], rest);
  return {c.value, {c.g0, c.g1, c.g2}};
}
Eval<2> dist(const std::array<Vec3, 2>& x, Real rest) {
  const DistanceEval c = evaluateDistance(x[0], x[1], rest);
  return {c.value, {c.g0, c.g1}};
}
Corr<4> tetProject(const std::array<Vec3, 4>& x, const std::array<Real, 4>& w, Real rest, ProjectionParams p) {
  const Correction4 r = projectTetVolume(x[0], x[1], x[2], x[3], w[0], w[1], w[2], w[3], rest, p, 0);
  return {{r.dx0, r.dx1, r.dx2, r.dx3}};
}
Corr<3> triProject(const std::array<Vec3, 3>& x, const std::array<Real, 3>& w, Real rest, ProjectionParams p) {
  const Correction3 r = projectTriangleArea(x[0], x[1], x[2], w[0], w[1], w[2], rest, p, 0);
  return {{r.dx0, r.dx1, r.dx2}};
}
Corr<2> distProject(const std::array<Vec3, 2>& x, const std::array<Real, 2>& w, Real rest, ProjectionParams p) {
  const Correction2 r = projectDistance(x[0], x[1], w[0], w[1], rest, p, 0);
  return {{r.dx0, r.dx1}};
}

template <std::size_t N>
std::array<Vec3, N> randomPoints(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::array<Vec3, N> x;
  for (auto& p : x) p = Vec3(Real(u(rng)), Real(u(rng)), Real(u(rng)));
  return x;
}

// Central differences of C with step h; compares with the analytic gradient.
template <std::size_t N, class EvalFn>
void expectGradientMatchesFiniteDifferences(const std::array<Vec3, N>& x, EvalFn eval) {
  const Eval<N> analytic = eval(x);
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
      EXPECT_NEAR(analytic.gradient[i][d], numeric, tolerance * scale) << "particle " << i << " axis " << d;
    }
  }
}

TEST(ConstraintKernels, TetVolumeGradientMatchesFiniteDifferences) {
  std::mt19937 rng(1);
  for (int trial = 0; trial < 50; ++trial)
    expectGradientMatchesFiniteDifferences<4>(randomPoints<4>(rng), [](const auto& x) { return tet(x, Real(0.1)); });
}

TEST(ConstraintKernels, TriangleAreaGradientMatchesFiniteDifferences) {
  std::mt19937 rng(2);
  for (int trial = 0; trial < 50; ++trial)
    expectGradientMatchesFiniteDifferences<3>(randomPoints<3>(rng), [](const auto& x) { return tri(x, Real(0.2)); });
}

TEST(ConstraintKernels, DistanceGradientMatchesFiniteDifferences) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 50; ++trial)
    expectGradientMatchesFiniteDifferences<2>(randomPoints<2>(rng), [](const auto& x) { return dist(x, Real(0.5)); });
}

TEST(ConstraintKernels, PlaneGradientMatchesFiniteDifferences) {
  std::mt19937 rng(4);
  const Plane plane{Vec3(1, 2, 2).normalized(), Real(0.3)};
  for (int trial = 0; trial < 20; ++trial) {
    expectGradientMatchesFiniteDifferences<1>(randomPoints<1>(rng), [&](const auto& x) {
      return Eval<1>{evaluatePlaneCollision(x[0], plane, Real(0.05)), {plane.normal}};
    });
  }
}

TEST(ConstraintKernels, TetVolumeValueIsSignedVolumeMinusRest) {
  const std::array<Vec3, 4> x{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  EXPECT_NEAR(tet(x, 0).value, Real(1.0 / 6.0), Real(1e-7));
  EXPECT_NEAR(tet({x[0], x[2], x[1], x[3]}, 0).value, Real(-1.0 / 6.0), Real(1e-7));
}

// A full-stiffness, zero-compliance projection zeroes the linearised constraint
// (thesis eq. 3.1: C + grad C . dx = 0) and, for these smooth constraints, reduces |C|.
template <std::size_t N, class EvalFn, class ProjectFn>
void expectProjectionReducesViolation(std::array<Vec3, N> x, const std::array<Real, N>& w, EvalFn eval,
                                      ProjectFn project) {
  const Eval<N> c = eval(x);
  const Real before = std::abs(c.value);
  ASSERT_GT(before, Real(1e-3));
  const Corr<N> r = project(x, w, ProjectionParams{0, 1});
  Real linearised = c.value;
  for (std::size_t i = 0; i < N; ++i) linearised += c.gradient[i].dot(r.dx[i]);
  EXPECT_NEAR(linearised, 0, 1e-5 * std::max(Real(1), before));
  for (std::size_t i = 0; i < N; ++i) x[i] += r.dx[i];
  EXPECT_LT(std::abs(eval(x).value), before);
}

TEST(ConstraintKernels, OneProjectionReducesViolation) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    expectProjectionReducesViolation<4>(
        randomPoints<4>(rng), {1, 2, Real(0.5), 1}, [](const auto& x) { return tet(x, Real(0.05)); },
        [](const auto& x, const auto& w, ProjectionParams p) { return tetProject(x, w, Real(0.05), p); });
    expectProjectionReducesViolation<3>(
        randomPoints<3>(rng), {1, 1, 3}, [](const auto& x) { return tri(x, Real(0.3)); },
        [](const auto& x, const auto& w, ProjectionParams p) { return triProject(x, w, Real(0.3), p); });
    expectProjectionReducesViolation<2>(
        randomPoints<2>(rng), {1, Real(0.25)}, [](const auto& x) { return dist(x, Real(0.4)); },
        [](const auto& x, const auto& w, ProjectionParams p) { return distProject(x, w, Real(0.4), p); });
  }
}

// The fused projections use algebraic shortcuts; they must equal the textbook XPBD step
// dx_i = w_i grad_i C dLambda built from the evaluated gradient.
template <std::size_t N>
void expectEqualsTextbookStep(const Eval<N>& c, const std::array<Real, N>& w, const Corr<N>& fused,
                              Real fusedDeltaLambda, ProjectionParams params, Real lambda) {
  Real gradientNorm = 0;
  for (std::size_t i = 0; i < N; ++i) gradientNorm += w[i] * c.gradient[i].squaredNorm();
  const Real dl = xpbdDeltaLambda(c.value, gradientNorm, params, lambda);
  EXPECT_NEAR(fusedDeltaLambda, dl, Real(1e-4) * std::max(Real(1), std::abs(dl)));
  for (std::size_t i = 0; i < N; ++i) {
    const Vec3 expected = (w[i] * dl) * c.gradient[i];
    EXPECT_LE((fused.dx[i] - expected).norm(), Real(1e-4) * std::max(Real(1e-3), expected.norm())) << i;
  }
}

TEST(ConstraintKernels, FusedProjectionsEqualTheTextbookStep) {
  std::mt19937 rng(6);
  const ProjectionParams params{Real(0.3), Real(0.7)};
  for (int trial = 0; trial < 50; ++trial) {
    const auto x3 = randomPoints<3>(rng);
    const std::array<Real, 3> w3{1, Real(0.5), 2};
    const Correction3 t = projectTriangleArea(x3[0], x3[1], x3[2], w3[0], w3[1], w3[2], Real(0.2), params, Real(0.1));
    expectEqualsTextbookStep<3>(tri(x3, Real(0.2)), w3, {{t.dx0, t.dx1, t.dx2}}, t.deltaLambda, params, Real(0.1));
    const auto x2 = randomPoints<2>(rng);
    const std::array<Real, 2> w2{Real(0.25), 1};
    const Correction2 d = projectDistance(x2[0], x2[1], w2[0], w2[1], Real(0.5), params, Real(0.1));
    expectEqualsTextbookStep<2>(dist(x2, Real(0.5)), w2, {{d.dx0, d.dx1}}, d.deltaLambda, params, Real(0.1));
    const auto x4 = randomPoints<4>(rng);
    const std::array<Real, 4> w4{1, 2, Real(0.5), 1};
    const Correction4 v = projectTetVolume(x4[0], x4[1], x4[2], x4[3], w4[0], w4[1], w4[2], w4[3], Real(0.05), params, Real(0.1));
    expectEqualsTextbookStep<4>(tet(x4, Real(0.05)), w4, {{v.dx0, v.dx1, v.dx2, v.dx3}}, v.deltaLambda, params, Real(0.1));
  }
}

TEST(ConstraintKernels, PinnedParticlesDoNotMoveAndMomentumIsKept) {
  const Vec3 a(0, 0, 0), b(2, 0, 0);
  const Correction2 pinned = projectDistance(a, b, 0, 1, 1, ProjectionParams{0, 1}, 0);
  EXPECT_EQ(pinned.dx0, Vec3::Zero());
  EXPECT_NEAR(pinned.dx1.x(), -1, 1e-6);
  // Equal masses: corrections are equal and opposite (no net momentum change).
  const Correction2 both = projectDistance(a, b, 1, 1, 1, ProjectionParams{0, 1}, 0);
  EXPECT_NEAR((both.dx0 + both.dx1).norm(), 0, 1e-7);
  const std::array<Vec3, 4> x{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  const Correction4 t = projectTetVolume(x[0], x[1], x[2], x[3], 1, 1, 1, 1, Real(0.3), ProjectionParams{0, 1}, 0);
  EXPECT_NEAR((t.dx0 + t.dx1 + t.dx2 + t.dx3).norm(), 0, 1e-6);
}

TEST(ConstraintKernels, StiffnessScalesThePbdCorrection) {
  const Vec3 a(0, 0, 0), b(2, 0, 0);
  const Correction2 full = projectDistance(a, b, 1, 1, 1, ProjectionParams{0, 1}, 0);
  const Correction2 half = projectDistance(a, b, 1, 1, 1, ProjectionParams{0, Real(0.5)}, 0);
  EXPECT_NEAR(half.dx1.x(), Real(0.5) * full.dx1.x(), 1e-7);
}

TEST(ConstraintKernels, ComplianceSoftensAndLambdaAccumulates) {
  // XPBD with compliance alpha: after converging, C = -alphaTilde * lambda (a spring).
  Vec3 a(0, 0, 0), b(2, 0, 0);
  const ProjectionParams params{Real(1), Real(1)};
  Real lambda = 0;
  for (int i = 0; i < 100; ++i) {
    const Correction2 r = projectDistance(a, b, 0, 1, 1, params, lambda);
    lambda += r.deltaLambda;
    b += r.dx1;
  }
  const Real c = evaluateDistance(a, b, 1).value;
  EXPECT_NEAR(c, -params.alphaTilde * lambda, 1e-5);
  EXPECT_NEAR(c, Real(0.5), 1e-4);  // w = 1, alphaTilde = 1: half of the violation remains
}

TEST(ConstraintKernels, DegenerateConfigurationsDoNotMove) {
  const Vec3 p(1, 1, 1);
  const Correction3 collapsed = projectTriangleArea(p, p, p, 1, 1, 1, Real(0.5), ProjectionParams{0, 1}, 0);
  EXPECT_TRUE(collapsed.dx0.allFinite());
  EXPECT_EQ(collapsed.dx1, Vec3::Zero());
  const Correction2 allPinned = projectDistance(Vec3::Zero(), Vec3::UnitX(), 0, 0, 2, ProjectionParams{0, 1}, 0);
  EXPECT_EQ(allPinned.dx1, Vec3::Zero());
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
