// Position Based Fluids (Macklin & Mueller 2013), see fluid.h for the equations and the
// determinism contract: every loop is a gather over the CSR neighbour lists. These are the
// scalar reference kernels; FluidKernelPath::Simd hands the neighbour loops to fluid_simd.cpp,
// and both share their set-up and per-particle work (fluid_loops.h).
#include "pbd/fluid/fluid.h"

#include <cassert>
#include <cmath>

#include "pbd/fluid/fluid_loops.h"
#ifdef HS_HAVE_HIGHWAY
#include "pbd/fluid/fluid_simd.h"
#endif

namespace hs::pbd {
namespace {

constexpr std::ptrdiff_t kParallelThreshold = kFluidParallelThreshold;
// The neighbour loops hand out chunks of this many particles as threads free up (as the SIMD
// path cuts its blocks by neighbour pairs, fluid_simd.cpp): slots come in cell order with whole
// runs of neighbourless parked blood, so a static split leaves one thread most of the work.
// Each particle's result is its own, so the chunks change nothing but who computes what.

bool useSimd([[maybe_unused]] const FluidSettings& settings) {
#ifdef HS_HAVE_HIGHWAY
  return settings.kernelPath == FluidKernelPath::Simd;
#else
  return false;
#endif
}

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

// The walk of every loop below over the CSR neighbour list of i: pair(k, j, r, r2) for each
// neighbour j, k its slot in the lists (for per-pair caches), r = x_i - x_j, r2 = |r|^2.
template <class Pair>
HS_KERNEL void forNeighbours(const Vec3* positions, const ListView& lists, Index i, const Pair& pair) {
  const Vec3& xi = positions[i];
  for (Index k = lists.offsets[i]; k < lists.offsets[i + 1]; ++k) {
    const Index j = lists.indices[k];
    const Vec3 r = xi - positions[j];
    pair(k, j, r, r.squaredNorm());
  }
}

// s with grad W_spiky(r_ij) = s r_ij, without branches (the kernels of sph_kernels.h branch
// on r >= h and r = 0): s = -45/(pi h^4) (1 - r/h)^2 / r, with q = 1 - r/h clamped to 0
// beyond h, and r clamped below at 1e-6 h so that s stays finite (r_ij = 0 then gives a zero
// gradient, as spikyGradient does; pairs closer than 1e-6 h get a slightly smaller one).
// Exactly 0 for r^2 >= h^2: the clamp of q alone is not exact there, since r/h may round to
// just under 1 (for about one h in five).
HS_KERNEL Real spikyGradientScale(const SphKernels& k, Real r2) {
  const Real r = std::sqrt(r2);
  const Real q = std::max(Real(0), Real(1) - r * k.invH);
  const Real s = k.spikyGradCoeff * q * q / std::max(r, Real(1e-6) * k.h);
  return r2 < k.h2 ? s : Real(0);
}

// W_poly6 from r^2, clamped to 0 beyond h without a branch (exactly 0 for r^2 >= h^2, as above).
HS_KERNEL Real poly6Clamped(const SphKernels& k, Real r2) {
  const Real t = std::max(Real(0), Real(1) - r2 * k.invH2);
  const Real w = k.poly6Coeff * (t * t * t);
  return r2 < k.h2 ? w : Real(0);
}

}  // namespace

Real latticeGradientSum(const SphKernels& kernels, Real spacing, Real mass, Real restDensity) {
  // Same sums as computeLambdas, over the lattice offsets inside the support.
  const int reach = int(std::ceil(kernels.h / spacing));
  const Real scale = mass / restDensity;
  Vec3 gradI = Vec3::Zero();
  Real sumSqJ = 0;
  for (int k = -reach; k <= reach; ++k)
    for (int j = -reach; j <= reach; ++j)
      for (int i = -reach; i <= reach; ++i) {
        const Vec3 r = -spacing * Vec3(Real(i), Real(j), Real(k));
        const Vec3 g = scale * spikyGradient(kernels, r, r.norm());
        gradI += g;
        sumSqJ += g.squaredNorm();
      }
  return gradI.squaredNorm() + sumSqJ;
}

void computeDensities(const std::vector<Vec3>& positions, const NeighbourLists& lists,
                      std::span<const Index> subset, const SphKernels& kernels,
                      const FluidSettings& settings, std::vector<Real>& densities, int threads) {
  checkInputs(positions, lists, kernels, settings);
  fitOutput(densities, positions.size());
  const Real m = settings.particleMass;
  const Real selfTerm = poly6SelfTerm(kernels);
  const ListView view = viewOf(lists);
  const std::ptrdiff_t count = std::ptrdiff_t(subset.size());
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads) if (count >= kParallelThreshold)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Index i = subset[std::size_t(s)];
    // rho_i = m sum_j W(x_i - x_j) (PBF eq. 2), self term first.
    Real sum = selfTerm;
    forNeighbours(positions.data(), view, i, [&](Index, Index, const Vec3&, Real r2) { sum += poly6(kernels, r2); });
    densities[i] = m * sum;
  }
}

