// Neighbour search for particle fluids: grid build (counting sort) plus all CSR neighbour lists,
// for random clouds at a PBF-like density (~30 neighbours per particle within the support).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "pbd/grid/neighbour_grid.h"

namespace hs::pbd {
namespace {

void BM_NeighbourGridBuildAndQuery(benchmark::State& state) {
  const auto n = std::size_t(state.range(0));
  const int threads = int(state.range(1));
  const Real h = 1;
  // Box side for ~30 neighbours: n * (4/3 pi h^3) / L^3 = 30.
  const double side = std::cbrt(double(n) * 4.18879 / 30.0);
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(0, side);
  std::vector<Vec3> x(n);
  for (auto& p : x) p = Vec3(Real(u(rng)), Real(u(rng)), Real(u(rng)));
  applyOrder(x, mortonOrder(x, h));  // as the solver would after periodic reordering

  NeighbourGridSettings settings;
  settings.threads = threads;
  NeighbourGrid grid(settings);
  NeighbourLists lists;
  for (auto _ : state) {
    grid.build(x, h);
    grid.buildNeighbourLists(x, h, lists);
    benchmark::DoNotOptimize(lists.indices.data());
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(n));
  state.counters["neighbours/particle"] = double(lists.indices.size()) / double(n);
}
BENCHMARK(BM_NeighbourGridBuildAndQuery)
    ->Args({10000, 1})
    ->Args({100000, 1})
    ->Args({100000, 2})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace hs::pbd
