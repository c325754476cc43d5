#pragma once
// The fluid's smoothed velocity: each particle's velocity replaced by the SPH interpolation of
// the velocity field at its position, Shepard-normalised (Monaghan 1992, "Smoothed particle
// hydrodynamics", ARA&A 30, eq. 2.1 with the Shepard 1968 denominator; Monaghan 2005 section 2):
//   v~_i = sum_j V_j v_j W(x_i - x_j, h) / sum_j V_j W(x_i - x_j, h),   j over i's neighbours and i,
// with the poly6 kernel W of the density estimate (sph_kernels.h) and V_j = m_j / rho0 the
// particle's volume (0: the particle takes no part). The denominator makes a constant field exact
// where the neighbourhood is cut by a wall or a free surface, where the plain sum would fall short.
//
// Why: PBF's per-particle velocities carry the position corrections' noise (neighbours differ by
// ~0.5 m/s in a beating heart); a measurement that reads one particle (the fastest through an
// orifice) reads the noise. The interpolated field is what a jet is, and what a clinician's
// Doppler sample volume, a few millimetres across, averages over. A measurement only: the solver
// never reads it.
//
// A per-particle gather over the lists, self term first and then the neighbours in list order,
// so the result is bitwise identical for any thread count.
#include <span>
#include <vector>

#include "pbd/core/types.h"
#include "pbd/fluid/sph_kernels.h"
#include "pbd/grid/neighbour_grid.h"

namespace hs::pbd {

// Several channels at once (the viewer's velocity and pressure): the same Shepard average.
using FieldVec4 = Eigen::Matrix<Real, 4, 1>;

// A~_i = sum_j V_j A_j W_ij / sum_j V_j W_ij for every i of `subset` (indices into positions),
// for any value type (Vec3: the velocity v~; FieldVec4: the viewer's velocity and pressure),
// written to smoothed[i]; the other entries of `smoothed` are left as they are (it is resized to
// positions.size() if smaller). lists[i] are i's neighbours (within h when the lists were built;
// a pair farther apart now adds nothing, W = 0 beyond h). A particle whose weights sum to 0 (its
// own volume 0 and no neighbour with a volume) keeps its own value. The one piece of code behind
// the Doppler readings (FluidSolver::smoothedVelocities) and the speed colours
// (render/blood_field.h).
template <class Value>
void shepardAverage(const std::vector<Vec3>& positions, const std::vector<Value>& values,
                    const std::vector<Real>& volumes, const NeighbourLists& lists, std::span<const Index> subset,
                    const SphKernels& kernels, std::vector<Value>& smoothed, int threads = 1);

// The same by testing every pair: the reference the lists are checked against.
std::vector<Vec3> smoothVelocitiesBruteForce(const std::vector<Vec3>& positions, const std::vector<Vec3>& velocities,
                                             const std::vector<Real>& volumes, const SphKernels& kernels);

}  // namespace hs::pbd
