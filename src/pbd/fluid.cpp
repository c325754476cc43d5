// Position Based Fluids (Macklin & Mueller 2013), see fluid.h for the equations and the
// determinism contract: every loop is a gather over the CSR neighbour lists.
#include "pbd/fluid.h"

#include <cassert>
#include <cmath>

namespace hs::pbd {
namespace {

// Outputs cover every particle index; entries outside the subset keep their values.
template <class T>
void fitOutput(std::vector<T>& out, std::size_t n) {
  if (out.size() != n) out.resize(n);
}

void checkInputs([[maybe_unused]] const std::vector<Vec3>& positions,
                 [[maybe_unused]] const NeighbourLists& lists,
                 [[maybe_unused]] const SphKernels& kernels,
                 [[maybe_unused]] const FluidSettings& settings) {
  assert(lists.offsets.size() == positions.size() + 1);
  assert(kernels.h == settings.supportRadius);
}

// s_corr = -k (W_poly6(r)/W_poly6(deltaQ))^n (PBF eq. 13), with invWq = 1/W_poly6(deltaQ).
Real tensileCorrection(const SphKernels& kernels, const FluidSettings& settings, Real invWq, Real r2) {
  const Real ratio = poly6(kernels, r2) * invWq;
  Real power = 1;
  for (int e = 0; e < settings.tensileN; ++e) power *= ratio;
  return -settings.tensileK * power;
}

}  // namespace

void computeDensities(const std::vector<Vec3>& positions, const NeighbourLists& lists,
                      std::span<const Index> subset, const SphKernels& kernels,
                      const FluidSettings& settings, std::vector<Real>& densities, int threads) {
  checkInputs(positions, lists, kernels, settings);
  fitOutput(densities, positions.size());
  const Real m = settings.particleMass;
  const Real selfTerm = poly6(kernels, Real(0));
  const std::ptrdiff_t count = std::ptrdiff_t(subset.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Index i = subset[std::size_t(s)];
    const Vec3& xi = positions[i];
    // rho_i = m sum_j W(x_i - x_j) (PBF eq. 2), self term first.
    Real sum = selfTerm;
    for (Index k = lists.offsets[i]; k < lists.offsets[i + 1]; ++k) {
      const Index j = lists.indices[k];
      const Vec3 r = xi - positions[j];
      sum += poly6(kernels, r.squaredNorm());
    }
    densities[i] = m * sum;
  }
}

void computeDensityConstraints(const std::vector<Real>& densities, std::span<const Index> subset,
                               const FluidSettings& settings, std::vector<Real>& constraints,
                               int threads) {
  fitOutput(constraints, densities.size());
  const Real invRho0 = Real(1) / settings.restDensity;
  const std::ptrdiff_t count = std::ptrdiff_t(subset.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Index i = subset[std::size_t(s)];
    constraints[i] = densities[i] * invRho0 - Real(1);  // C_i = rho_i/rho0 - 1 (PBF eq. 1)
  }
}

void computeLambdas(const std::vector<Vec3>& positions, const NeighbourLists& lists,
                    std::span<const Index> subset, const SphKernels& kernels,
                    const FluidSettings& settings, const std::vector<Real>& densities,
                    std::vector<Real>& lambdas, int threads) {
  checkInputs(positions, lists, kernels, settings);
  assert(densities.size() == positions.size());
  fitOutput(lambdas, positions.size());
  const Real invRho0 = Real(1) / settings.restDensity;
  const Real gradScale = settings.particleMass * invRho0;  // m/rho0, see fluid.h
  const std::ptrdiff_t count = std::ptrdiff_t(subset.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Index i = subset[std::size_t(s)];
    const Vec3& xi = positions[i];
    // PBF eq. 8: grad_{p_i} C_i = (m/rho0) sum_j grad W_ij, grad_{p_j} C_i = -(m/rho0) grad W_ij.
    Vec3 gradI = Vec3::Zero();
    Real sumSqJ = 0;
    for (Index k = lists.offsets[i]; k < lists.offsets[i + 1]; ++k) {
      const Index j = lists.indices[k];
      const Vec3 r = xi - positions[j];
      const Vec3 g = gradScale * spikyGradient(kernels, r, r.norm());
      gradI += g;
      sumSqJ += g.squaredNorm();
    }
    const Real c = densities[i] * invRho0 - Real(1);  // PBF eq. 1
    // PBF eq. 11: lambda_i = -C_i / (sum_k |grad_{p_k} C_i|^2 + eps).
    lambdas[i] = -c / (gradI.squaredNorm() + sumSqJ + settings.relaxation);
  }
}

void computeDensityCorrections(const std::vector<Vec3>& positions, const NeighbourLists& lists,
                               std::span<const Index> subset, const SphKernels& kernels,
                               const FluidSettings& settings, const std::vector<Real>& lambdas,
                               std::vector<Vec3>& corrections, int threads) {
  checkInputs(positions, lists, kernels, settings);
  assert(lambdas.size() == positions.size());
  fitOutput(corrections, positions.size());
  const Real scale = settings.particleMass / settings.restDensity;  // m/rho0, see fluid.h
  const bool tensile = settings.tensileCorrection;
  const Real deltaQ = settings.tensileDeltaQRatio * kernels.h;
  const Real wq = poly6(kernels, deltaQ * deltaQ);
  const Real invWq = wq > Real(0) ? Real(1) / wq : Real(0);
  const std::ptrdiff_t count = std::ptrdiff_t(subset.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Index i = subset[std::size_t(s)];
    const Vec3& xi = positions[i];
    const Real li = lambdas[i];
    // PBF eq. 12: dp_i = (m/rho0) sum_j (lambda_i + lambda_j + s_corr) grad W(p_i - p_j).
    Vec3 sum = Vec3::Zero();
    for (Index k = lists.offsets[i]; k < lists.offsets[i + 1]; ++k) {
      const Index j = lists.indices[k];
      const Vec3 r = xi - positions[j];
      const Real r2 = r.squaredNorm();
      Real weight = li + lambdas[j];
      if (tensile) weight += tensileCorrection(kernels, settings, invWq, r2);
      sum += weight * spikyGradient(kernels, r, std::sqrt(r2));
    }
    corrections[i] = scale * sum;
  }
}

void applyXsphViscosity(const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities,
                        const NeighbourLists& lists, std::span<const Index> subset,
                        const SphKernels& kernels, const FluidSettings& settings,
                        std::vector<Vec3>& newVelocities, int threads) {
  checkInputs(positions, lists, kernels, settings);
  assert(velocities.size() == positions.size());
  assert(&velocities != &newVelocities);
  fitOutput(newVelocities, positions.size());
  const Real c = settings.xsphViscosity;
  const std::ptrdiff_t count = std::ptrdiff_t(subset.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Index i = subset[std::size_t(s)];
    const Vec3& xi = positions[i];
    const Vec3& vi = velocities[i];
    // PBF eq. 17: v_i <- v_i + c sum_j (v_j - v_i) W_poly6(x_i - x_j).
    Vec3 sum = Vec3::Zero();
    for (Index k = lists.offsets[i]; k < lists.offsets[i + 1]; ++k) {
      const Index j = lists.indices[k];
      const Vec3 r = xi - positions[j];
      sum += poly6(kernels, r.squaredNorm()) * (velocities[j] - vi);
    }
    newVelocities[i] = vi + c * sum;
  }
}

}  // namespace hs::pbd
