#pragma once
// Position Based Fluids: the density constraint and XSPH viscosity of Macklin & Mueller 2013,
// "Position Based Fluids", ACM TOG 32(4), sections 3-5 (thesis section 4.2, eq. 4.7-4.11).
//
// One Jacobi iteration of the density solve is
//   computeLambdas             rho_i = sum_j m W_poly6(p_i - p_j, h)             (PBF eq. 2)
//                              lambda_i = -C_i / (sum_k |grad_{p_k} C_i|^2 + eps) (PBF eq. 11)
//   computeDensityCorrections  dp_i = (m/rho0) sum_j (lambda_i + lambda_j + s_corr) grad W  (eq. 12)
//                              plus the particle-particle collision of thesis eq. 4.6
// after which the caller adds dp_i to p_i. applyViscosity (XSPH, PBF eq. 17, and the SPH
// Laplacian of a physical viscosity) and applyVorticityConfinement (PBF eq. 15-16)
// post-process velocities.
//
// Mass convention: PBF (and thesis eq. 4.9-4.10) write grad C and dp with a factor 1/rho0,
// which assumes unit particle mass (the thesis says so under eq. 4.11). With a physical mass m
// in eq. 2 the chain rule gives grad_{p_k} C_i = (m/rho0) sum_j grad W, so here the factor is
// m/rho0; it equals the papers' 1/rho0 for m = 1. Without it the Newton step of eq. 9-11 would
// be scaled by m (a 4.3x overshoot for blood at the thesis spacing of 0.16 m).
//
// Support: every kernel term is exactly zero for |p_i - p_j| >= h (r^2 >= h^2), so lists may
// hold pairs beyond h (a skin kept over several steps): such pairs contribute nothing.
//
// Parallelism and determinism: every function is a gather. Each particle i of `subset` reads
// its neighbours through the CSR lists (neighbours sorted by j, neighbour_grid.h) and writes
// only its own output entry, so there are no atomics and no cross-thread reductions, and the
// result is bitwise identical for any thread count.
//
// Subsets: `subset` lists the particles whose outputs are computed (e.g. the fluid particles of
// a Particles set). Neighbours are whatever `lists` holds for them; every neighbour is treated
// as a fluid particle of mass m (computeDensityCorrections reads lambdas[j] for every listed
// neighbour j), so build the lists over the fluid particles only. Output vectors are resized to
// positions.size() when their size differs; entries outside `subset` are left unchanged.
#include <span>
#include <vector>

#include "pbd/core/types.h"
#include "pbd/fluid/sph_kernels.h"
#include "pbd/fluid/wall_density.h"
#include "pbd/grid/neighbour_grid.h"

