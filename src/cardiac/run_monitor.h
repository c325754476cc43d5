#pragma once
// One watcher of a running HeartSimulation for every front end (`heartsim run`, `render`,
// `bench`, `validate` and the viewer), so that they agree on what a failed simulation is and
// read the same figures. After each step it checks the simulation's health (positions and
// velocities finite, no inverted wall tetrahedron, blood not lost, blood not inside the wall)
// and gathers the step's metrics (cavity volume, beats, valve flows, pressures, blood
// statistics) and the run's extremes. The checks are pure functions over the simulation's
// plain statistics, tested without running a heart.
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>

#include "cardiac/anatomy/lv_model.h"
#include "cardiac/blood.h"
#include "cardiac/blood/echo_velocities.h"
#include "cardiac/blood/filling_vortex.h"
#include "cardiac/blood/ventricle_blood.h"
#include "cardiac/circulation.h"
#include "cardiac/circulation/beat_metrics.h"
#include "cardiac/circulation/circulation_recorder.h"
#include "cardiac/circulation/heart_phase.h"
#include "cardiac/heart_simulation.h"
#include "mesh/surface_hinges.h"

namespace hs::cardiac {

enum class HealthCheck { Healthy, NonFinite, InvertedTets, BloodLost, BloodInsideWall };

// Blood may leave the domain or sit inside the wall for a while without the run being wrong
// (the thesis's one-way contact lets a few through): by default these are measured and
// reported, not failures. A limit makes more than that many particles a failure.
struct HealthLimits {
  static constexpr std::size_t kUnlimited = std::numeric_limits<std::size_t>::max();
  std::size_t bloodLost = kUnlimited;
  std::size_t bloodInsideWall = kUnlimited;
};

// What went wrong (what and where); empty `what` when healthy.
struct HealthIssue {
  HealthCheck check = HealthCheck::Healthy;
  std::string what;
};

// The verdict after a step: healthy, or the first failed check with when it was found.
struct Verdict {
  HealthIssue issue;
  std::int64_t step = 0;
  double time = 0;  // s
  [[nodiscard]] bool healthy() const { return issue.check == HealthCheck::Healthy; }
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);
  // One line: "simulation became invalid at step 12 (t = 0.06 s): <what>".
  [[nodiscard]] std::string message() const;
};

// "x = 0.1, y = 2, z = -0.3 m, AHA segment 4" (or the region's name) of a tet's first vertex.
std::string tetLocation(const LvModel& model, std::span<const Vec3> positions, Index tet);
// Non-finite state (`cavityFinite`: the cavity volume is a number), then inverted tets, located
// on `model` at `positions` (the wall's particles).
HealthIssue checkTissue(const TissueStats& tissue, bool cavityFinite, const LvModel* model,
                        std::span<const Vec3> positions);
HealthIssue checkBlood(const BloodStats& blood, const HealthLimits& limits);

struct StepSample;
// What a step's heart phase is read from: the lumped circulation's valves and the ventricle's
// activation; without it the 3D valves and the wall's own clock; nothing without valves.
PhaseSignals phaseSignals(const StepSample& sample);
// The step's phase as every front end names it (heart_phase.h), with the atrial kick and leaks
// from the lumped circulation's flows (or the 3D blood's, without it).
std::string heartPhaseLabel(const StepSample& sample);

