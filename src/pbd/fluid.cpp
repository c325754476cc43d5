// Position Based Fluids (Macklin & Mueller 2013), see fluid.h for the equations and the
// determinism contract: every loop is a gather over the CSR neighbour lists.
#include "pbd/fluid.h"

#include <cassert>
#include <cmath>

namespace hs::pbd {
namespace {

// Below this many particles a fork-join costs more than a neighbour loop saves. Measured with
// `heartsim bench --case pbf-dam-break-1k --threads 2`: a threshold of 2048 (serial at 1,000
// particles) gave 640 steps/s, 256 gave about 1,000.
constexpr std::ptrdiff_t kParallelThreshold = 256;

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

// The walk of every loop below over the CSR neighbour list of i: pair(k, j, r, r2) for each
// neighbour j, k its slot in the lists (for per-pair caches), r = x_i - x_j, r2 = |r|^2.
template <class Pair>
HS_KERNEL void forNeighbours(const std::vector<Vec3>& positions, const NeighbourLists& lists, Index i,
                             const Pair& pair) {
  const Vec3& xi = positions[i];
  for (Index k = lists.offsets[i]; k < lists.offsets[i + 1]; ++k) {
    const Index j = lists.indices[k];
    const Vec3 r = xi - positions[j];
    pair(k, j, r, r.squaredNorm());
  }
}

// sum_j W_poly6(|x_i - x_j|) over the list of i, self term W(0) first.
Real poly6Sum(const std::vector<Vec3>& positions, const NeighbourLists& lists, const SphKernels& kernels, Index i,
              Real selfTerm) {
  Real sum = selfTerm;
  forNeighbours(positions, lists, i, [&](Index, Index, const Vec3&, Real r2) { sum += poly6(kernels, r2); });
  return sum;
}

// s with grad W_spiky(r_ij) = s r_ij, without branches (the kernels of sph_kernels.h branch
// on r >= h and r = 0): s = -45/(pi h^4) (1 - r/h)^2 / r, with q = 1 - r/h clamped to 0
// beyond h, and r clamped below at 1e-6 h so that s stays finite (r_ij = 0 then gives a zero
// gradient, as spikyGradient does; pairs closer than 1e-6 h get a slightly smaller one).
HS_KERNEL Real spikyGradientScale(const SphKernels& k, Real r) {
  const Real q = std::max(Real(0), Real(1) - r * k.invH);
  return k.spikyGradCoeff * q * q / std::max(r, Real(1e-6) * k.h);
}

// W_poly6 from r^2, clamped to 0 beyond h without a branch.
HS_KERNEL Real poly6Clamped(const SphKernels& k, Real r2) {
  const Real t = std::max(Real(0), Real(1) - r2 * k.invH2);
  return k.poly6Coeff * (t * t * t);
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
  const Real selfTerm = poly6(kernels, Real(0));
  const std::ptrdiff_t count = std::ptrdiff_t(subset.size());
#pragma omp parallel for schedule(static) num_threads(threads) if (count >= kParallelThreshold)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Index i = subset[std::size_t(s)];
    // rho_i = m sum_j W(x_i - x_j) (PBF eq. 2), self term first.
    densities[i] = m * poly6Sum(positions, lists, kernels, i, selfTerm);
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
  checkInputs(positions, lists, kernels, settings);
  if (pairGradients) pairGradients->resize(lists.indices.size());
  Real* const pairOut = pairGradients ? pairGradients->data() : nullptr;
  fitOutput(densities, positions.size());
  fitOutput(lambdas, positions.size());
  const Real invRho0 = Real(1) / settings.restDensity;
  const Real m = settings.particleMass;
  const Real selfTerm = poly6(kernels, Real(0));
  const bool unilateral = settings.unilateralDensity;
  const Real gradScale = settings.particleMass * invRho0;  // m/rho0, see fluid.h
  const std::ptrdiff_t count = std::ptrdiff_t(subset.size());
#pragma omp parallel for schedule(static) num_threads(threads) if (count >= kParallelThreshold)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Index i = subset[std::size_t(s)];
    // PBF eq. 8: grad_{p_i} C_i = (m/rho0) sum_j grad W_ij, grad_{p_j} C_i = -(m/rho0) grad W_ij.
    // One loop for rho_i (PBF eq. 2, self term first) and the gradient sums.
    Real kernelSum = selfTerm;
    Vec3 gradI = Vec3::Zero();
    Real sumSqJ = 0;
    forNeighbours(positions, lists, i, [&](Index k, Index, const Vec3& r, Real r2) {
      kernelSum += poly6Clamped(kernels, r2);
      const Real gs = spikyGradientScale(kernels, std::sqrt(r2));
      if (pairOut) pairOut[k] = gs;
      const Vec3 g = (gradScale * gs) * r;
      gradI += g;
      sumSqJ += g.squaredNorm();
    });
    Real rho = m * kernelSum;
    if (walls) {
      const Real d = wallDistance(*walls, i, positions[i]);
      if (d >= Real(0)) {
        const Vec3& n = (*walls->proximity)[i].normal;
        rho += settings.restDensity * walls->table->density(d);
        gradI -= walls->table->gradient(d) * n;
      }
    }
    densities[i] = rho;
    const Real c = rho * invRho0 - Real(1);  // PBF eq. 1
    // PBF eq. 11: lambda_i = -C_i / (sum_k |grad_{p_k} C_i|^2 + eps).
    const Real lambda = -c / (gradI.squaredNorm() + sumSqJ + settings.relaxation);
    lambdas[i] = unilateral ? std::min(lambda, Real(0)) : lambda;
  }
}

void computeDensityCorrections(const std::vector<Vec3>& positions, const NeighbourLists& lists,
                               std::span<const Index> subset, const SphKernels& kernels,
                               const FluidSettings& settings, const std::vector<Real>& lambdas,
                               std::vector<Vec3>& corrections, int threads,
                               const std::vector<Real>* pairGradients, const WallDensityInput* walls) {
  checkInputs(positions, lists, kernels, settings);
  assert(!pairGradients || pairGradients->size() == lists.indices.size());
  const Real* const pairIn = pairGradients ? pairGradients->data() : nullptr;
  const bool collide = settings.collisionRadius > Real(0);
  assert(lambdas.size() == positions.size());
  fitOutput(corrections, positions.size());
  const Real scale = settings.particleMass / settings.restDensity;  // m/rho0, see fluid.h
  const bool tensile = settings.tensileCorrection;
  const Real deltaQ = settings.tensileDeltaQRatio * kernels.h;
  const Real wq = poly6(kernels, deltaQ * deltaQ);
  const Real invWq = wq > Real(0) ? Real(1) / wq : Real(0);
  const Real contact = 2 * settings.collisionRadius;  // r_i + r_j of thesis eq. 4.6
  const Real contact2 = contact * contact;
  const std::ptrdiff_t count = std::ptrdiff_t(subset.size());
#pragma omp parallel for schedule(static) num_threads(threads) if (count >= kParallelThreshold)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Index i = subset[std::size_t(s)];
    const Real li = lambdas[i];
    // PBF eq. 12: dp_i = (m/rho0) sum_j (lambda_i + lambda_j + s_corr) grad W(p_i - p_j).
    Vec3 sum = Vec3::Zero();
    Vec3 push = Vec3::Zero();
    forNeighbours(positions, lists, i, [&](Index k, Index j, const Vec3& r, Real r2) {
      Real weight = li + lambdas[j];
      if (tensile) weight += tensileCorrection(kernels, settings, invWq, r2);
      const Real gs = pairIn ? pairIn[k] : spikyGradientScale(kernels, std::sqrt(r2));
      sum += (weight * gs) * r;
      // Thesis eq. 4.6: C = |x_ij| - 2r >= 0; equal masses move half the overlap each.
      if (collide && r2 < contact2 && r2 > Real(0)) {
        const Real d = std::sqrt(r2);
        push += (Real(0.5) * (contact - d) / d) * r;
      }
    });
    corrections[i] = scale * sum + push;
    if (walls) {
      const Real d = wallDistance(*walls, i, positions[i]);
      if (d >= Real(0)) corrections[i] -= (2 * li * walls->table->gradient(d)) * (*walls->proximity)[i].normal;
    }
  }
}

