#pragma once
// Particle state as structure-of-arrays. Every simulated point, wall vertex or blood particle,
// lives here; `kind` lets later stages (fluid density, coupling) select their own particles.
//
// Identity and state travel with the particle: `id` is its creation index, stable however the
// set is reordered (permuteRange moves every column), and `state` says whether it takes part
// in the step. A pinned wall vertex (inverse mass 0: kinematic, moved only by its owner) and a
// parked blood particle (state Parked: waiting outside the model, ignored by every solver
// stage, keeping its mass) are different things.
#include <algorithm>
#include <cassert>
#include <type_traits>
#include <vector>

#include "pbd/core/state_stream.h"
#include "pbd/core/types.h"

namespace hs::pbd {

enum class ParticleKind : std::uint8_t { Tissue = 0, Fluid = 1 };
enum class ParticleState : std::uint8_t { Active = 0, Parked = 1 };

struct Particles {
  std::vector<Vec3> position;   // x: state at the start of a step
  std::vector<Vec3> predicted;  // p: predicted / corrected position during a step
  std::vector<Vec3> velocity;   // v
  std::vector<Real> inverseMass;  // w = 1/m; 0 = kinematic (pinned)
  std::vector<ParticleKind> kind;
  std::vector<Index> id;               // creation index, stable under reordering
  std::vector<ParticleState> state;

  [[nodiscard]] std::size_t size() const { return position.size(); }
  [[nodiscard]] bool active(std::size_t i) const { return state[i] == ParticleState::Active; }
  // Moved by the solver stages: active and not pinned.
  [[nodiscard]] bool dynamic(std::size_t i) const { return active(i) && inverseMass[i] > Real(0); }

  Index add(const Vec3& x, Real inverseMassValue, ParticleKind particleKind) {
    const auto index = static_cast<Index>(position.size());
    position.push_back(x);
    predicted.push_back(x);
    velocity.push_back(Vec3::Zero());
    inverseMass.push_back(inverseMassValue);
    kind.push_back(particleKind);
    id.push_back(index);
    state.push_back(ParticleState::Active);
    return index;
  }

  // Checkpoints (state_stream.h): every column. A set of another size is another scenario's.
  void save(StateWriter& w) const {
    w.section("particles");
    w.fields(position, predicted, velocity, inverseMass, kind, id, state);
  }
  void load(StateReader& r) {
    r.section("particles");
    const std::size_t n = size();
    r.getSized(position, n, "particles: positions");
    r.getSized(predicted, n, "particles: predictions");
    r.getSized(velocity, n, "particles: velocities");
    r.getSized(inverseMass, n, "particles: inverse masses");
    r.getSized(kind, n, "particles: kinds");
    r.getSized(id, n, "particles: ids");
    r.getSized(state, n, "particles: states");
  }
};

// Permutes the particles [first, first + order.size()): slot first + k receives the particle
// that was at first + order[k], with all its columns. Used to keep spatial neighbours close in
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
  permute(particles.id);
  permute(particles.state);
}

}  // namespace hs::pbd
