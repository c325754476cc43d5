#pragma once
// What moves the wall each step, chosen once when the heart is built (HeartSimulation::
// buildHeart) from what the scenario asks for, so that the step itself asks nothing:
//   PrescribedCycleMotion  the cardiac cycle moves its beating vertices (thesis Algorithms 2-3,
//                          or the physiological clock; cardiac_cycle.h);
//   VolumeFollowingMotion  the lumped circulation's ventricular volume sets the wall's shape
//                          (volume_driven_wall.h), the cycle keeps the clocks;
//   RecordedBeatMotion     a recorded beat moves the endocardium (recorded_beat.h), the cycle
//                          keeps the clocks.
// Each holds the pieces it drives, which the simulation owns and outlive it.
#include <vector>

#include "cardiac/circulation/lumped_circulation.h"
#include "cardiac/motion/cardiac_cycle.h"
#include "cardiac/motion/recorded_beat.h"
#include "cardiac/motion/volume_driven_wall.h"
#include "pbd/core/step_context.h"

namespace hs::cardiac {

class WallMotion {
 public:
  virtual ~WallMotion() = default;
  // Moves the predictions of the wall's driven vertices to where this step ends
  // (position: where the step starts; the thesis cycle moves it too).
  virtual void move(std::vector<Vec3>& position, std::vector<Vec3>& predicted,
                    const pbd::StepContext& context) = 0;
};

class PrescribedCycleMotion final : public WallMotion {
 public:
  explicit PrescribedCycleMotion(CardiacCycle& cycle) : m_cycle(cycle) {}
  void move(std::vector<Vec3>& position, std::vector<Vec3>& predicted, const pbd::StepContext& context) override;

 private:
  CardiacCycle& m_cycle;
};

class VolumeFollowingMotion final : public WallMotion {
 public:
  VolumeFollowingMotion(CardiacCycle& cycle, VolumeDrivenWall& wall, const LumpedCirculation& lumped)
      : m_cycle(cycle), m_wall(wall), m_lumped(lumped) {}
  void move(std::vector<Vec3>& position, std::vector<Vec3>& predicted, const pbd::StepContext& context) override;

 private:
  CardiacCycle& m_cycle;
  VolumeDrivenWall& m_wall;
  const LumpedCirculation& m_lumped;
};

class RecordedBeatMotion final : public WallMotion {
 public:
  RecordedBeatMotion(CardiacCycle& cycle, RecordedBeat& beat) : m_cycle(cycle), m_beat(beat) {}
  void move(std::vector<Vec3>& position, std::vector<Vec3>& predicted, const pbd::StepContext& context) override;

 private:
  CardiacCycle& m_cycle;
  RecordedBeat& m_beat;
};

}  // namespace hs::cardiac
