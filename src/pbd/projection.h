#pragma once
// The one XPBD update every bilateral constraint shares (Macklin, Mueller, Chentanez 2016,
// "XPBD", eq. 18; with alpha = 0 it is Mueller et al. 2007 PBD, thesis eq. 3.3-3.4):
//   dLambda = k * (-C - alphaTilde * lambda) / (sum_i w_i |grad_i C|^2 + alphaTilde)
//   dx_i    = w_i * grad_i C * dLambda,      alphaTilde = alpha / dt^2
// k is the PBD stiffness in [0, 1] (thesis Table 5.3: 0.5). Pure: no state is touched.
#include <array>
#include <cstddef>

#include "pbd/types.h"

namespace hs::pbd {

struct ProjectionParams {
  Real alphaTilde = 0;  // compliance / dt^2
  Real stiffness = 1;   // k
};

template <std::size_t N>
struct Projection {
  std::array<Vec3, N> dx;
  Real deltaLambda = 0;
};

// A constraint value and its gradient with respect to each of its N particles.
template <std::size_t N>
struct ConstraintEval {
  Real value = 0;
  std::array<Vec3, N> gradient;
};

template <std::size_t N>
Projection<N> projectXpbd(const ConstraintEval<N>& c, const std::array<Real, N>& w,
                          const ProjectionParams& params, Real lambda) {
  Projection<N> out;
  Real denominator = params.alphaTilde;
  for (std::size_t i = 0; i < N; ++i) denominator += w[i] * c.gradient[i].squaredNorm();
  // A degenerate configuration (all gradients zero or all particles pinned) cannot be corrected.
  constexpr Real kTiny = Real(1e-30);
  if (denominator <= kTiny) {
    for (auto& d : out.dx) d.setZero();
    return out;
  }
  out.deltaLambda = params.stiffness * (-c.value - params.alphaTilde * lambda) / denominator;
  for (std::size_t i = 0; i < N; ++i) out.dx[i] = (w[i] * out.deltaLambda) * c.gradient[i];
  return out;
}

}  // namespace hs::pbd
