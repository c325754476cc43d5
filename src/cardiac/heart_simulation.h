#pragma once
// One simulated world: the beating heart wall (the LV model as a PBD soft body driven by the
// cardiac cycle) and/or blood (PBF particles). Both live in one particle set and one step,
// following thesis Fig. 4.1 / Algorithm 1: external forces and prediction, then the cardiac
// cycle moves the beating vertices and the blood's density constraints are solved, then the
// wall's constraints are projected, then velocities are updated and the blood's are
// post-processed (viscosity). The wall particles come first (particle = model vertex), then
// the blood. With both, blood that the moving wall has swept over is pushed back out of the
// wall's tetrahedra after the wall's constraints (thesis 4.4, one-way: the wall does not feel
// the blood yet).
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "cardiac/blood.h"
#include "cardiac/cardiac_cycle.h"
#include "cardiac/circulation.h"
#include "cardiac/lv_model.h"
#include "cardiac/scenario.h"
#include "pbd/fluid_solver.h"
#include "pbd/particle_tet_collision.h"
#include "pbd/solver.h"

namespace hs::cardiac {

struct TissueStats {
  Real volumeErrorMax = 0;   // max over tets of |V - V0| / V0
  Real volumeErrorMean = 0;  // mean over tets of |V - V0| / V0
  std::size_t invertedTets = 0;  // tets with V <= 0
  Index firstInvertedTet = 0;    // model tet id, when invertedTets > 0
  bool finite = true;        // every position and velocity finite
  Index firstNonFinite = 0;  // particle id, when !finite
};

class HeartSimulation {
 public:
  // Throws std::invalid_argument for parameters the model or cycle reject.
  HeartSimulation(const Scenario& scenario, int threads);

  void step();

  [[nodiscard]] const Scenario& scenario() const { return m_scenario; }
  [[nodiscard]] bool hasHeart() const { return m_model.has_value(); }
  [[nodiscard]] bool hasBlood() const { return m_fluid != nullptr; }
  // Heart only (hasHeart()).
  [[nodiscard]] const LvModel& model() const { return *m_model; }
  [[nodiscard]] const CardiacCycle& cycle() const { return *m_cycle; }
  [[nodiscard]] const pbd::Particles& particles() const { return m_particles; }
  [[nodiscard]] const pbd::ConstraintSet& constraints() const { return m_constraints; }
  // Blood particles are [firstBloodParticle(), particles().size()).
  [[nodiscard]] Index firstBloodParticle() const { return m_firstBloodParticle; }
  [[nodiscard]] BloodStats bloodStats() const;
  // The creation index (0 .. count-1, in start-block order) of each blood particle: the
  // particles are reordered along a Morton curve every kReorderInterval steps.
  [[nodiscard]] const std::vector<Index>& bloodIds() const { return m_bloodIds; }
  static constexpr int kReorderInterval = 50;
  [[nodiscard]] double time() const { return double(m_steps) * double(m_solver.dt); }
  [[nodiscard]] std::int64_t stepCount() const { return m_steps; }
  // Phase during the last step (what the wall was doing), Systole before the first.
  [[nodiscard]] Phase lastPhase() const { return m_lastPhase; }

  // Heart and blood: the flow path (valves, loop, per-step flows and pressures); null otherwise.
  [[nodiscard]] const Circulation* circulation() const { return m_circulation.get(); }
  // Pressure (Pa) of each particle from the last density solve (0 for the wall), see
  // pbd::FluidSolver::pressures(); empty without blood.
  [[nodiscard]] const std::vector<Real>& pressures() const;
  // Where a blood particle started (its FlowRegion at t = 0: inflow vessel, ventricle, or
  // Parked for blood that began outside the model); Outside without a heart.
  [[nodiscard]] FlowRegion bloodOrigin(Index particle) const {
    const Index id = m_bloodIds[particle - m_firstBloodParticle];
    return id < m_bloodOrigin.size() ? m_bloodOrigin[id] : FlowRegion::Outside;
  }
  // A blood particle that is shown and measured (not parked outside the model).
  [[nodiscard]] bool bloodActive(Index particle) const {
    return particle >= m_firstBloodParticle && m_particles.inverseMass[particle] > Real(0);
  }

  // Heart only (hasHeart()).
  [[nodiscard]] Real cavityVolume() const;
  [[nodiscard]] TissueStats tissueStats() const;
  // Largest vertex distance from its rest position, divided by the LV long axis.
  [[nodiscard]] Real restDeviationRelative() const;

 private:
  Scenario m_scenario;
  int m_threads = 1;
  std::optional<LvModel> m_model;
  pbd::Particles m_particles;
  pbd::ConstraintSet m_constraints;
  pbd::SolverSettings m_solver;
  Index m_firstWallParticle = 0;
  Index m_firstBloodParticle = 0;
  std::optional<CardiacCycle> m_cycle;
  std::unique_ptr<pbd::FluidSolver> m_fluid;
  std::unique_ptr<pbd::ParticleTetCollider> m_wallContact;  // heart and blood
  std::unique_ptr<Circulation> m_circulation;               // heart and blood
  Vec3 m_domainMin = Vec3::Zero(), m_domainMax = Vec3::Zero();  // outside: blood is lost
  std::vector<Index> m_bloodIds;
  std::vector<FlowRegion> m_bloodOrigin;  // per blood id
  void reorderBlood();
  pbd::ParticleTetSettings wallContactSettings() const;
  std::vector<Real> m_restVolume;  // per model tet
  std::int64_t m_steps = 0;
  Phase m_lastPhase = Phase::Systole;
};

}  // namespace hs::cardiac
