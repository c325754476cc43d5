#pragma once
// SIMD versions of the neighbour loops of fluid.h (Highway, fluid_simd.cpp), selected by
// FluidSettings::kernelPath = FluidKernelPath::Simd; the public functions of fluid.h call these.
// Same arguments, equations and contracts as there; only builds with HS_HAVE_HIGHWAY have them.
//
// Layout: a particle's neighbours are taken eight at a time, one lane each (kFluidSimdLanes),
// read by neighbour index with one 128-bit load per lane (x, y, z of the AoS Vec3 arrays, or
// x, y, z, lambda of a packed copy for the corrections) and a 4x4 transpose; measured faster
// than three gathers (bench_kernels; SoA copies would still need one gather per coordinate,
// as neighbour indices are scattered). Each lane keeps its own partial sums; after the list,
// the eight lanes are added in a fixed tree order (fluid_simd_lanes-inl.h). The lane count is
// fixed rather than the machine's vector width (an SSE4 machine runs two 4-lane vectors,
// AVX-512 a 256-bit one), and no operation is fused (the build has -ffp-contract=off, and no
// MulAdd is used), so every instruction set gives bitwise the same result.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "pbd/fluid/fluid.h"

namespace hs::pbd::simd {

inline constexpr std::size_t kFluidSimdLanes = 8;

void computeLambdas(const std::vector<Vec3>& positions, const NeighbourLists& lists,
                    std::span<const Index> subset, const SphKernels& kernels,
                    const FluidSettings& settings, std::vector<Real>& densities,
                    std::vector<Real>& lambdas, int threads, std::vector<Real>* pairGradients,
                    const WallDensityInput* walls);

void computeDensityCorrections(const std::vector<Vec3>& positions, const NeighbourLists& lists,
                               std::span<const Index> subset, const SphKernels& kernels,
                               const FluidSettings& settings, const std::vector<Real>& lambdas,
                               std::vector<Vec3>& corrections, int threads,
                               const std::vector<Real>* pairGradients, const WallDensityInput* walls);

void applyViscosity(const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities,
                    const NeighbourLists& lists, std::span<const Index> subset,
                    const SphKernels& kernels, const FluidSettings& settings, Real dt,
                    std::vector<Vec3>& newVelocities, int threads);

void applyVorticityConfinement(const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities,
                               const NeighbourLists& lists, std::span<const Index> subset,
                               const SphKernels& kernels, const FluidSettings& settings, Real dt,
                               std::vector<Vec3>& vorticity, std::vector<Vec3>& newVelocities,
                               int threads);

// Name of the instruction set the dispatch picks on this machine (e.g. "AVX2"), for benchmarks.
const char* targetName();

}  // namespace hs::pbd::simd
