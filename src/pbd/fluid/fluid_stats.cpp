#include "pbd/fluid/fluid_stats.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "pbd/fluid/sph_kernels.h"
#include "pbd/grid/neighbour_grid.h"

namespace hs::pbd {

Index latticeNeighbourCount(Real supportRadius, Real spacing) {
  const int reach = int(std::ceil(supportRadius / spacing)) + 1;
  const Real h2 = supportRadius * supportRadius;
  Index count = 0;
  for (int k = -reach; k <= reach; ++k)
    for (int j = -reach; j <= reach; ++j)
      for (int i = -reach; i <= reach; ++i) {
        if (i == 0 && j == 0 && k == 0) continue;
        if ((spacing * Vec3(Real(i), Real(j), Real(k))).squaredNorm() < h2) ++count;
      }
  return count;
}

FluidStats measureFluid(const Particles& particles, const FluidSettings& fluid, Real spacing, int threads) {
  std::vector<Index> indices;
  std::vector<Vec3> x;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (particles.kind[i] != ParticleKind::Fluid) continue;
    indices.push_back(Index(i));
    x.push_back(particles.position[i]);
  }
  if (x.empty()) return measureDensityOnLists({}, NeighbourLists{}, fluid, spacing, threads);
  // A grid of their own, in cell order like the solver's: the statistics are sums over
  // particles and do not depend on their order but for rounding.
  NeighbourGridSettings gridSettings;
  gridSettings.threads = threads;
  NeighbourGrid grid(gridSettings);
  grid.build(x, fluid.supportRadius);
  NeighbourLists lists;
  grid.buildSlotNeighbourLists(fluid.supportRadius, lists);
  FluidStats stats = measureDensityOnLists(grid.sortedPositions(), lists, fluid, spacing, threads);
  for (const Index i : indices) stats.maxSpeed = std::max(stats.maxSpeed, particles.velocity[i].norm());
  return stats;
}

FluidStats measureDensityOnLists(const std::vector<Vec3>& positions, const NeighbourLists& lists,
                                 const FluidSettings& fluid, Real spacing, int threads) {
  FluidStats stats;
  stats.fluidCount = positions.size();
  // 90% of an interior lattice particle's neighbours, rounded up.
  stats.fullThreshold = Index(std::ceil(Real(0.9) * Real(latticeNeighbourCount(fluid.supportRadius, spacing))));
  if (positions.empty()) return stats;
  std::vector<Index> all(positions.size());
  std::iota(all.begin(), all.end(), Index(0));
  std::vector<Real> density;
  computeDensities(positions, lists, all, makeSphKernels(fluid.supportRadius), fluid, density, threads);
  double sumAbs = 0, sumSigned = 0;
  for (std::size_t s = 0; s < positions.size(); ++s) {
    if (lists.offsets[s + 1] - lists.offsets[s] < stats.fullThreshold) continue;
    const Real c = density[s] / fluid.restDensity - Real(1);
    ++stats.fullCount;
    sumAbs += double(std::abs(c));
    sumSigned += double(c);
    stats.densityErrorMax = std::max(stats.densityErrorMax, std::abs(c));
  }
  stats.meanNeighbours = Real(double(lists.indices.size()) / double(positions.size()));
  if (stats.fullCount > 0) {
    stats.densityErrorMean = Real(sumAbs / double(stats.fullCount));
    stats.densitySignedMean = Real(sumSigned / double(stats.fullCount));
  }
  return stats;
}

}  // namespace hs::pbd
