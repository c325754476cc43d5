#include "pbd/fluid/velocity_field.h"

#include <cassert>

#include "pbd/fluid/fluid_loops.h"

namespace hs::pbd {
namespace {

// A~_i from the sums of V_j W_ij A_j and V_j W_ij; the particle's own value when nothing
// weighs (a parked particle, volume 0, alone).
template <class Value>
inline Value shepard(const Value& weighted, Real weight, const Value& own) {
  return weight > Real(0) ? Value(weighted / weight) : own;
}

}  // namespace

template <class Value>
void shepardAverage(const std::vector<Vec3>& positions, const std::vector<Value>& values,
                    const std::vector<Real>& volumes, const NeighbourLists& lists, std::span<const Index> subset,
                    const SphKernels& kernels, std::vector<Value>& smoothed, int threads) {
  assert(lists.offsets.size() == positions.size() + 1);
  assert(values.size() == positions.size() && volumes.size() == positions.size());
  if (smoothed.size() < positions.size()) smoothed.resize(positions.size(), Value::Zero());
  const Real selfKernel = poly6(kernels, Real(0));
  const auto count = std::ptrdiff_t(subset.size());
  // Chunks as threads free up: slots come in cell order with runs of neighbourless parked blood.
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads) if (count >= kFluidParallelThreshold)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Index i = subset[std::size_t(s)];
    const Vec3& xi = positions[i];
    // Self term first, then the neighbours in list order (a fixed order for any thread count).
    Real weight = volumes[i] * selfKernel;
    Value weighted = weight * values[i];
    for (Index k = lists.offsets[i]; k < lists.offsets[i + 1]; ++k) {
      const Index j = lists.indices[k];
      const Real w = volumes[j] * poly6(kernels, (xi - positions[j]).squaredNorm());
      weighted += w * values[j];
      weight += w;
    }
    smoothed[i] = shepard(weighted, weight, values[i]);
  }
}

template void shepardAverage<Vec3>(const std::vector<Vec3>&, const std::vector<Vec3>&, const std::vector<Real>&,
                                   const NeighbourLists&, std::span<const Index>, const SphKernels&,
                                   std::vector<Vec3>&, int);
template void shepardAverage<FieldVec4>(const std::vector<Vec3>&, const std::vector<FieldVec4>&,
                                        const std::vector<Real>&, const NeighbourLists&, std::span<const Index>,
                                        const SphKernels&, std::vector<FieldVec4>&, int);

std::vector<Vec3> smoothVelocitiesBruteForce(const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities,
                                             const std::vector<Real>& volumes, const SphKernels& kernels) {
  std::vector<Vec3> smoothed(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    Real weight = 0;
    Vec3 weighted = Vec3::Zero();
    for (std::size_t j = 0; j < positions.size(); ++j) {
      const Real w = volumes[j] * poly6(kernels, (positions[i] - positions[j]).squaredNorm());
      weighted += w * velocities[j];
      weight += w;
    }
    smoothed[i] = shepard(weighted, weight, velocities[i]);
  }
  return smoothed;
}

}  // namespace hs::pbd