// One step's figures. `cavity`, `flows` and `flowStep` with a heart (flows with blood too);
// `restDeviation` and `blood` only when the monitor gathers every column (MonitorSettings).
struct StepSample {
  std::int64_t step = 0;
  double startTime = 0, time = 0;  // s, at the step's start and end
  Phase phase = Phase::Rest;       // the wall's own clock during the step
  // The heart's phase from the valves (heart_phase.h; None without valves or figures gathered).
  HeartPhase heartPhase = HeartPhase::None;
  HeartSound heartSound = HeartSound::None;  // a sound that starts in this step
  double ecg = 0;  // mV, the synthetic ECG at the step's end (circulation.lumped; motion/ecg.h)
  double cavity = 0;               // m^3, at the end
  TissueStats tissue;
  Real restDeviation = 0;
  std::optional<BloodStats> blood;
  ValveFlows flows;   // m^3 through each orifice in the step
  FlowStep flowStep;  // valves, particles per region, mean pressures
  bool circulation = false;
  // circulation.lumped: the lumped circulation's step, the wall's contraction a and base
  // descent (m), the vessels' fill.
  std::optional<CirculationSample> lumped;
  double contraction = 0, baseDescent = 0, vesselFill = 1;
  // With a heart and pump figures: the largest turn from rest (radians) of a hinge of the wall's
  // surface that is smooth at rest (mesh/surface_hinges.h, run_monitor.cpp): a crease folds one.
  double surfaceTurn = 0;
  // Two-way coupling: the cavity's change (m^3) from the blood's push on the wall in the step.
  double bloodPush = 0;
  // Heart and blood with valves: the kinetic energy of the blood in the ventricle (J), from the
  // smoothed velocity (ventricle_blood.h), and the largest smoothed speed of any blood particle
  // but the vessels' far ends (m/s): what the viewer's and `render`'s speed colours show at their
  // hottest (they average over the drawn positions, this over the solve's lists: a particle the
  // contacts threw far in the step can read faster here, blood_field.h).
  double ventricleKineticEnergy = 0;
  double smoothedSpeedMax = 0;
  [[nodiscard]] double pressure(FlowRegion region) const { return flowStep.pressure[std::size_t(region)]; }
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);
};

// Extremes and means over the steps of a run. Blood's density error counts over the last
// simulated second only (from `lastSecondFrom`), once the fluid has settled. `heart`: the
// samples carry the wall's figures (a heart, and a monitor that gathers them).
struct RunExtremes {
  double volumeErrorMax = 0;
  double volumeErrorMeanSum = 0;  // sum over steps of the per-step mean
  double surfaceTurnMax = 0;      // radians
  double bloodPushMax = 0, bloodPushSum = 0;  // m^3, of |bloodPush|
  double cavityMin = std::numeric_limits<double>::infinity();
  double cavityMax = -std::numeric_limits<double>::infinity();
  std::size_t bloodLostMax = 0, bloodInsideWallMax = 0;
  double bloodSpeedMax = 0;
  double smoothedSpeedMax = 0;  // m/s, StepSample::smoothedSpeedMax
  double lastSecondFrom = 0;
  double densityErrorMeanSum = 0, densityErrorMax = 0;
  std::size_t lastSecondSteps = 0;
  void add(const StepSample& sample, bool heart);
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);
};

// What a finished run reports (summary.json's figures), read once at its end.
struct RunSummary {
  std::int64_t steps = 0;
  double time = 0;
  std::uint64_t stateHash = 0;
  bool heart = false, blood = false;
  // Heart.
  std::size_t vertices = 0, tets = 0, surfaceTriangles = 0;
  double volumeErrorMax = 0, volumeErrorMean = 0;
  double surfaceTurnMax = 0;     // radians: the wall surface's largest hinge turn from rest
  // Two-way coupling: the cavity moved by the blood's push in a step (m^3), largest and mean.
  bool twoWay = false;
  double bloodPushMax = 0, bloodPushMean = 0;
  std::size_t invertedTets = 0;  // at the end
  Real restDeviation = 0;        // at the end
  Real minDihedralDeg = 0, maxAspectRatio = 0;
  Real restCavity = 0;
  double cavityMin = 0, cavityMax = 0;
  BeatTracker beats{0};
  std::optional<CirculationRecorder> circulation;  // circulation.lumped
  // Heart and blood with valves: the flow components of each beat and the blood's kinetic
  // energy over each cycle (ventricle_blood.h).
  std::optional<VentricleBlood> ventricleBlood;
  // With the same: each cycle's Doppler peaks in the orifices (echo_velocities.h).
  std::optional<EchoVelocities> echo;
  // circulation.lumped with blood: the E-wave filling vortex of each beat (filling_vortex.h).
  std::optional<FillingVortex> fillingVortex;
  // [motion]: the recorded beat's frame volumes (m^3; empty without one), its period (s) and the
  // largest relative difference of the 3D cavity from the recorded volume over the run.
  std::vector<double> motionFrameVolumes;
  double motionPeriod = 0, motionVolumeErrorMax = 0;
  // Blood: at the end, and the most over the run (lost, inside the wall, speed) or over its
  // last second (density error).
  BloodStats bloodFinal;
  std::size_t bloodLost = 0, bloodInsideWall = 0;
  double densityErrorMean = 0, densityErrorMax = 0, bloodSpeedMax = 0;
  double smoothedSpeedMax = 0;  // m/s, over the run (RunExtremes)
};

