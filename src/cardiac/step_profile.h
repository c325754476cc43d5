#pragma once
// Wall time per stage of HeartSimulation::step, summed over the steps since it was attached:
// what `heartsim bench --case normal` prints beside its steps per second, so that the effect of
// a change on each stage can be seen (perf says where inside a stage). Timing costs two clock
// reads per stage, so it runs only when a profile is attached; the physics is the same either way.
#include <array>
#include <chrono>
#include <cstddef>
#include <string_view>

namespace hs::cardiac {

enum class StepStage : std::size_t {
  Begin,            // reorder, lumped circulation, valves, flow meter
  Forces,           // filling pressure, gravity; p = x + dt v
  MoveWall,         // cardiac cycle or driven wall, vessels' ends
  WallConstraints,  // the wall's own PBD constraints
  Neighbours,       // the blood's cell grid and neighbour lists
  WallLending,      // nearest wall of each blood particle (wall density)
  DensityKernels,   // lambdas and corrections, all iterations
  WallInIterations, // valves, wall push-out and vessels' ends inside the iterations
  Contacts,         // valves and wall push-out after the wall has moved
  Velocities,       // v = (p - x)/dt; viscosity, XSPH
  End,              // flows, the closed loop
  Count
};

constexpr std::array<std::string_view, std::size_t(StepStage::Count)> kStepStageNames{
    "begin",           "forces",             "move_wall", "wall_constraints", "neighbours", "wall_lending",
    "density_kernels", "wall_in_iterations", "contacts",  "velocities",       "end"};

struct StepProfile {
  std::array<double, std::size_t(StepStage::Count)> seconds{};
  long steps = 0;
};

// Adds the time since the previous lap (or construction) to a stage; no-op without a profile.
class StageLaps {
 public:
  using Clock = std::chrono::steady_clock;
  explicit StageLaps(StepProfile* profile) : m_profile(profile) {
    if (m_profile) m_last = Clock::now();
  }
  void lap(StepStage stage) {
    if (!m_profile) return;
    const Clock::time_point now = Clock::now();
    m_profile->seconds[std::size_t(stage)] += std::chrono::duration<double>(now - m_last).count();
    m_last = now;
  }

 private:
  StepProfile* m_profile;
  Clock::time_point m_last{};
};

}  // namespace hs::cardiac