void computeDensityConstraints(const std::vector<Real>& densities, std::span<const Index> subset,
                               const FluidSettings& settings, std::vector<Real>& constraints,
                               int threads) {
  fitOutput(constraints, densities.size());
  const Real invRho0 = Real(1) / settings.restDensity;
  const std::ptrdiff_t count = std::ptrdiff_t(subset.size());
#pragma omp parallel for schedule(static) num_threads(threads) if (count >= kParallelThreshold)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Index i = subset[std::size_t(s)];
    constraints[i] = densities[i] * invRho0 - Real(1);  // C_i = rho_i/rho0 - 1 (PBF eq. 1)
  }
}

void computeLambdas(const std::vector<Vec3>& positions, const NeighbourLists& lists,
                    std::span<const Index> subset, const SphKernels& kernels,
                    const FluidSettings& settings, std::vector<Real>& densities,
                    std::vector<Real>& lambdas, int threads, std::vector<Real>* pairGradients,
                    const WallDensityInput* walls) {
#ifdef HS_HAVE_HIGHWAY
  if (useSimd(settings))
    return simd::computeLambdas(positions, lists, subset, kernels, settings, densities, lambdas, threads,
                                pairGradients, walls);
#endif
  const LambdaJob job =
      makeLambdaJob(positions, lists, subset, kernels, settings, densities, lambdas, pairGradients, walls);
  const std::ptrdiff_t count = std::ptrdiff_t(subset.size());
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads) if (count >= kParallelThreshold)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Index i = subset[std::size_t(s)];
    // PBF eq. 8: grad_{p_i} C_i = (m/rho0) sum_j grad W_ij, grad_{p_j} C_i = -(m/rho0) grad W_ij.
    // One loop for rho_i (PBF eq. 2, self term first) and the gradient sums.
    Real kernelSum = job.selfTerm;
    Vec3 gradI = Vec3::Zero();
    Real sumSqJ = 0;
    forNeighbours(job.positions, job.lists, i, [&](Index k, Index, const Vec3& r, Real r2) {
      kernelSum += poly6Clamped(kernels, r2);
      const Real gs = spikyGradientScale(kernels, r2);
      if (job.pairOut) job.pairOut[k] = gs;
      const Vec3 g = (job.gradScale * gs) * r;
      gradI += g;
      sumSqJ += g.squaredNorm();
    });
    finishLambda(job, i, kernelSum, gradI, sumSqJ);
  }
}

void computeDensityCorrections(const std::vector<Vec3>& positions, const NeighbourLists& lists,
                               std::span<const Index> subset, const SphKernels& kernels,
                               const FluidSettings& settings, const std::vector<Real>& lambdas,
                               std::vector<Vec3>& corrections, int threads,
                               const std::vector<Real>* pairGradients, const WallDensityInput* walls) {
#ifdef HS_HAVE_HIGHWAY
  if (useSimd(settings))
    return simd::computeDensityCorrections(positions, lists, subset, kernels, settings, lambdas, corrections,
                                           threads, pairGradients, walls);
#endif
  const CorrectionJob job =
      makeCorrectionJob(positions, lists, subset, kernels, settings, lambdas, corrections, pairGradients, walls);
  const Real contact2 = job.contact * job.contact;
  const std::ptrdiff_t count = std::ptrdiff_t(subset.size());
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads) if (count >= kParallelThreshold)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Index i = subset[std::size_t(s)];
    const Real li = job.lambdas[i];
    // PBF eq. 12: dp_i = (m/rho0) sum_j (lambda_i + lambda_j + s_corr) grad W(p_i - p_j).
    Vec3 sum = Vec3::Zero();
    Vec3 push = Vec3::Zero();
    forNeighbours(job.positions, job.lists, i, [&](Index k, Index j, const Vec3& r, Real r2) {
      Real weight = li + job.lambdas[j];
      if (job.tensile) {
        // s_corr = -k (W_poly6(r)/W_poly6(deltaQ))^n (PBF eq. 13).
        const Real ratio = poly6(kernels, r2) * job.invWq;
        Real power = 1;
        for (int e = 0; e < job.tensileN; ++e) power *= ratio;
        weight += -job.tensileK * power;
      }
      const Real gs = job.pairIn ? job.pairIn[k] : spikyGradientScale(kernels, r2);
      sum += (weight * gs) * r;
      // Thesis eq. 4.6: C = |x_ij| - 2r >= 0; equal masses move half the overlap each.
      if (job.collide && r2 < contact2 && r2 > Real(0)) {
        const Real d = std::sqrt(r2);
        push += (Real(0.5) * (job.contact - d) / d) * r;
      }
    });
    finishCorrection(job, i, li, sum, push);
  }
}

