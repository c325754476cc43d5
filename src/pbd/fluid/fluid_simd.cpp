// The neighbour loops of Position Based Fluids (Macklin & Mueller 2013) in SIMD with Highway's
// runtime dispatch: this file is compiled once per instruction set (foreach_target.h) and the
// best one the machine has runs. See fluid_simd.h for the lane layout and why results are the
// same on every instruction set, and fluid.h for the equations; each lane evaluates the scalar
// kernel's expression of fluid.cpp for one neighbour, operation for operation.
#include "pbd/fluid/fluid_simd.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "pbd/fluid/fluid_loops.h"

#ifndef HS_PBD_FLUID_SIMD_QUAD_JOB
#define HS_PBD_FLUID_SIMD_QUAD_JOB
namespace hs::pbd::simd {
// computeDensityCorrections' inputs plus (x, y, z, lambda) per particle.
struct QuadCorrectionJob : CorrectionJob {
  const Real* quads;
};
}  // namespace hs::pbd::simd
#endif

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pbd/fluid/fluid_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "pbd/fluid/fluid_simd_lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace hs::pbd::simd::HWY_NAMESPACE {

// rho_i, lambda_i and the per-pair gradient scales of computeLambdas (fluid.h), for subset
// entries [begin, end).
void LambdasRange(const LambdaJob& job, std::size_t begin, std::size_t end) {
  const D d;
  const KernelConstants<D> kc(d, job.kernels);
  const V gradScale = hn::Set(d, job.gradScale);
  for (std::size_t s = begin; s < end; ++s) {
    const Index i = job.subset[s];
    const Vec3& pi = job.positions[i];
    const V xi = hn::Set(d, pi.x()), yi = hn::Set(d, pi.y()), zi = hn::Set(d, pi.z());
    Accumulator<D> kernelSum(d), gx(d), gy(d), gz(d), sumSq(d);
    forNeighbourLanes(d, job.lists, i, [&](std::size_t part, const NeighbourLanes<D>& n) {
      const Pair<D> p = pairAt(d, job.coords, n, xi, yi, zi);
      const auto inside = hn::And(n.valid, hn::Lt(p.r2, kc.h2));
      kernelSum.add(part, poly6Clamped(kc, inside, p.r2));
      const V gs = spikyGradientScale(kc, inside, p.r2);
      if (job.pairOut) storeLanes(d, gs, job.pairOut, n);
      // g = (m/rho0) s_ij r_ij (PBF eq. 8), as fluid.cpp.
      const V scale = hn::Mul(gradScale, gs);
      const V gxl = hn::Mul(scale, p.dx), gyl = hn::Mul(scale, p.dy), gzl = hn::Mul(scale, p.dz);
      gx.add(part, gxl);
      gy.add(part, gyl);
      gz.add(part, gzl);
      sumSq.add(part, squaredNorm(gxl, gyl, gzl));
    });
    finishLambda(job, i, job.selfTerm + kernelSum.sum(d), Vec3(gx.sum(d), gy.sum(d), gz.sum(d)), sumSq.sum(d));
  }
}

