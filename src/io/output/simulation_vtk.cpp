#include "io/output/simulation_vtk.h"

#include <string>

namespace hs::io {

VtuFrame wallFrame(const cardiac::HeartSimulation& sim) {
  const auto& model = sim.model();
  VtuFrame frame;
  frame.points.assign(sim.particles().position.begin(),
                      sim.particles().position.begin() + static_cast<std::ptrdiff_t>(model.mesh.vertices.size()));
  frame.tets = model.mesh.tets;
  std::vector<int> segment(model.segment.begin(), model.segment.end());
  std::vector<int> region;
  for (auto r : model.region) region.push_back(static_cast<int>(r));
  frame.intArrays = {{"aha_segment", segment}, {"region", region}};
  std::vector<pbd::Vec3> velocity(sim.particles().velocity.begin(),
                                  sim.particles().velocity.begin() + static_cast<std::ptrdiff_t>(frame.points.size()));
  std::vector<pbd::Vec3> displacement(frame.points.size());
  for (std::size_t i = 0; i < frame.points.size(); ++i) displacement[i] = frame.points[i] - model.mesh.vertices[i];
  frame.vectorArrays = {{"velocity", velocity}, {"displacement", displacement}};
  return frame;
}

VtuFrame bloodFrame(const cardiac::HeartSimulation& sim) {
  VtuFrame frame;
  const auto first = static_cast<std::ptrdiff_t>(sim.firstBloodParticle());
  frame.points.assign(sim.particles().position.begin() + first, sim.particles().position.end());
  std::vector<pbd::Vec3> velocity(sim.particles().velocity.begin() + first, sim.particles().velocity.end());
  frame.vectorArrays = {{"velocity", velocity}};
  // 0: parked outside the model by the closed loop, waiting to re-enter (hide with a threshold).
  std::vector<int> active;
  for (std::size_t i = sim.firstBloodParticle(); i < sim.particles().size(); ++i)
    active.push_back(sim.bloodActive(pbd::Index(i)) ? 1 : 0);
  frame.intArrays = {{"active", active}};
  return frame;
}

SimulationVtkSeries::SimulationVtkSeries(const std::filesystem::path& dir, bool heart, bool blood)
    : m_dir(dir), m_heart(heart), m_blood(blood), m_wall(dir / "wall.pvd"), m_bloodSeries(dir / "blood.pvd") {}

void SimulationVtkSeries::write(const cardiac::HeartSimulation& sim, std::int64_t step) {
  const std::string suffix = "_" + std::to_string(step) + ".vtu";
  if (m_heart) {
    writeVtu(m_dir / ("wall" + suffix), wallFrame(sim));
    m_wall.add(sim.time(), "wall" + suffix);
  }
  if (m_blood) {
    writeVtu(m_dir / ("blood" + suffix), bloodFrame(sim));
    m_bloodSeries.add(sim.time(), "blood" + suffix);
  }
}

void SimulationVtkSeries::finish() const {
  if (m_heart) m_wall.write();
  if (m_blood) m_bloodSeries.write();
}

}  // namespace hs::io