struct MonitorSettings {
  bool pump = true;          // cavity, valve flows and pressures each step (with a heart)
  bool beatList = true;      // every beat of the run in beats() (the viewer keeps its own, bounded)
  bool everyColumn = false;  // also rest deviation and blood statistics each step (metrics.csv)
  double endTime = 0;        // s, the run's planned end (its last second averages the density)
  // circulation.lumped: the most recent lumped samples kept (the viewer bounds them).
  std::size_t lumpedSamples = std::numeric_limits<std::size_t>::max();
  HealthLimits limits;
  // Checks only: for front ends that read no figures (render, bench, validate).
  static MonitorSettings healthOnly() { return {false, false, false, 0, {}, {}}; }
};

class RunMonitor {
 public:
  // Reads the state before the next step (the first beat's end-diastolic volume).
  RunMonitor(const HeartSimulation& sim, MonitorSettings settings = {});

  // After each sim.step(): the checks, then (when healthy) the step's figures.
  const Verdict& observe();
  // The checks alone, on the state as it is (between steps or after a timed stretch).
  const Verdict& checkNow();
  // Closes the beat in progress at the end of the run.
  void finish() {
    m_beats.finish();
    if (m_circulation) m_circulation->finish();
  }

  [[nodiscard]] const Verdict& verdict() const { return m_verdict; }
  // The last observed step (step 0: the state the monitor started from).
  [[nodiscard]] const StepSample& last() const { return m_last; }
  [[nodiscard]] const BeatTracker& beats() const { return m_beats; }
  // Heart and blood with valves, figures gathered: the blood's own figures; null otherwise.
  [[nodiscard]] const VentricleBlood* ventricleBlood() const { return m_ventricleBlood ? &*m_ventricleBlood : nullptr; }
  // With the same: each cycle's Doppler peaks; null otherwise.
  [[nodiscard]] const EchoVelocities* echo() const { return m_echo ? &*m_echo : nullptr; }
  // circulation.lumped and blood, figures gathered: the E-wave filling vortex; null otherwise.
  [[nodiscard]] const FillingVortex* fillingVortex() const { return m_fillingVortex ? &*m_fillingVortex : nullptr; }
  // circulation.lumped with figures gathered (MonitorSettings::pump); null otherwise.
  [[nodiscard]] const CirculationRecorder* circulation() const { return m_circulation ? &*m_circulation : nullptr; }
  [[nodiscard]] const RunExtremes& extremes() const { return m_extremes; }
  [[nodiscard]] std::int64_t observedSteps() const { return m_observed; }
  [[nodiscard]] RunSummary summary() const;
  // Checkpoints: what the monitor has gathered, so that a resumed run reports the whole run.
  // The settings are the reader's: a run resumed toward another end time averages the density
  // over its own last second, from the samples after the checkpoint when that second begins
  // after it.
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);

 private:
  const HeartSimulation& m_sim;
  MonitorSettings m_settings;
  Verdict m_verdict;
  StepSample m_last;
  BeatTracker m_beats;
  std::optional<CirculationRecorder> m_circulation;
  std::optional<VentricleBlood> m_ventricleBlood;
  std::optional<EchoVelocities> m_echo;  // kept with m_ventricleBlood
  std::optional<FillingVortex> m_fillingVortex;
  RunExtremes m_extremes;
  std::int64_t m_observed = 0;
  std::vector<pbd::Hinge> m_hinges;     // of the wall's surface, with a heart
  std::vector<double> m_restHingeAngles;
  bool check(const TissueStats& tissue, double cavity);
  [[nodiscard]] bool bloodLimited() const;
  void gather(StepSample& sample) const;
  void recordCirculation(const StepSample& sample);
  void observeBlood(StepSample& sample);
  void watchFillingVortex(const StepSample& sample);
};

}  // namespace hs::cardiac