// dp_i of computeDensityCorrections (PBF eq. 12, thesis eq. 4.6), for subset entries [begin, end).
// Neighbours come from job.quads = (x_j, y_j, z_j, lambda_j): one load per lane, no gather.
void CorrectionsRange(const QuadCorrectionJob& job, std::size_t begin, std::size_t end) {
  const D d;
  const KernelConstants<D> kc(d, job.kernels);
  const V zero = hn::Zero(d), half = hn::Set(d, Real(0.5));
  const V invWq = hn::Set(d, job.invWq), minusK = hn::Set(d, -job.tensileK);
  const V contact = hn::Set(d, job.contact), contact2 = hn::Set(d, job.contact * job.contact);
  for (std::size_t s = begin; s < end; ++s) {
    const Index i = job.subset[s];
    const Vec3& pi = job.positions[i];
    const V xi = hn::Set(d, pi.x()), yi = hn::Set(d, pi.y()), zi = hn::Set(d, pi.z());
    const Real li = job.lambdas[i];
    const V liV = hn::Set(d, li);
    Accumulator<D> sx(d), sy(d), sz(d), px(d), py(d), pz(d);
    forNeighbourLanes(d, job.lists, i, [&](std::size_t part, const NeighbourLanes<D>& n) {
      V lj;
      const Pair<D> p = pairAtQuads(d, job.quads, n, xi, yi, zi, lj);
      V weight = hn::Add(liV, lj);
      if (job.tensile) {
        // s_corr = -k (W_poly6(r)/W_poly6(deltaQ))^n (PBF eq. 13).
        const V ratio = hn::Mul(poly6(kc, n.valid, p.r2), invWq);
        V power = kc.one;
        for (int e = 0; e < job.tensileN; ++e) power = hn::Mul(power, ratio);
        weight = hn::Add(weight, hn::Mul(minusK, power));
      }
      const V gs = job.pairIn ? loadLanes(d, job.pairIn, n)
                              : spikyGradientScale(kc, hn::And(n.valid, hn::Lt(p.r2, kc.h2)), p.r2);
      const V f = hn::IfThenElseZero(n.valid, hn::Mul(weight, gs));
      sx.add(part, hn::Mul(f, p.dx));
      sy.add(part, hn::Mul(f, p.dy));
      sz.add(part, hn::Mul(f, p.dz));
      if (job.collide) {
        // Thesis eq. 4.6: each of an overlapping pair moves half the overlap, (2r - d)/2 along r_ij/d.
        const auto touching = hn::And(n.valid, hn::And(hn::Lt(p.r2, contact2), hn::Gt(p.r2, zero)));
        const V dist = hn::Sqrt(p.r2);
        const V push = hn::IfThenElseZero(touching, hn::Div(hn::Mul(half, hn::Sub(contact, dist)), dist));
        px.add(part, hn::IfThenElseZero(touching, hn::Mul(push, p.dx)));
        py.add(part, hn::IfThenElseZero(touching, hn::Mul(push, p.dy)));
        pz.add(part, hn::IfThenElseZero(touching, hn::Mul(push, p.dz)));
      }
    });
    const Vec3 sum(sx.sum(d), sy.sum(d), sz.sum(d));
    const Vec3 push = job.collide ? Vec3(px.sum(d), py.sum(d), pz.sum(d)) : Vec3::Zero();
    finishCorrection(job, i, li, sum, push);
  }
}

// XSPH and the SPH Laplacian viscosity of applyViscosity, for subset entries [begin, end).
void ViscosityRange(const ViscosityJob& job, std::size_t begin, std::size_t end) {
  const D d;
  const KernelConstants<D> kc(d, job.kernels);
  const V softening = hn::Set(d, job.softening);
  for (std::size_t s = begin; s < end; ++s) {
    const Index i = job.subset[s];
    const Vec3& pi = job.positions[i];
    const Vec3& vi = job.velocities[i];
    const V xi = hn::Set(d, pi.x()), yi = hn::Set(d, pi.y()), zi = hn::Set(d, pi.z());
    const V vxi = hn::Set(d, vi.x()), vyi = hn::Set(d, vi.y()), vzi = hn::Set(d, vi.z());
    Accumulator<D> ax(d), ay(d), az(d), bx(d), by(d), bz(d);
    forNeighbourLanes(d, job.lists, i, [&](std::size_t part, const NeighbourLanes<D>& n) {
      const Pair<D> p = pairAt(d, job.coords, n, xi, yi, zi);
      const Triple<D> vj = loadPoints(d, job.velocityCoords, n);
      const V vx = hn::Sub(vxi, vj.x), vy = hn::Sub(vyi, vj.y), vz = hn::Sub(vzi, vj.z);
      // PBF eq. 17: xsph -= W_poly6(x_ij) v_ij.
      const V w = poly6(kc, n.valid, p.r2);
      ax.subtract(part, hn::Mul(w, vx));
      ay.subtract(part, hn::Mul(w, vy));
      az.subtract(part, hn::Mul(w, vz));
      // Monaghan 2005 eq. 6.13: (v_ij . x_ij)/(|x_ij|^2 + 0.01 h^2) grad W(x_ij).
      const V g = spikyGradientFactor(kc, n.valid, p.r2);
      const V a = hn::Div(dot(vx, vy, vz, p.dx, p.dy, p.dz), hn::Add(p.r2, softening));
      bx.add(part, hn::Mul(a, hn::Mul(g, p.dx)));
      by.add(part, hn::Mul(a, hn::Mul(g, p.dy)));
      bz.add(part, hn::Mul(a, hn::Mul(g, p.dz)));
    });
    const Vec3 xsph(ax.sum(d), ay.sum(d), az.sum(d));
    const Vec3 viscous(bx.sum(d), by.sum(d), bz.sum(d));
    job.newVelocities[i] = vi + job.xsph * xsph + job.laplace * viscous;
  }
}

