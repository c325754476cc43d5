#pragma once
// The blood's velocity and pressure as fields, for colours and flow lines: each particle's
// value replaced by the SPH interpolation over its neighbours with the solver's own kernel
// (poly6, support h = blood.support_radius), Shepard-normalised so that a constant field stays
// constant near the wall where neighbours are missing (Monaghan 1992, "Smoothed particle
// hydrodynamics", ARA&A 30, eq. 2.1; Shepard 1968):
//   A(x_i) = sum_j A_j W(|x_i - x_j|, h) / sum_j W(|x_i - x_j|, h),   j over the neighbours and i.
// With equal masses and densities near rest the volumes m_j / rho_j cancel. Per-particle
// velocities of PBF are noisy (neighbours differ by ~1 m/s after the position corrections);
// the interpolated field is the one a jet or a vortex shows in. Drawing only: the simulation
// is not touched.
#include <vector>

#include "cardiac/heart_simulation.h"
#include "render/camera.h"

namespace hs::render {

// Four channels per point: velocity x, y, z and pressure.
using FieldValue = Eigen::Matrix<pbd::Real, 4, 1>;

// The interpolation at every point of `positions` over all of them (grid search, cell = h).
std::vector<FieldValue> smoothField(const std::vector<pbd::Vec3>& positions, const std::vector<FieldValue>& values,
                                    pbd::Real supportRadius);
// The same by testing every pair: the reference the grid search is checked against.
std::vector<FieldValue> smoothFieldBruteForce(const std::vector<pbd::Vec3>& positions,
                                              const std::vector<FieldValue>& values, pbd::Real supportRadius);

// The active blood particles (not parked outside the model) with their smoothed velocity
// (m/s) and pressure (Pa).
struct BloodField {
  std::vector<pbd::Index> particle;  // particle index in sim.particles()
  std::vector<Vec3f> position, velocity;
  std::vector<float> pressure;
};
BloodField smoothedBlood(const cardiac::HeartSimulation& sim);

}  // namespace hs::render
