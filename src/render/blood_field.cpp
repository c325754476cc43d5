#include "render/blood_field.h"

#include "pbd/fluid/sph_kernels.h"
#include "pbd/grid/neighbour_grid.h"

namespace hs::render {

std::vector<FieldValue> smoothField(const std::vector<pbd::Vec3>& positions, const std::vector<FieldValue>& values,
                                    pbd::Real supportRadius) {
  const pbd::SphKernels kernels = pbd::makeSphKernels(supportRadius);
  pbd::NeighbourGrid grid;
  grid.build(positions, supportRadius);
  std::vector<FieldValue> smoothed(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const pbd::Real self = pbd::poly6(kernels, 0);
    FieldValue sum = values[i] * self;
    pbd::Real weight = self;
    grid.forEachNeighbour(pbd::Index(i), positions, supportRadius, [&](pbd::Index j, const pbd::Vec3&, pbd::Real r2) {
      const pbd::Real w = pbd::poly6(kernels, r2);
      sum += values[j] * w;
      weight += w;
    });
    smoothed[i] = sum / weight;
  }
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