void applyViscosity(const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities,
                    const NeighbourLists& lists, std::span<const Index> subset,
                    const SphKernels& kernels, const FluidSettings& settings, Real dt,
                    std::vector<Vec3>& newVelocities, int threads) {
#ifdef HS_HAVE_HIGHWAY
  if (useSimd(settings))
    return simd::applyViscosity(positions, velocities, lists, subset, kernels, settings, dt, newVelocities, threads);
#endif
  const ViscosityJob job = makeViscosityJob(positions, velocities, lists, subset, kernels, settings, dt, newVelocities);
  const std::ptrdiff_t count = std::ptrdiff_t(subset.size());
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads) if (count >= kParallelThreshold)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Index i = subset[std::size_t(s)];
    const Vec3& vi = job.velocities[i];
    Vec3 xsph = Vec3::Zero();
    Vec3 viscous = Vec3::Zero();
    forNeighbours(job.positions, job.lists, i, [&](Index, Index j, const Vec3& r, Real r2) {
      const Vec3 vij = vi - job.velocities[j];
      // PBF eq. 17: c sum_j (v_j - v_i) W_poly6(x_i - x_j).
      xsph -= poly6(kernels, r2) * vij;
      // Monaghan 2005 eq. 6.13: (v_ij . x_ij)/(|x_ij|^2 + 0.01 h^2) grad W(x_ij).
      viscous += (vij.dot(r) / (r2 + job.softening)) * spikyGradient(kernels, r, std::sqrt(r2));
    });
    job.newVelocities[i] = vi + job.xsph * xsph + job.laplace * viscous;
  }
}

void applyVorticityConfinement(const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities,
                               const NeighbourLists& lists, std::span<const Index> subset,
                               const SphKernels& kernels, const FluidSettings& settings, Real dt,
                               std::vector<Vec3>& vorticity, std::vector<Vec3>& newVelocities,
                               int threads) {
#ifdef HS_HAVE_HIGHWAY
  if (useSimd(settings))
    return simd::applyVorticityConfinement(positions, velocities, lists, subset, kernels, settings, dt, vorticity,
                                           newVelocities, threads);
#endif
  const VorticityJob job =
      makeVorticityJob(positions, velocities, lists, subset, kernels, settings, dt, vorticity, newVelocities);
  const std::ptrdiff_t count = std::ptrdiff_t(subset.size());
  // PBF eq. 15: omega_i = sum_j (m/rho0) (v_i - v_j) x grad_i W(x_ij), the SPH curl of v
  // (= PBF's sum_j (v_j - v_i) x grad_j W; a rigid rotation Omega gives omega ~ 2 Omega).
  // Neighbours outside the subset keep vorticity 0: the subset is normally all fluid.
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads) if (count >= kParallelThreshold)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Index i = subset[std::size_t(s)];
    Vec3 omega = Vec3::Zero();
    forNeighbours(job.positions, job.lists, i, [&](Index, Index j, const Vec3& r, Real r2) {
      omega += (job.velocities[i] - job.velocities[j]).cross(spikyGradient(kernels, r, std::sqrt(r2)));
    });
    job.vorticity[i] = job.scale * omega;
  }
  // PBF eq. 16: f = eps (N x omega), N = eta/|eta|, eta = grad |omega| (SPH difference form).
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads) if (count >= kParallelThreshold)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Index i = subset[std::size_t(s)];
    const Real wi = job.vorticity[i].norm();
    Vec3 eta = Vec3::Zero();
    forNeighbours(job.positions, job.lists, i, [&](Index, Index j, const Vec3& r, Real r2) {
      // grad |omega| at i ~ sum_j (m/rho0)(|omega_j| - |omega_i|) grad_i W(x_ij); grad_i W
      // points from i towards j, so a larger |omega_j| turns eta towards j.
      eta += (job.vorticity[j].norm() - wi) * spikyGradient(kernels, r, std::sqrt(r2));
    });
    finishConfinement(job, i, eta);
  }
}

}  // namespace hs::pbd