namespace hs::pbd {

// Which implementation runs the neighbour loops of computeLambdas, computeDensityCorrections,
// applyViscosity and applyVorticityConfinement. Simd (fluid_simd.cpp, Highway) evaluates the
// same per-pair arithmetic, in the same operation order, eight neighbours at a time with a lane
// per neighbour, and sums the eight lanes in a fixed order: its results equal the scalar
// reference within float rounding (the sums over neighbours are re-associated), and are the
// same on every instruction set and thread count. Builds without Highway (HS_SIMD=OFF) run
// Scalar for both.
enum class FluidKernelPath { Scalar, Simd };

struct FluidSettings {
  Real restDensity = 1000;      // rho0, kg/m^3 (thesis Table: blood rest density 1000 kg/m^3)
  Real particleMass = 1;        // m, kg; particleMassFor(rho0, spacing) for a lattice at rest
  Real supportRadius = Real(0.32);  // h, m (thesis Table: kernel support radius 0.32 m)
  // epsilon of PBF eq. 11 (constraint-force mixing), in the units of sum_k |grad C|^2, 1/m^2.
  // Keeps lambda finite where a particle has few neighbours; it should be small next to the
  // sum of a full rest neighbourhood, measured in test_fluid.cpp as 0.37/d^2 for h = 2d and
  // 0.022/d^2 for h = 4d (d the spacing; 14.6/m^2 at the thesis's d = 0.16 m, h = 0.32 m).
  Real relaxation = Real(0.1);
  // Artificial pressure s_corr = -k (W_poly6(r)/W_poly6(deltaQ))^n against the tensile
  // instability (PBF eq. 13-14; PBF suggests k = 0.1, n = 4, |deltaQ| = 0.1..0.3 h).
  bool tensileCorrection = false;
  Real tensileK = Real(0.1);
  int tensileN = 4;
  Real tensileDeltaQRatio = Real(0.2);  // deltaQ = ratio * h
  // Unilateral density constraint C_i = max(rho_i/rho0 - 1, 0), i.e. lambda_i <- min(lambda_i, 0):
  // corrections only push apart. PBF's bilateral C also pulls under-dense particles together;
  // with no boundary particles, every particle at a wall or the free surface is under-dense
  // (a corner of the rest lattice has C = -0.32 at h = 2d) and has a small sum |grad C|^2, so
  // the pull is huge (measured: 16 m/s after one step, the column explodes within 0.1 s).
  // SPlisHSPlasH's PBF clamps C the same way (Bender et al., TimeStepPBF).
  bool unilateralDensity = true;
  // Particle-particle collision, thesis eq. 4.6: C(x_i, x_j) = |x_ij| - (r_i + r_j) >= 0 with
  // r_i = r_j = collisionRadius (m); 0 switches it off. Solved in the same Jacobi pass as the
  // density: each particle of an overlapping pair moves half the overlap apart.
  Real collisionRadius = 0;
  // c of PBF eq. 17, units m^3 (W is 1/m^3). Stable only while c sum_j W_ij < 1, and a full
  // neighbourhood has sum_j W_ij ~ rho0/m, so c must stay below m/rho0 (= d^3 at rest spacing d:
  // 0.0041 m^3 for the thesis's d = 0.16 m). Default: 0.003, what the settling test uses.
  Real xsphViscosity = Real(0.003);
  // nu = mu / rho0, m^2/s: the kinematic viscosity of the liquid, applied explicitly by the
  // SPH Laplacian of Monaghan 2005 ("Smoothed particle hydrodynamics", Rep. Prog. Phys. 68,
  // eq. 6.13; after Morris et al. 1997) in applyViscosity. 0 = inviscid.
  Real kinematicViscosity = 0;
  // epsilon of PBF eq. 16 (vorticity confinement): the acceleration is eps (N x omega) with
  // omega in 1/s, so eps is in m/s. 0 switches it off.
  Real vorticityConfinement = 0;
  // m: the longest density correction a particle may take in one iteration; 0 = no limit.
  // A heavily compressed particle (blood squeezed against a moving wall) gets a Newton step
  // of lambda grad C far longer than its neighbourhood, and would jump through a thin wall
  // in one iteration; PBF's linearisation is only valid for steps small against h.
  Real maxCorrection = 0;
  FluidKernelPath kernelPath = FluidKernelPath::Simd;
};

// Mass of one particle of a cubic lattice at rest: m = rho0 d^3 (one particle per d^3 cell).
inline Real particleMassFor(Real restDensity, Real spacing) {
  return restDensity * spacing * spacing * spacing;
}

// sum_k |grad_{p_k} C_i|^2 of PBF eq. 11 for an interior particle of a cubic lattice of
// spacing d at rest: the natural scale of the relaxation eps (which is in the same units).
Real latticeGradientSum(const SphKernels& kernels, Real spacing, Real mass, Real restDensity);

// rho_i = sum_j m W_poly6(|p_i - p_j|, h), j over the neighbours of i and i itself (PBF eq. 2,
// thesis eq. 4.8). The self term m W_poly6(0) comes first, then the neighbours in list order.
void computeDensities(const std::vector<Vec3>& positions, const NeighbourLists& lists,
                      std::span<const Index> subset, const SphKernels& kernels,
                      const FluidSettings& settings, std::vector<Real>& densities, int threads = 1);

// lambda_i = -C_i / (sum_k |grad_{p_k} C_i|^2 + eps), C_i = rho_i/rho0 - 1 (PBF eq. 1, 11;
// thesis eq. 4.7), with the gradient of PBF eq. 8 (thesis eq. 4.9), spiky kernel:
//   grad_{p_i} C_i = (m/rho0) sum_j grad W(p_i - p_j),  grad_{p_j} C_i = -(m/rho0) grad W(p_i - p_j).
// The densities rho_i (as computeDensities) come out of the same neighbour loop. With
// settings.unilateralDensity, lambda_i = min(lambda_i, 0). With pairGradients, the scalar
// s_ij of grad W(p_i - p_j) = s_ij (p_i - p_j) is stored per list entry, for
// computeDensityCorrections at the same positions (it then skips the square root and the
// division per pair, half of its cost). With walls, a particle with a wall within its support
// adds the wall's share (wall_density.h): rho_i += rho0 D(d), grad_{p_i} C_i += -G(d) n.
void computeLambdas(const std::vector<Vec3>& positions, const NeighbourLists& lists,
                    std::span<const Index> subset, const SphKernels& kernels,
                    const FluidSettings& settings, std::vector<Real>& densities,
                    std::vector<Real>& lambdas, int threads = 1,
                    std::vector<Real>* pairGradients = nullptr, const WallDensityInput* walls = nullptr);

// C_i = rho_i/rho0 - 1 (PBF eq. 1) for the particles of subset (diagnostics and tests).
void computeDensityConstraints(const std::vector<Real>& densities, std::span<const Index> subset,
                               const FluidSettings& settings, std::vector<Real>& constraints,
                               int threads = 1);

// dp_i = (m/rho0) sum_j (lambda_i + lambda_j + s_corr) grad W_spiky(p_i - p_j) (PBF eq. 12,
// thesis eq. 4.10), s_corr = -k (W_poly6(|p_i - p_j|)/W_poly6(deltaQ))^n when enabled (eq. 13),
// plus sum_j (1/2)(2r - |p_ij|) p_ij/|p_ij| over pairs closer than 2r (thesis eq. 4.6, equal
// masses) when settings.collisionRadius = r > 0. With walls, the wall's share of grad_{p_i} C_i
// adds 2 lambda_i (-G(d) n): the wall's share of i's own constraint and, as for a fluid neighbour
// j (lambda_i + lambda_j), a mirrored one with the wall's lambda taken as lambda_i (pressure
// mirroring, Akinci et al. 2012): a compressed particle is pushed off the wall, which does not move.
void computeDensityCorrections(const std::vector<Vec3>& positions, const NeighbourLists& lists,
                               std::span<const Index> subset, const SphKernels& kernels,
                               const FluidSettings& settings, const std::vector<Real>& lambdas,
                               std::vector<Vec3>& corrections, int threads = 1,
                               const std::vector<Real>* pairGradients = nullptr,
                               const WallDensityInput* walls = nullptr);

// Viscosity in the velocity post-process (thesis Algorithm 1 line 15), one neighbour loop:
//   v_i^new = v_i + c sum_j (v_j - v_i) W_poly6(|x_ij|, h)                         (XSPH)
//         + dt 2(d+2) nu (m/rho0) sum_j (v_ij . x_ij)/(|x_ij|^2 + 0.01 h^2) grad W(x_ij)
// with d = 3, v_ij = v_i - v_j, x_ij = x_i - x_j. The first term is XSPH (PBF eq. 17). Thesis
// eq. 4.11 writes v_i - gamma sum_j (m/rho_i)(v_i - v_j) W, the same sign and an extra m/rho_i
// factor: c = gamma m/rho0 (rho0 rather than rho_i keeps the pair terms antisymmetric, so
// momentum is conserved). The second term is the SPH Laplacian nu lap(v) of a Newtonian liquid
// (Monaghan 2005 eq. 6.13), explicit, stable for dt < 0.125 h^2/nu; it gives the liquid its
// physical viscosity, which XSPH (a velocity filter) does not. Reads velocities, writes
// newVelocities (must not be the same vector: Jacobi update).
void applyViscosity(const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities,
                    const NeighbourLists& lists, std::span<const Index> subset,
                    const SphKernels& kernels, const FluidSettings& settings, Real dt,
                    std::vector<Vec3>& newVelocities, int threads = 1);

// Vorticity confinement (PBF eq. 15-16, after Fedkiw et al. 2001), adds back small-scale
// swirl that the position solve and XSPH dissipate:
//   omega_i = sum_j (m/rho0) (v_i - v_j) x grad_i W(x_ij)  (SPH curl of v)
//   eta_i = sum_j (m/rho0) (|omega_j| - |omega_i|) grad_i W(x_ij)  (gradient of |omega|), N = eta/|eta|
//   v_i += dt eps (N x omega_i)
// `vorticity` is a work array (resized). Reads velocities, writes newVelocities.
void applyVorticityConfinement(const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities,
                               const NeighbourLists& lists, std::span<const Index> subset,
                               const SphKernels& kernels, const FluidSettings& settings, Real dt,
                               std::vector<Vec3>& vorticity, std::vector<Vec3>& newVelocities,
                               int threads = 1);

}  // namespace hs::pbd