// omega_i = (m/rho0) sum_j (v_i - v_j) x grad W(x_ij) (PBF eq. 15), for subset entries [begin, end).
void VorticityRange(const VorticityJob& job, std::size_t begin, std::size_t end) {
  const D d;
  const KernelConstants<D> kc(d, job.kernels);
  for (std::size_t s = begin; s < end; ++s) {
    const Index i = job.subset[s];
    const Vec3& pi = job.positions[i];
    const Vec3& vi = job.velocities[i];
    const V xi = hn::Set(d, pi.x()), yi = hn::Set(d, pi.y()), zi = hn::Set(d, pi.z());
    const V vxi = hn::Set(d, vi.x()), vyi = hn::Set(d, vi.y()), vzi = hn::Set(d, vi.z());
    Accumulator<D> ox(d), oy(d), oz(d);
    forNeighbourLanes(d, job.lists, i, [&](std::size_t part, const NeighbourLanes<D>& n) {
      const Pair<D> p = pairAt(d, job.coords, n, xi, yi, zi);
      const Triple<D> vj = loadPoints(d, job.velocityCoords, n);
      const V vx = hn::Sub(vxi, vj.x), vy = hn::Sub(vyi, vj.y), vz = hn::Sub(vzi, vj.z);
      const V g = spikyGradientFactor(kc, n.valid, p.r2);
      const V gx = hn::Mul(g, p.dx), gy = hn::Mul(g, p.dy), gz = hn::Mul(g, p.dz);
      // Eigen's cross product, component by component.
      ox.add(part, hn::Sub(hn::Mul(vy, gz), hn::Mul(vz, gy)));
      oy.add(part, hn::Sub(hn::Mul(vz, gx), hn::Mul(vx, gz)));
      oz.add(part, hn::Sub(hn::Mul(vx, gy), hn::Mul(vy, gx)));
    });
    job.vorticity[i] = job.scale * Vec3(ox.sum(d), oy.sum(d), oz.sum(d));
  }
}

