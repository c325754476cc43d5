#pragma once
// A HeartSimulation as ParaView frames: the wall as tetrahedra (AHA segment, region, velocity,
// displacement from rest) and the blood as points (velocity, and whether each is active), one
// .pvd series per body in the output directory.
#include <cstdint>
#include <filesystem>

#include "cardiac/heart_simulation.h"
#include "io/output/vtk_writer.h"

namespace hs::io {

VtuFrame wallFrame(const cardiac::HeartSimulation& sim);
VtuFrame bloodFrame(const cardiac::HeartSimulation& sim);

// wall_N.vtu and blood_N.vtu per frame (N the step), wall.pvd and blood.pvd at finish().
// Throws std::runtime_error naming the file that cannot be written.
class SimulationVtkSeries {
 public:
  SimulationVtkSeries(const std::filesystem::path& dir, bool heart, bool blood);
  void write(const cardiac::HeartSimulation& sim, std::int64_t step);
  void finish() const;

 private:
  std::filesystem::path m_dir;
  bool m_heart, m_blood;
  PvdSeries m_wall, m_bloodSeries;
};

}  // namespace hs::io
