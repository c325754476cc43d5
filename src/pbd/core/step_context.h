#pragma once
// What every stage of one step shares, made once per step by the world that owns the step
// and passed to each stage (box2d's b2StepContext, Jolt's SoftBodyUpdateContext). The time
// step lives here and nowhere else: settings describe the model, the context the step.
#include <cstdint>

#include "pbd/core/types.h"

namespace hs::pbd {

struct StepContext {
  Real dt = 0;                   // s
  Real inverseDt = 0;            // 1/s, = 1 / dt
  Vec3 gravity = Vec3::Zero();   // m/s^2
  int threads = 1;               // OpenMP threads for the stages' parallel loops
  std::int64_t stepIndex = 0;    // steps taken before this one
};

inline StepContext makeStepContext(Real dt, const Vec3& gravity, int threads, std::int64_t stepIndex = 0) {
  return {dt, Real(1) / dt, gravity, threads, stepIndex};
}

}  // namespace hs::pbd