void applyViscosity(const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities,
                    const NeighbourLists& lists, std::span<const Index> subset,
                    const SphKernels& kernels, const FluidSettings& settings, Real dt,
                    std::vector<Vec3>& newVelocities, int threads) {
  checkInputs(positions, lists, kernels, settings);
  assert(velocities.size() == positions.size());
  assert(&velocities != &newVelocities);
  fitOutput(newVelocities, positions.size());
  const Real c = settings.xsphViscosity;
  // dt 2(d+2) nu m/rho0 with d = 3 (Monaghan 2005 eq. 6.13), and the 0.01 h^2 that keeps the
  // denominator away from zero for close pairs.
  const Real laplace = dt * Real(10) * settings.kinematicViscosity * settings.particleMass / settings.restDensity;
  const Real softening = Real(0.01) * kernels.h2;
  const std::ptrdiff_t count = std::ptrdiff_t(subset.size());
#pragma omp parallel for schedule(static) num_threads(threads) if (count >= kParallelThreshold)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Index i = subset[std::size_t(s)];
    const Vec3& vi = velocities[i];
    Vec3 xsph = Vec3::Zero();
    Vec3 viscous = Vec3::Zero();
    forNeighbours(positions, lists, i, [&](Index, Index j, const Vec3& r, Real r2) {
      const Vec3 vij = vi - velocities[j];
      // PBF eq. 17: c sum_j (v_j - v_i) W_poly6(x_i - x_j).
      xsph -= poly6(kernels, r2) * vij;
      // Monaghan 2005 eq. 6.13: (v_ij . x_ij)/(|x_ij|^2 + 0.01 h^2) grad W(x_ij).
      viscous += (vij.dot(r) / (r2 + softening)) * spikyGradient(kernels, r, std::sqrt(r2));
    });
    newVelocities[i] = vi + c * xsph + laplace * viscous;
  }
}

