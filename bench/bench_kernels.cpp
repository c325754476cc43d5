// Micro-benchmarks of each constraint kernel and of one solver iteration on a tet box.
#include <benchmark/benchmark.h>

#include <numeric>
#include <random>

#include "../tests/pbd/box_mesh.h"
#include "pbd/core/constraints.h"
#include "pbd/core/soft_body.h"
#include "pbd/core/solver.h"
#include "pbd/fluid/fluid.h"

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

// The fluid's neighbour loops on a block of 16^3 = 4,096 particles (the size of the `normal`
// scenario's blood) at spacing d, h = 2d, jittered by 2% of d: about 30 neighbours each, as
// the blood has when compressed. Argument: 0 = scalar reference kernels, 1 = SIMD (fluid_simd.cpp).
struct FluidBlock {
  std::vector<Vec3> x, v;
  NeighbourLists lists;
  std::vector<Index> all;
  SphKernels kernels = makeSphKernels(Real(0.32));
  FluidSettings settings;
  std::vector<Real> density, lambda, pairGradient;
  std::vector<Vec3> dp, vNew;

  explicit FluidBlock(FluidKernelPath path) {
    const Real d = Real(0.16);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> jitter(-0.02f, 0.02f);
    for (int k = 0; k < 16; ++k)
      for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i) {
          x.push_back(d * Vec3(Real(i), Real(j), Real(k)) + d * Vec3(jitter(rng), jitter(rng), jitter(rng)));
          v.push_back(Vec3(jitter(rng), jitter(rng), jitter(rng)));
        }
    NeighbourGrid grid;
    grid.build(x, kernels.h);
    grid.buildNeighbourLists(x, kernels.h, lists);
    all.resize(x.size());
    std::iota(all.begin(), all.end(), Index(0));
    settings.particleMass = particleMassFor(settings.restDensity, d);
    settings.supportRadius = kernels.h;
    settings.kinematicViscosity = Real(0.003);
    settings.kernelPath = path;
    computeLambdas(x, lists, all, kernels, settings, density, lambda, 1, &pairGradient);
  }
  FluidKernelPath path() const { return settings.kernelPath; }
};

FluidKernelPath pathOf(const benchmark::State& state) {
  return state.range(0) == 0 ? FluidKernelPath::Scalar : FluidKernelPath::Simd;
}

void countParticles(benchmark::State& state, const FluidBlock& block) {
  state.SetLabel(state.range(0) == 0 ? "scalar" : "simd");
  state.counters["particles_per_s"] =
      benchmark::Counter(double(block.x.size()), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["pairs"] = double(block.lists.indices.size());
}

// rho_i, lambda_i and the pair-gradient cache (PBF eq. 2, 8, 11), one thread.
void BM_FluidLambdas(benchmark::State& state) {
  FluidBlock block(pathOf(state));
  for (auto _ : state) {
    computeLambdas(block.x, block.lists, block.all, block.kernels, block.settings, block.density, block.lambda, 1,
                   &block.pairGradient);
    benchmark::DoNotOptimize(block.lambda.data());
  }
  countParticles(state, block);
}
BENCHMARK(BM_FluidLambdas)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// dp_i (PBF eq. 12) from the cached pair gradients, as the solver calls it, one thread.
void BM_FluidCorrections(benchmark::State& state) {
  FluidBlock block(pathOf(state));
  for (auto _ : state) {
    computeDensityCorrections(block.x, block.lists, block.all, block.kernels, block.settings, block.lambda, block.dp,
                              1, &block.pairGradient);
    benchmark::DoNotOptimize(block.dp.data());
  }
  countParticles(state, block);
}
BENCHMARK(BM_FluidCorrections)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// XSPH and the Laplacian viscosity (PBF eq. 17, Monaghan 2005 eq. 6.13), one thread.
void BM_FluidViscosity(benchmark::State& state) {
  FluidBlock block(pathOf(state));
  for (auto _ : state) {
    applyViscosity(block.x, block.v, block.lists, block.all, block.kernels, block.settings, Real(0.005), block.vNew, 1);
    benchmark::DoNotOptimize(block.vNew.data());
  }
  countParticles(state, block);
}
BENCHMARK(BM_FluidViscosity)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace hs::pbd

BENCHMARK_MAIN();
