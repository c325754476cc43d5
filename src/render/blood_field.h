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
#include <cstdint>
#include <vector>

#include "cardiac/heart_simulation.h"
#include "pbd/fluid/velocity_field.h"
#include "render/camera.h"

namespace hs::render {

// Four channels per point: velocity x, y, z and pressure.
using FieldValue = pbd::FieldVec4;

// The interpolation at every point of `positions` over all of them: the flow meter's Shepard
// average (pbd::shepardAverage, velocity_field.h) over neighbour lists found at these positions
// (grid search, cell = h), so the colours and the Doppler readings come from one piece of code.
// (The solver's lists, which the Doppler readings use, are found before the step's contacts move
// the blood; a particle the contacts throw several millimetres has few of its new neighbours
// there, and its average is mostly its own velocity. The lists here are the drawn positions'.)
std::vector<FieldValue> smoothField(const std::vector<pbd::Vec3>& positions, const std::vector<FieldValue>& values,
                                    pbd::Real supportRadius);
// The same by testing every pair: the reference the grid search is checked against.
std::vector<FieldValue> smoothFieldBruteForce(const std::vector<pbd::Vec3>& positions,
                                              const std::vector<FieldValue>& values, pbd::Real supportRadius);

// The active blood particles (not parked outside the model) with their smoothed velocity
// (m/s) and pressure (Pa).
struct BloodField {
  std::vector<pbd::Index> particle;  // particle index in sim.particles()
  // 1: in a vessel's far-end buffer, the lumped model's boundary (HeartSimulation::bloodInVesselEnd).
  std::vector<std::uint8_t> vesselEnd;
  std::vector<Vec3f> position, velocity;
  std::vector<float> pressure;
};
BloodField smoothedBlood(const cardiac::HeartSimulation& sim);

}  // namespace hs::render