// eta_i = (m/rho0) sum_j (|omega_j| - |omega_i|) grad W(x_ij) and v_i += dt eps (N x omega_i)
// (PBF eq. 16), for subset entries [begin, end).
void ConfinementRange(const VorticityJob& job, std::size_t begin, std::size_t end) {
  const D d;
  const KernelConstants<D> kc(d, job.kernels);
  const Real* const omega = reinterpret_cast<const Real*>(job.vorticity);
  for (std::size_t s = begin; s < end; ++s) {
    const Index i = job.subset[s];
    const Vec3& pi = job.positions[i];
    const V xi = hn::Set(d, pi.x()), yi = hn::Set(d, pi.y()), zi = hn::Set(d, pi.z());
    const Real wi = job.vorticity[i].norm();
    const V wiV = hn::Set(d, wi);
    Accumulator<D> ex(d), ey(d), ez(d);
    forNeighbourLanes(d, job.lists, i, [&](std::size_t part, const NeighbourLanes<D>& n) {
      const Pair<D> p = pairAt(d, job.coords, n, xi, yi, zi);
      const Triple<D> oj = loadPoints(d, omega, n);
      const V difference = hn::Sub(hn::Sqrt(squaredNorm(oj.x, oj.y, oj.z)), wiV);
      const V g = spikyGradientFactor(kc, n.valid, p.r2);
      ex.add(part, hn::IfThenElseZero(n.valid, hn::Mul(difference, hn::Mul(g, p.dx))));
      ey.add(part, hn::IfThenElseZero(n.valid, hn::Mul(difference, hn::Mul(g, p.dy))));
      ez.add(part, hn::IfThenElseZero(n.valid, hn::Mul(difference, hn::Mul(g, p.dz))));
    });
    finishConfinement(job, i, Vec3(ex.sum(d), ey.sum(d), ez.sum(d)));
  }
}

std::int64_t DispatchedTarget() { return HWY_TARGET; }

}  // namespace hs::pbd::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace hs::pbd::simd {

HWY_EXPORT(LambdasRange);
HWY_EXPORT(CorrectionsRange);
HWY_EXPORT(ViscosityRange);
HWY_EXPORT(VorticityRange);
HWY_EXPORT(ConfinementRange);
HWY_EXPORT(DispatchedTarget);

namespace {

// Runs range(begin, end) over contiguous blocks of [0, count), one per thread (a static
// schedule). Each particle's result depends only on its own neighbour loop, so the blocks
// change nothing but who computes what.
template <class Range>
void forRanges(std::size_t count, int threads, const Range& range) {
  if (count < std::size_t(kFluidParallelThreshold) || threads <= 1) {
    range(std::size_t(0), count);
    return;
  }
#pragma omp parallel num_threads(threads)
  {
    const auto t = std::size_t(omp_get_thread_num());
    const auto teams = std::size_t(omp_get_num_threads());
    range(count * t / teams, count * (t + 1) / teams);
  }
}

// Per-entry cost of a neighbour loop: its pairs plus a particle's own work, in pairs.
constexpr std::size_t kParticleCostInPairs = 8;

// The same over the subset's entries, the blocks cut so that each thread gets about the same
// number of neighbour pairs rather than of particles: slots come in cell order, and whole runs
// of them are blood parked outside the heart with no neighbours, which left one thread with
// most of the work (normal, 2 threads: the density kernels took longer than on one).
template <class Range>
void forBalancedRanges(const ListView& lists, const Index* subset, std::size_t count, int threads,
                       const Range& range) {
  if (count < std::size_t(kFluidParallelThreshold) || threads <= 1) {
    range(std::size_t(0), count);
    return;
  }
  auto cost = [&](std::size_t s) {
    const Index i = subset[s];
    return std::size_t(lists.offsets[i + 1] - lists.offsets[i]) + kParticleCostInPairs;
  };
  std::size_t total = 0;
  for (std::size_t s = 0; s < count; ++s) total += cost(s);
  std::vector<std::size_t> cut(std::size_t(threads) + 1, count);
  cut[0] = 0;
  std::size_t done = 0, team = 1;
  for (std::size_t s = 0; s < count && team < std::size_t(threads); ++s) {
    done += cost(s);
    while (team < std::size_t(threads) && done * std::size_t(threads) >= total * team) cut[team++] = s + 1;
  }
#pragma omp parallel num_threads(threads)
  {
    const auto t = std::size_t(omp_get_thread_num());
    if (omp_get_num_threads() == threads) range(cut[t], cut[t + 1]);
    else if (t == 0) range(std::size_t(0), count);  // a smaller team than asked: one does all
  }
}

// The same for an exported range function; the dispatch is resolved before the threads start.
template <class Job>
void runRanges(void (*range)(const Job&, std::size_t, std::size_t), const Job& job, std::size_t count,
               int threads) {
  forBalancedRanges(job.lists, job.subset, count, threads, [&](std::size_t begin, std::size_t end) { range(job, begin, end); });
}

// The function of the chosen target (choosing it on the first call).
#define HS_DISPATCHED(FUNC) (HWY_DYNAMIC_DISPATCH(DispatchedTarget)(), &HWY_DYNAMIC_DISPATCH(FUNC))

}  // namespace

