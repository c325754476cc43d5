#pragma once
// What the neighbour loops of fluid.h share between the scalar kernels (fluid.cpp) and the SIMD
// ones (fluid_simd.cpp): their inputs as plain pointers ("jobs", built once per call, outputs
// resized), and the per-particle work before and after the loop over neighbours (the wall's
// share of the density, lambda from the sums, the final velocity), so both paths run the very
// same code there and differ only in how the sums over neighbours are accumulated.
#include <algorithm>
#include <cassert>
#include <cstddef>
#include <span>
#include <vector>

#include "pbd/fluid/fluid.h"

namespace hs::pbd {

// Below this many particles a fork-join costs more than a neighbour loop saves. Measured with
// `heartsim bench --case pbf-dam-break-1k --threads 2`: a threshold of 2048 (serial at 1,000
// particles) gave 640 steps/s, 256 gave about 1,000.
inline constexpr std::ptrdiff_t kFluidParallelThreshold = 256;

// Sanity of any Vec3 array read as 3 Reals per entry (SIMD gathers by 3 j + axis).
static_assert(sizeof(Vec3) == 3 * sizeof(Real));

inline const Real* coordinates(const std::vector<Vec3>& v) { return reinterpret_cast<const Real*>(v.data()); }

struct ListView {
  const Index* offsets;
  const Index* indices;
  Index count;  // particles (positions)
};

inline ListView viewOf(const NeighbourLists& lists) {
  return {lists.offsets.data(), lists.indices.data(), Index(lists.offsets.size() - 1)};
}

// W_poly6(0), the self term of rho_i.
inline Real poly6SelfTerm(const SphKernels& kernels) { return poly6(kernels, Real(0)); }

struct LambdaJob {
  const Vec3* positions;
  const Real* coords;
  ListView lists;
  const Index* subset;
  SphKernels kernels;
  Real mass, restDensity, invRho0, selfTerm, gradScale, relaxation;
  bool unilateral;
  Real* densities;
  Real* lambdas;
  Real* pairOut;  // nullptr: no per-pair cache
  const WallDensityInput* walls;
};

inline LambdaJob makeLambdaJob(const std::vector<Vec3>& positions, const NeighbourLists& lists,
                               std::span<const Index> subset, const SphKernels& kernels,
                               const FluidSettings& settings, std::vector<Real>& densities,
                               std::vector<Real>& lambdas, std::vector<Real>* pairGradients,
                               const WallDensityInput* walls) {
  assert(lists.offsets.size() == positions.size() + 1);
  assert(kernels.h == settings.supportRadius);
  if (pairGradients) pairGradients->resize(lists.indices.size());
  if (densities.size() != positions.size()) densities.resize(positions.size());
  if (lambdas.size() != positions.size()) lambdas.resize(positions.size());
  const Real invRho0 = Real(1) / settings.restDensity;
  return {positions.data(), coordinates(positions), viewOf(lists), subset.data(), kernels,
          settings.particleMass, settings.restDensity, invRho0, poly6SelfTerm(kernels),
          settings.particleMass * invRho0,  // m/rho0, see fluid.h
          settings.relaxation, settings.unilateralDensity, densities.data(), lambdas.data(),
          pairGradients ? pairGradients->data() : nullptr, walls};
}

// From kernelSum = sum_j W_poly6 (self term included), gradI = grad_{p_i} C_i and
// sumSqJ = sum_j |grad_{p_j} C_i|^2: the wall's share, rho_i and lambda_i (PBF eq. 1, 2, 11).
inline void finishLambda(const LambdaJob& job, Index i, Real kernelSum, Vec3 gradI, Real sumSqJ) {
  Real rho = job.mass * kernelSum;
  if (job.walls) {
    const WallDensityInput& walls = *job.walls;
    const Real d = wallDistance(walls, i, job.positions[i]);
    if (d >= Real(0)) {
      const Vec3& n = (*walls.proximity)[i].normal;
      rho += job.restDensity * walls.table->density(d);
      gradI -= walls.table->gradient(d) * n;
    }
  }
  job.densities[i] = rho;
  const Real c = rho * job.invRho0 - Real(1);  // PBF eq. 1
  // PBF eq. 11: lambda_i = -C_i / (sum_k |grad_{p_k} C_i|^2 + eps).
  const Real lambda = -c / (gradI.squaredNorm() + sumSqJ + job.relaxation);
  job.lambdas[i] = job.unilateral ? std::min(lambda, Real(0)) : lambda;
}

struct CorrectionJob {
  const Vec3* positions;
  const Real* coords;
  ListView lists;
  const Index* subset;
  SphKernels kernels;
  const Real* lambdas;
  const Real* pairIn;  // nullptr: gradients recomputed
  Real scale;          // m/rho0
  bool tensile;
  Real tensileK;
  int tensileN;
  Real invWq;  // 1/W_poly6(deltaQ) of PBF eq. 13
  bool collide;
  Real contact;  // r_i + r_j of thesis eq. 4.6
  Vec3* corrections;
  const WallDensityInput* walls;
};

inline CorrectionJob makeCorrectionJob(const std::vector<Vec3>& positions, const NeighbourLists& lists,
                                       std::span<const Index> subset, const SphKernels& kernels,
                                       const FluidSettings& settings, const std::vector<Real>& lambdas,
                                       std::vector<Vec3>& corrections, const std::vector<Real>* pairGradients,
                                       const WallDensityInput* walls) {
  assert(lists.offsets.size() == positions.size() + 1);
  assert(kernels.h == settings.supportRadius);
  assert(!pairGradients || pairGradients->size() == lists.indices.size());
  assert(lambdas.size() == positions.size());
  if (corrections.size() != positions.size()) corrections.resize(positions.size());
  const Real deltaQ = settings.tensileDeltaQRatio * kernels.h;
  const Real wq = poly6(kernels, deltaQ * deltaQ);
  return {positions.data(), coordinates(positions), viewOf(lists), subset.data(), kernels, lambdas.data(),
          pairGradients ? pairGradients->data() : nullptr, settings.particleMass / settings.restDensity,
          settings.tensileCorrection, settings.tensileK, settings.tensileN,
          wq > Real(0) ? Real(1) / wq : Real(0), settings.collisionRadius > Real(0),
          2 * settings.collisionRadius, corrections.data(), walls};
}

// dp_i = (m/rho0) sum + push, and the wall's mirrored share 2 lambda_i (-G(d) n) (fluid.h).
inline void finishCorrection(const CorrectionJob& job, Index i, Real li, const Vec3& sum, const Vec3& push) {
  Vec3& out = job.corrections[i];
  out = job.scale * sum + push;
  if (job.walls) {
    const WallDensityInput& walls = *job.walls;
    const Real d = wallDistance(walls, i, job.positions[i]);
    if (d >= Real(0)) out -= (2 * li * walls.table->gradient(d)) * (*walls.proximity)[i].normal;
  }
}

struct ViscosityJob {
  const Vec3* positions;
  const Real* coords;
  const Vec3* velocities;
  const Real* velocityCoords;
  ListView lists;
  const Index* subset;
  SphKernels kernels;
  Real xsph;       // c of PBF eq. 17
  Real laplace;    // dt 2(d+2) nu m/rho0 (Monaghan 2005 eq. 6.13)
  Real softening;  // 0.01 h^2
  Vec3* newVelocities;
};

inline ViscosityJob makeViscosityJob(const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities,
                                     const NeighbourLists& lists, std::span<const Index> subset,
                                     const SphKernels& kernels, const FluidSettings& settings, Real dt,
                                     std::vector<Vec3>& newVelocities) {
  assert(lists.offsets.size() == positions.size() + 1);
  assert(kernels.h == settings.supportRadius);
  assert(velocities.size() == positions.size());
  assert(&velocities != &newVelocities);
  if (newVelocities.size() != positions.size()) newVelocities.resize(positions.size());
  // dt 2(d+2) nu m/rho0 with d = 3, and the 0.01 h^2 that keeps the denominator away from zero
  // for close pairs.
  const Real laplace = dt * Real(10) * settings.kinematicViscosity * settings.particleMass / settings.restDensity;
  return {positions.data(), coordinates(positions), velocities.data(), coordinates(velocities), viewOf(lists),
          subset.data(), kernels, settings.xsphViscosity, laplace, Real(0.01) * kernels.h2, newVelocities.data()};
}

struct VorticityJob {
  const Vec3* positions;
  const Real* coords;
  const Vec3* velocities;
  const Real* velocityCoords;
  ListView lists;
  const Index* subset;
  SphKernels kernels;
  Real scale;  // m/rho0
  Real dt, epsilon;
  Vec3* vorticity;
  Vec3* newVelocities;
};

inline VorticityJob makeVorticityJob(const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities,
                                     const NeighbourLists& lists, std::span<const Index> subset,
                                     const SphKernels& kernels, const FluidSettings& settings, Real dt,
                                     std::vector<Vec3>& vorticity, std::vector<Vec3>& newVelocities) {
  assert(lists.offsets.size() == positions.size() + 1);
  assert(kernels.h == settings.supportRadius);
  assert(&velocities != &newVelocities);
  if (vorticity.size() != positions.size()) vorticity.resize(positions.size());
  if (newVelocities.size() != positions.size()) newVelocities.resize(positions.size());
  return {positions.data(), coordinates(positions), velocities.data(), coordinates(velocities), viewOf(lists),
          subset.data(), kernels, settings.particleMass / settings.restDensity, dt, settings.vorticityConfinement,
          vorticity.data(), newVelocities.data()};
}

// PBF eq. 16 from eta_i / (m/rho0) = sum_j (|omega_j| - |omega_i|) grad W(x_ij):
// N = eta/|eta|, v_i += dt eps (N x omega_i).
inline void finishConfinement(const VorticityJob& job, Index i, Vec3 eta) {
  eta *= job.scale;
  const Real len = eta.norm();
  Vec3 v = job.velocities[i];
  if (len > Real(1e-12)) v += job.dt * job.epsilon * (eta / len).cross(job.vorticity[i]);
  job.newVelocities[i] = v;
}

}  // namespace hs::pbd
