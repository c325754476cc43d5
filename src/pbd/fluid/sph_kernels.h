#pragma once
// SPH smoothing kernels for Position Based Fluids (Macklin & Mueller 2013, "Position Based
// Fluids"; thesis eq. 4.8-4.11). The kernels are those of Mueller, Charypar & Gross 2003,
// "Particle-based fluid simulation for interactive applications" (SCA 2003), eq. 20-21:
//   poly6 for the density estimate  rho_i = sum_j m_j W_poly6(|x_i - x_j|, h)        (eq. 4.8)
//   spiky gradient for the density constraint gradient grad_{x_k} C_i             (eq. 4.9)
// h is the support radius: every kernel and gradient is zero for r >= h. Each kernel is
// normalised so that its integral over R^3 is 1 (checked in tests/pbd/fluid/test_sph_kernels.cpp).
//
// Float-friendliness: the formulas are evaluated in the scaled form with q = r / h, e.g.
//   315/(64 pi h^9) (h^2 - r^2)^3 = 315/(64 pi h^3) (1 - r^2/h^2)^3,
// so no intermediate is a power of h beyond the third (h^9 underflows/overflows in float for
// h far from 1). The constants are computed in double once and then rounded to Real.
#include <cmath>
#include <numbers>

#include "pbd/core/types.h"

namespace hs::pbd {

struct SphKernels {
  Real h;           // support radius
  Real h2;          // h^2 (poly6 takes squared distances)
  Real invH;        // 1 / h
  Real invH2;       // 1 / h^2
  Real poly6Coeff;  // 315 / (64 pi h^3)   (= 315/(64 pi h^9) * h^6)
  Real spikyCoeff;  // 15 / (pi h^3)       (= 15/(pi h^6) * h^3)
  Real spikyGradCoeff;  // -45 / (pi h^4)  (= -45/(pi h^6) * h^2)
};

inline SphKernels makeSphKernels(Real supportRadius) {
  const double h = static_cast<double>(supportRadius);
  const double pi = std::numbers::pi;
  SphKernels k;
  k.h = supportRadius;
  k.h2 = supportRadius * supportRadius;
  k.invH = static_cast<Real>(1.0 / h);
  k.invH2 = static_cast<Real>(1.0 / (h * h));
  k.poly6Coeff = static_cast<Real>(315.0 / (64.0 * pi * h * h * h));
  k.spikyCoeff = static_cast<Real>(15.0 / (pi * h * h * h));
  k.spikyGradCoeff = static_cast<Real>(-45.0 / (pi * h * h * h * h));
  return k;
}

// Poly6 kernel (Mueller et al. 2003, eq. 20), used for density (PBF eq. 4.8, thesis):
//   W(r) = 315/(64 pi h^9) (h^2 - r^2)^3   for 0 <= r < h,   0 otherwise.
// Takes the squared distance r2 = |x_i - x_j|^2, so no square root is needed.
HS_KERNEL Real poly6(const SphKernels& k, Real r2) {
  if (r2 >= k.h2) return Real(0);
  const Real t = Real(1) - r2 * k.invH2;  // (h^2 - r^2) / h^2
  return k.poly6Coeff * (t * t * t);
}

// Spiky kernel (Mueller et al. 2003, eq. 21, after Desbrun & Gascuel 1996):
//   W(r) = 15/(pi h^6) (h - r)^3   for 0 <= r < h,   0 otherwise.
// PBF only uses its gradient; the kernel itself is here to test the gradient against it.
HS_KERNEL Real spiky(const SphKernels& k, Real r) {
  if (r >= k.h) return Real(0);
  const Real t = Real(1) - r * k.invH;  // (h - r) / h
  return k.spikyCoeff * (t * t * t);
}

// Gradient of the spiky kernel with respect to x_i, r_ij = x_i - x_j, r = |r_ij|
// (Mueller et al. 2003, eq. 21; used for the density constraint gradient, PBF eq. 4.9):
//   grad W(r_ij) = -45/(pi h^6) (h - r)^2 r_ij / r   for 0 < r < h,   0 otherwise.
// It points from x_i towards x_j. At r = 0 the direction is undefined; the limit of the
// magnitude is not zero (the spiky kernel has a cusp), and the zero vector is returned so
// that a particle exerts no force on itself. grad W(-r_ij) = -grad W(r_ij).
HS_KERNEL Vec3 spikyGradient(const SphKernels& k, const Vec3& rij, Real r) {
  if (r >= k.h || r <= Real(0)) return Vec3::Zero();
  const Real t = Real(1) - r * k.invH;  // (h - r) / h
  return (k.spikyGradCoeff * t * t / r) * rij;
}

}  // namespace hs::pbd
