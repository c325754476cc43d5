#pragma once
// Particle state as structure-of-arrays. Every simulated point, wall vertex or blood particle,
// lives here; `kind` lets later stages (fluid density, coupling) select their own particles.
#include <vector>

#include "pbd/types.h"

namespace hs::pbd {

enum class ParticleKind : std::uint8_t { Tissue = 0, Fluid = 1 };

struct Particles {
  std::vector<Vec3> position;   // x: state at the start of a step
  std::vector<Vec3> predicted;  // p: predicted / corrected position during a step
  std::vector<Vec3> velocity;   // v
  std::vector<Real> inverseMass;  // w = 1/m; 0 = kinematic (pinned)
  std::vector<ParticleKind> kind;

  [[nodiscard]] std::size_t size() const { return position.size(); }

  Index add(const Vec3& x, Real inverseMassValue, ParticleKind particleKind) {
    position.push_back(x);
    predicted.push_back(x);
    velocity.push_back(Vec3::Zero());
    inverseMass.push_back(inverseMassValue);
    kind.push_back(particleKind);
    return static_cast<Index>(position.size() - 1);
  }
};

}  // namespace hs::pbd
