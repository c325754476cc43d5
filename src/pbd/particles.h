#pragma once
// Particle state as structure-of-arrays. Every simulated point, wall vertex or blood particle,
// lives here; `kind` lets later stages (fluid density, coupling) select their own particles.
#include <algorithm>
#include <cassert>
#include <type_traits>
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

// Permutes the particles [first, first + order.size()): slot first + k receives the particle
// that was at first + order[k], with all its state. Used to keep spatial neighbours close in
// memory (neighbour_grid.h, mortonOrder).
inline void permuteRange(Particles& particles, Index first, const std::vector<Index>& order) {
  assert(first + order.size() <= particles.size());
  auto permute = [&](auto& values) {
    using T = typename std::decay_t<decltype(values)>::value_type;
    std::vector<T> moved;
    moved.reserve(order.size());
    for (const Index o : order) moved.push_back(values[first + o]);
    std::copy(moved.begin(), moved.end(), values.begin() + first);
  };
  permute(particles.position);
  permute(particles.predicted);
  permute(particles.velocity);
  permute(particles.inverseMass);
  permute(particles.kind);
}

}  // namespace hs::pbd