void applyVorticityConfinement(const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities,
                               const NeighbourLists& lists, std::span<const Index> subset,
                               const SphKernels& kernels, const FluidSettings& settings, Real dt,
                               std::vector<Vec3>& vorticity, std::vector<Vec3>& newVelocities,
                               int threads) {
  checkInputs(positions, lists, kernels, settings);
  assert(&velocities != &newVelocities);
  fitOutput(vorticity, positions.size());
  fitOutput(newVelocities, positions.size());
  const Real scale = settings.particleMass / settings.restDensity;
  const std::ptrdiff_t count = std::ptrdiff_t(subset.size());
  // PBF eq. 15: omega_i = sum_j (m/rho0) (v_i - v_j) x grad_i W(x_ij), the SPH curl of v
  // (= PBF's sum_j (v_j - v_i) x grad_j W; a rigid rotation Omega gives omega ~ 2 Omega).
  // Neighbours outside the subset keep vorticity 0: the subset is normally all fluid.
#pragma omp parallel for schedule(static) num_threads(threads) if (count >= kParallelThreshold)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Index i = subset[std::size_t(s)];
    Vec3 omega = Vec3::Zero();
    forNeighbours(positions, lists, i, [&](Index, Index j, const Vec3& r, Real r2) {
      omega += (velocities[i] - velocities[j]).cross(spikyGradient(kernels, r, std::sqrt(r2)));
    });
    vorticity[i] = scale * omega;
  }
  // PBF eq. 16: f = eps (N x omega), N = eta/|eta|, eta = grad |omega| (SPH difference form).
  const Real eps = settings.vorticityConfinement;
#pragma omp parallel for schedule(static) num_threads(threads) if (count >= kParallelThreshold)
  for (std::ptrdiff_t s = 0; s < count; ++s) {
    const Index i = subset[std::size_t(s)];
    const Real wi = vorticity[i].norm();
    Vec3 eta = Vec3::Zero();
    forNeighbours(positions, lists, i, [&](Index, Index j, const Vec3& r, Real r2) {
      // grad |omega| at i ~ sum_j (m/rho0)(|omega_j| - |omega_i|) grad_i W(x_ij); grad_i W
      // points from i towards j, so a larger |omega_j| turns eta towards j.
      eta += (vorticity[j].norm() - wi) * spikyGradient(kernels, r, std::sqrt(r2));
    });
    eta *= scale;
    const Real len = eta.norm();
    Vec3 v = velocities[i];
    if (len > Real(1e-12)) v += dt * eps * (eta / len).cross(vorticity[i]);
    newVelocities[i] = v;
  }
}

}  // namespace hs::pbd
