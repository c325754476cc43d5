// Micro-benchmarks of each constraint kernel and of one solver iteration on a tet box.
#include <benchmark/benchmark.h>

#include <random>

#include "../tests/pbd/box_mesh.h"
#include "pbd/constraints.h"
#include "pbd/soft_body.h"
#include "pbd/solver.h"

namespace hs::pbd {
namespace {

template <std::size_t N>
std::array<Vec3, N> randomPoints(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1, 1);
  std::array<Vec3, N> x;
  for (auto& p : x) p = Vec3(Real(u(rng)), Real(u(rng)), Real(u(rng)));
  return x;
}

void BM_TetVolumeProjection(benchmark::State& state) {
  auto x = randomPoints<4>(1);
  for (auto _ : state) {
    const Correction4 r = projectTetVolume(x[0], x[1], x[2], x[3], 1, 1, 1, 1, Real(0.1), ProjectionParams{0, Real(0.5)}, 0);
    x[0] += Real(1e-3) * r.dx0;
    x[1] += Real(1e-3) * r.dx1;
    x[2] += Real(1e-3) * r.dx2;
    x[3] += Real(1e-3) * r.dx3;
    benchmark::DoNotOptimize(x);
  }
}
BENCHMARK(BM_TetVolumeProjection);

void BM_TriangleAreaProjection(benchmark::State& state) {
  auto x = randomPoints<3>(2);
  for (auto _ : state) {
    const Correction3 r = projectTriangleArea(x[0], x[1], x[2], 1, 1, 1, Real(0.2), ProjectionParams{0, Real(0.5)}, 0);
    x[0] += Real(1e-3) * r.dx0;
    x[1] += Real(1e-3) * r.dx1;
    x[2] += Real(1e-3) * r.dx2;
    benchmark::DoNotOptimize(x);
  }
}
BENCHMARK(BM_TriangleAreaProjection);

void BM_DistanceProjection(benchmark::State& state) {
  auto x = randomPoints<2>(3);
  for (auto _ : state) {
    const Correction2 r = projectDistance(x[0], x[1], 1, 1, Real(0.5), ProjectionParams{0, Real(0.5)}, 0);
    x[0] += Real(1e-3) * r.dx0;
    x[1] += Real(1e-3) * r.dx1;
    benchmark::DoNotOptimize(x);
  }
}
BENCHMARK(BM_DistanceProjection);

void BM_PlaneCollision(benchmark::State& state) {
  Vec3 x(0, Real(-0.1), 0);
  const Plane floor{Vec3::UnitY(), 0};
  for (auto _ : state) {
    benchmark::DoNotOptimize(projectPlaneCollision(x, 1, floor, Real(0.05)));
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_PlaneCollision);

// One solver step (10 iterations) on an n^3-cube box: per-step cost of a soft body.
void BM_SoftBodyStep(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  Particles particles;
  ConstraintSet constraints;
  const TetMesh mesh = testing::makeBoxMesh(n, Real(0.1));
  addSoftBody(particles, constraints, mesh, boundaryFaces(mesh.tets), SoftBodySettings{});
  for (std::size_t i = 0; i < particles.size(); ++i)
    if (particles.position[i].y() == Real(0)) particles.inverseMass[i] = 0;
  finalizeConstraints(constraints, particles.position);
  SolverSettings settings;
  const StepContext context = makeStepContext(Real(0.005), Vec3(0, Real(-9.81), 0), threads);
  for (auto _ : state) step(constraints, particles, settings, context);
  state.counters["tets"] = double(mesh.tets.size());
  state.counters["tets_per_s"] = benchmark::Counter(double(mesh.tets.size()) * settings.iterations,
                                                    benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_SoftBodyStep)->Args({6, 1})->Args({6, 2})->Args({16, 1})->Args({16, 2})->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace hs::pbd

BENCHMARK_MAIN();
