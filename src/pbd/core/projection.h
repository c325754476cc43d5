#pragma once
// The one XPBD update every bilateral constraint shares (Macklin, Mueller, Chentanez 2016,
// "XPBD", eq. 18; with alpha = 0 it is Mueller et al. 2007 PBD, thesis eq. 3.3-3.4):
//   dLambda = k * (-C - alphaTilde * lambda) / (sum_i w_i |grad_i C|^2 + alphaTilde)
//   dx_i    = w_i * grad_i C * dLambda,      alphaTilde = alpha / dt^2
// k is the PBD stiffness in [0, 1] (thesis Table 5.3: 0.5). Pure: no state is touched.
#include "pbd/core/types.h"

namespace hs::pbd {

struct ProjectionParams {
  Real alphaTilde = 0;  // compliance / dt^2
  Real stiffness = 1;   // k
};

// gradientNorm = sum_i w_i |grad_i C|^2. A degenerate configuration (all gradients zero, or
// every particle pinned) cannot be corrected: no change.
HS_KERNEL Real xpbdDeltaLambda(Real c, Real gradientNorm, const ProjectionParams& params, Real lambda) {
  const Real denominator = gradientNorm + params.alphaTilde;
  constexpr Real kTiny = Real(1e-30);
  if (denominator <= kTiny) return 0;
  return params.stiffness * (-c - params.alphaTilde * lambda) / denominator;
}

}  // namespace hs::pbd