const char* targetName() { return hwy::TargetName(HWY_DYNAMIC_DISPATCH(DispatchedTarget)()); }

void computeLambdas(const std::vector<Vec3>& positions, const NeighbourLists& lists,
                    std::span<const Index> subset, const SphKernels& kernels,
                    const FluidSettings& settings, std::vector<Real>& densities,
                    std::vector<Real>& lambdas, int threads, std::vector<Real>* pairGradients,
                    const WallDensityInput* walls) {
  const LambdaJob job = makeLambdaJob(positions, lists, subset, kernels, settings, densities, lambdas,
                                      pairGradients, walls);
  runRanges(HS_DISPATCHED(LambdasRange), job, subset.size(), threads);
}

void computeDensityCorrections(const std::vector<Vec3>& positions, const NeighbourLists& lists,
                               std::span<const Index> subset, const SphKernels& kernels,
                               const FluidSettings& settings, const std::vector<Real>& lambdas,
                               std::vector<Vec3>& corrections, int threads,
                               const std::vector<Real>* pairGradients, const WallDensityInput* walls) {
  QuadCorrectionJob job{makeCorrectionJob(positions, lists, subset, kernels, settings, lambdas, corrections,
                                          pairGradients, walls),
                        nullptr};
  // (x, y, z, lambda) of every particle, 16 bytes, so that a neighbour is one 128-bit load.
  std::vector<Real> quads(4 * positions.size());
  const auto pack = [&](std::size_t begin, std::size_t end) {
    for (std::size_t j = begin; j < end; ++j) {
      quads[4 * j] = positions[j].x();
      quads[4 * j + 1] = positions[j].y();
      quads[4 * j + 2] = positions[j].z();
      quads[4 * j + 3] = lambdas[j];
    }
  };
  forRanges(positions.size(), threads, pack);
  job.quads = quads.data();
  runRanges(HS_DISPATCHED(CorrectionsRange), job, subset.size(), threads);
}

void applyViscosity(const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities,
                    const NeighbourLists& lists, std::span<const Index> subset,
                    const SphKernels& kernels, const FluidSettings& settings, Real dt,
                    std::vector<Vec3>& newVelocities, int threads) {
  const ViscosityJob job = makeViscosityJob(positions, velocities, lists, subset, kernels, settings, dt, newVelocities);
  runRanges(HS_DISPATCHED(ViscosityRange), job, subset.size(), threads);
}

void applyVorticityConfinement(const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities,
                               const NeighbourLists& lists, std::span<const Index> subset,
                               const SphKernels& kernels, const FluidSettings& settings, Real dt,
                               std::vector<Vec3>& vorticity, std::vector<Vec3>& newVelocities,
                               int threads) {
  const VorticityJob job =
      makeVorticityJob(positions, velocities, lists, subset, kernels, settings, dt, vorticity, newVelocities);
  // The second pass reads every neighbour's vorticity: the first must have finished.
  runRanges(HS_DISPATCHED(VorticityRange), job, subset.size(), threads);
  runRanges(HS_DISPATCHED(ConfinementRange), job, subset.size(), threads);
}

#undef HS_DISPATCHED

}  // namespace hs::pbd::simd
#endif  // HWY_ONCE
