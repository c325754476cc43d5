#include "render/blood_field.h"

#include "pbd/fluid/sph_kernels.h"
#include "pbd/fluid/velocity_field.h"
#include "pbd/grid/neighbour_grid.h"

namespace hs::render {

std::vector<FieldValue> smoothField(const std::vector<pbd::Vec3>& positions, const std::vector<FieldValue>& values,
                                    pbd::Real supportRadius) {
  // The Doppler readings' own average (pbd::shepardAverage) over lists found at these positions:
  // equal volumes, which the Shepard denominator cancels.
  const pbd::SphKernels kernels = pbd::makeSphKernels(supportRadius);
  pbd::NeighbourGrid grid;
  grid.build(positions, supportRadius);
  pbd::NeighbourLists lists;
  grid.buildNeighbourLists(positions, supportRadius, lists);
  std::vector<pbd::Index> all(positions.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = pbd::Index(i);
  std::vector<FieldValue> smoothed;
  pbd::shepardAverage(positions, values, std::vector<pbd::Real>(positions.size(), pbd::Real(1)), lists, all, kernels,
                      smoothed);
  return smoothed;
}

std::vector<FieldValue> smoothFieldBruteForce(const std::vector<pbd::Vec3>& positions,
                                              const std::vector<FieldValue>& values, pbd::Real supportRadius) {
  const pbd::SphKernels kernels = pbd::makeSphKernels(supportRadius);
  std::vector<FieldValue> smoothed(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    FieldValue sum = FieldValue::Zero();
    pbd::Real weight = 0;
    for (std::size_t j = 0; j < positions.size(); ++j) {
      const pbd::Real w = pbd::poly6(kernels, (positions[i] - positions[j]).squaredNorm());
      sum += values[j] * w;
      weight += w;
    }
    smoothed[i] = sum / weight;
  }
  return smoothed;
}

BloodField smoothedBlood(const cardiac::HeartSimulation& sim) {
  BloodField field;
  if (!sim.hasBlood()) return field;
  const pbd::Particles& p = sim.particles();
  const std::vector<pbd::Real>& pressure = sim.pressures();
  std::vector<pbd::Vec3> positions;
  std::vector<FieldValue> values;
  for (std::size_t i = sim.firstBloodParticle(); i < p.size(); ++i) {
    if (!sim.bloodActive(pbd::Index(i))) continue;  // parked outside the model (circulation.h)
    field.particle.push_back(pbd::Index(i));
    field.vesselEnd.push_back(sim.bloodInVesselEnd(pbd::Index(i)) ? 1 : 0);
    positions.push_back(p.position[i]);
    FieldValue v;
    v << p.velocity[i], i < pressure.size() ? pressure[i] : pbd::Real(0);
    values.push_back(v);
  }
  const std::vector<FieldValue> smoothed = smoothField(positions, values, sim.scenario().blood.supportRadius);
  for (std::size_t k = 0; k < positions.size(); ++k) {
    field.position.push_back(positions[k].cast<float>());
    field.velocity.push_back(smoothed[k].head<3>().cast<float>());
    field.pressure.push_back(float(smoothed[k][3]));
  }
  return field;
}

}  // namespace hs::render
