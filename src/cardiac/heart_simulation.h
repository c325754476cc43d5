#pragma once
// One simulated world: the beating heart wall (the LV model as a PBD soft body driven by the
// cardiac cycle) and/or blood (PBF particles), in one particle set: the wall's vertices first
// (particle = model vertex), then the blood. step() lists the stages of a step in order
// (thesis Fig. 4.1 / Algorithm 1, PBF Algorithm 1); docs/architecture.md names the file and
// function of each. With both, blood is kept out of the wall inside every density iteration
// and once more after the wall's constraints (thesis 4.4); with circulation.two_way the push
// is shared with the wall (the wall feels the blood).
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "cardiac/anatomy/lv_model.h"
#include "cardiac/blood.h"
#include "cardiac/blood/vessel_ends.h"
#include "cardiac/circulation.h"
#include "cardiac/circulation/lumped_circulation.h"
#include "cardiac/heart_sites.h"
#include "cardiac/motion/cardiac_cycle.h"
#include "cardiac/motion/recorded_beat.h"
#include "cardiac/motion/volume_driven_wall.h"
#include "cardiac/motion/wall_motion.h"
#include "cardiac/scenario.h"
#include "cardiac/step_profile.h"
#include "pbd/contact/particle_tet_collision.h"
#include "pbd/contact/swept_contact.h"
#include "pbd/core/solver.h"
#include "pbd/core/step_context.h"
#include "pbd/core/thread_governor.h"
#include "pbd/fluid/fluid_solver.h"

namespace hs::cardiac {

struct TissueStats {
  Real volumeErrorMax = 0;   // max over tets of |V - V0| / V0
  Real volumeErrorMean = 0;  // mean over tets of |V - V0| / V0
  std::size_t invertedTets = 0;  // tets with V <= 0
  Index firstInvertedTet = 0;    // model tet id, when invertedTets > 0
  bool finite = true;        // every position and velocity finite
  Index firstNonFinite = 0;  // particle id, when !finite
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);
};

class HeartSimulation {
 public:
  // Throws std::invalid_argument for parameters the model or cycle reject.
  HeartSimulation(const Scenario& scenario, int threads);
  // Its pieces refer to each other (the wall's motion to the cycle it drives): not copied or moved.
  HeartSimulation(const HeartSimulation&) = delete;
  HeartSimulation& operator=(const HeartSimulation&) = delete;

  void step();
  // How many of the `threads` each step uses is chosen from the measured time of recent steps
  // (thread_governor.h; the state is the same on any count). Replaces the governor's settings.
  void governThreads(const pbd::ThreadGovernorSettings& settings) { m_governor = pbd::ThreadGovernor(m_threads, settings); }
  [[nodiscard]] const pbd::ThreadGovernor& threadGovernor() const { return m_governor; }
  // Wall time per stage of each following step is added to `profile` (null: none, the default).
  void attachProfile(StepProfile* profile) { m_profile = profile; }

  [[nodiscard]] const Scenario& scenario() const { return m_scenario; }
  [[nodiscard]] bool hasHeart() const { return m_model.has_value(); }
  [[nodiscard]] bool hasBlood() const { return m_fluid != nullptr; }
  // Heart only (hasHeart()).
  [[nodiscard]] const LvModel& model() const { return *m_model; }
  [[nodiscard]] const CardiacCycle& cycle() const { return *m_cycle; }
  [[nodiscard]] const pbd::Particles& particles() const { return m_particles; }
  [[nodiscard]] const pbd::ConstraintSet& constraints() const { return m_constraints; }
  // Blood particles are [firstBloodParticle(), particles().size()), reordered along a Morton
  // curve every kReorderInterval steps; particles().id follows each one.
  [[nodiscard]] Index firstBloodParticle() const { return m_firstBloodParticle; }
  static constexpr int kReorderInterval = 50;
  [[nodiscard]] BloodStats bloodStats() const;
  [[nodiscard]] double time() const { return double(m_steps) * double(m_scenario.simulation.dt); }
  [[nodiscard]] std::int64_t stepCount() const { return m_steps; }
  // Phase during the last step (what the wall was doing), Systole before the first.
  [[nodiscard]] Phase lastPhase() const { return m_lastPhase; }
  // The synthetic ECG (mV, motion/ecg.h) at the end of the last step, from the main region's
  // beat clock; NaN without the lumped circulation (its beat timing places the waves).
  [[nodiscard]] double ecgMillivolts() const;

