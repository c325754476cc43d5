#include "cardiac/motion/wall_motion.h"

namespace hs::cardiac {

void PrescribedCycleMotion::move(std::vector<Vec3>& position, std::vector<Vec3>& predicted,
                                 const pbd::StepContext& context) {
  m_cycle.apply(position, predicted, context);
}

// The lumped ventricle's volume at the end of this step (the circulation advanced first).
void VolumeFollowingMotion::move(std::vector<Vec3>& position, std::vector<Vec3>& predicted,
                                 const pbd::StepContext& context) {
  m_cycle.advanceClocks(context.dt);
  m_wall.drive(position, predicted, m_lumped.last().lvVolume);
}

// The recording's surface at the end of this step.
void RecordedBeatMotion::move(std::vector<Vec3>&, std::vector<Vec3>& predicted, const pbd::StepContext& context) {
  m_cycle.advanceClocks(context.dt);
  m_beat.drive(double(context.stepIndex + 1) * double(context.dt), predicted);
}

}  // namespace hs::cardiac
