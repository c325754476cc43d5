#pragma once
// Scalar and vector types shared by the whole engine.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <cstdint>

// Hot kernels are small and called in tight loops; GCC at -O2 sometimes declines to inline
// them, which costs a third of the solver's time.
#define HS_KERNEL [[gnu::always_inline]] inline

namespace hs::pbd {

#ifdef HS_DOUBLE
using Real = double;
#else
using Real = float;
#endif

using Vec3 = Eigen::Matrix<Real, 3, 1>;
using Index = std::uint32_t;

}  // namespace hs::pbd