  // Heart and blood: the flow path's pieces (valves, flow meter, loop); null otherwise.
  [[nodiscard]] const Circulation* circulation() const { return m_circulation ? &*m_circulation : nullptr; }
  // circulation.lumped: the lumped circulation driving the wall, and the wall it drives; null
  // otherwise.
  [[nodiscard]] const LumpedCirculation* lumped() const { return m_lumped ? &*m_lumped : nullptr; }
  [[nodiscard]] const VolumeDrivenWall* drivenWall() const { return m_drivenWall ? &*m_drivenWall : nullptr; }
  // [motion]: the recorded beat driving the endocardium; null otherwise.
  [[nodiscard]] const RecordedBeat* recordedBeat() const { return m_recordedBeat ? &*m_recordedBeat : nullptr; }
  // Some myocardium vertex has mass (is neither pinned nor driven): two-way coupling, which pushes
  // the myocardium only, can move it.
  [[nodiscard]] bool wallCanYield() const;
  // Two-way coupling: the cavity's change (m^3) the blood's push on the wall made in the last
  // step's contacts; 0 otherwise.
  [[nodiscard]] double lastBloodPush() const { return m_lastBloodPush; }
  // Heart and blood: the smaller share of the two vessels' lumens holding blood after the last
  // step: of each vessel's rest-density sites between the ends' buffers, the share whose blood
  // colour is at least half of its value with the heart full (vesselFillShare, heart_sites.h).
  [[nodiscard]] double vesselFill() const;
  // Pressure (Pa) of each particle from the last density solve (0 for the wall), see
  // pbd::FluidSolver::pressures(); empty without blood.
  [[nodiscard]] const std::vector<Real>& pressures() const;
  // Heart and blood: the smoothed velocity (m/s) of each particle at the end of the last step
  // (pbd/fluid/velocity_field.h), by particle index, 0 for the wall; what the flow meter's Doppler
  // readings and the ventricle's kinetic energy are measured from. Empty before the first step
  // (and after a checkpoint's load) and without a circulation.
  [[nodiscard]] const std::vector<Vec3>& smoothedVelocities() const { return m_smoothedVelocity; }
  // Where a blood particle started (its FlowRegion at t = 0: inflow vessel, ventricle, or
  // Parked for blood that began outside the model); Outside without a heart.
  [[nodiscard]] FlowRegion bloodOrigin(Index particle) const {
    return m_bloodOrigin.empty() ? FlowRegion::Outside : m_bloodOrigin[m_particles.id[particle] - m_firstBloodParticle];
  }
  // A blood particle that is shown and measured (not parked outside the model).
  [[nodiscard]] bool bloodActive(Index particle) const {
    return particle >= m_firstBloodParticle && m_particles.active(particle);
  }

  // circulation.lumped: a blood particle in a vessel's far-end buffer (vessel_ends.h), the
  // lumped model's boundary: it moves along its vessel as the lumped flows say (the outflow's
  // plug also repays the volume it fell behind), not as the blood's own flow; false otherwise.
  [[nodiscard]] bool bloodInVesselEnd(Index particle) const {
    return m_ends && particle >= m_firstBloodParticle && m_ends->inBuffer(m_particles.position[particle]);
  }

  // Heart only (hasHeart()).
  [[nodiscard]] Real cavityVolume() const;
  [[nodiscard]] TissueStats tissueStats() const;
  // Largest vertex distance from its rest position, divided by the LV long axis.
  [[nodiscard]] Real restDeviationRelative() const;

  // Checkpoints (io/output/checkpoint.h): everything a step changes, piece by piece; the rest (the
  // model, the constraints, settings, scratch) is rebuilt from the scenario by the
  // constructor. load() expects a simulation built from the same scenario and throws
  // pbd::StateError for state of another.
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);

 private:
  // Construction.
  void buildHeart();
  void chooseWallMotion();
  void attachVessels();
  void buildLumpedCirculation();
  void buildRecordedBeat(const PatientWall& wall);
  void buildBlood();
  void findDomain();
  void recordBloodOrigins();
  // The stages of step(), in order.
  void beginStep(const pbd::StepContext& context);
  void advanceLumpedCirculation(const pbd::StepContext& context);
  void applyExternalForces(const pbd::StepContext& context);
  void moveWall(const pbd::StepContext& context);
  void projectWall(const pbd::StepContext& context, StageLaps& laps);  // before the blood one-way, after two-way
  void solveBloodDensity(const pbd::StepContext& context, StageLaps& laps);
  void lendWallDensity(const pbd::StepContext& context);
  void resolveBloodContacts(const pbd::StepContext& context);
  void endStep(const pbd::StepContext& context);

  void reorderBlood();

  Scenario m_scenario;
  int m_threads = 1;  // the most a step may use
  pbd::ThreadGovernor m_governor{1};
  StepProfile* m_profile = nullptr;  // not owned; see attachProfile
  std::optional<LvModel> m_model;
  pbd::Particles m_particles;
  pbd::ConstraintSet m_constraints;
  pbd::SolverSettings m_solver;
  Index m_firstWallParticle = 0;
  Index m_firstBloodParticle = 0;
  std::optional<CardiacCycle> m_cycle;
  std::unique_ptr<pbd::FluidSolver> m_fluid;
  std::unique_ptr<pbd::ParticleTetCollider> m_wallContact;  // heart and blood
  std::unique_ptr<pbd::SweptContact> m_sweptContact;        // heart and blood, blood.wall_contact = continuous
  pbd::ParticleTetSettings m_contactSettings;               // heart and blood, from the scenario at set-up
  pbd::SweptContactSettings m_sweptSettings;                // with m_sweptContact
  std::unique_ptr<WallMotion> m_wallMotion;                 // heart: what moves the wall (wall_motion.h)
  std::optional<Circulation> m_circulation;                 // heart and blood
  std::optional<LumpedCirculation> m_lumped;                // circulation.lumped
  std::optional<VolumeDrivenWall> m_drivenWall;             // circulation.lumped
  double m_lastBloodPush = 0;                                // m^3, two-way coupling
  std::vector<Vec3> m_smoothedVelocity;                     // heart and blood: see smoothedVelocities()
  std::optional<VesselEnds> m_ends;                         // circulation.lumped
  std::optional<RecordedBeat> m_recordedBeat;               // [motion]
  std::vector<double> m_regionShares;                       // circulation.lumped: per beating region
  BeatTiming m_beatTiming;                                  // circulation.lumped
  VesselSites m_vesselSites;                                // heart and blood
  std::vector<pbd::Triangle> m_lumenSurface;                // blood.wall_density
  double m_lastBaseDescent = 0;                             // m, circulation.lumped
  Vec3 m_domainMin = Vec3::Zero(), m_domainMax = Vec3::Zero();  // outside: blood is lost
  std::vector<FlowRegion> m_bloodOrigin;  // per blood particle id - firstBloodParticle
  std::vector<Real> m_restVolume;  // per model tet
  std::int64_t m_steps = 0;
  Phase m_lastPhase = Phase::Systole;
};

}  // namespace hs::cardiac
