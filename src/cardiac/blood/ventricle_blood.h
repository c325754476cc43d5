#pragma once
// What the 3D blood in the ventricle itself tells, step by step and beat by beat, as 4D-flow MRI
// reads a patient's: its kinetic energy and the flow components of each beat (flow_components.h).
// The kinetic energy is that of the smoothed velocity field (pbd/fluid/velocity_field.h), as
// 4D-flow MRI measures it from a velocity field on voxels (Garg et al. 2018, J Cardiovasc Magn
// Reson 20:61: KE = sum over voxels of rho V |v|^2 / 2):
//   E_k = sum over the blood particles in the ventricle of m |v~_i|^2 / 2.
// PBF's particle velocities carry noise of ~0.5 m/s that is no flow: the sum of m |v_i|^2 / 2 over
// particles counts its energy too, about twenty times the flow's in a healthy ventricle. The beat's two events
// come from the heart's phase (heart_phase.h): end-diastole when filling gives way to isovolumic
// contraction (or straight to ejection), end-systole when ejection ends. Fed by the run's monitor
// after each step with the flow meter's regions.
#include <optional>
#include <span>
#include <vector>

#include "cardiac/anatomy/flow_path.h"
#include "cardiac/blood/flow_components.h"
#include "cardiac/circulation/heart_phase.h"
#include "pbd/core/particles.h"

namespace hs::cardiac {

// One beat's components, with the time of the end-diastole they are shares of (s).
struct BeatFlowComponents {
  double endDiastole = 0;
  FlowComponents shares;
  void save(pbd::StateWriter& w) const {
    const FlowComponents& c = shares;
    w.fields(endDiastole, c.direct, c.retainedInflow, c.delayedEjection, c.residual, c.particles,
             c.meanResidenceBeats, c.stayedOverThreeBeats);
  }
  void load(pbd::StateReader& r) {
    FlowComponents& c = shares;
    r.fields(endDiastole, c.direct, c.retainedInflow, c.delayedEjection, c.residual, c.particles,
             c.meanResidenceBeats, c.stayedOverThreeBeats);
  }
};

// The mean of the beats' components (every field, the particle count left 0) over the beats
// after the first `skipped` (the first beats, while the blood settles into its path); none
// when no beat is left.
std::optional<FlowComponents> meanFlowComponents(std::span<const BeatFlowComponents> beats, std::size_t skipped);

// The kinetic energy of the blood in the ventricle over one cardiac cycle, from an end-diastole
// to the next (J): its time mean (the mean over the cycle's steps of E_k, the cycle mean Garg et
// al. 2018 divide by the EDV) and its largest value while filling (the E and A jets).
struct CycleKineticEnergy {
  double start = 0, end = 0;  // s
  double mean = 0, fillingPeak = 0;
  void save(pbd::StateWriter& w) const { w.fields(start, end, mean, fillingPeak); }
  void load(pbd::StateReader& r) { r.fields(start, end, mean, fillingPeak); }
};

class VentricleBlood {
 public:
  // `first`: the first blood particle; the blood is [first, particles.size()).
  VentricleBlood(const pbd::Particles& particles, pbd::Index first);

  // After a step ending at `time`: `regions[b]` is the region of the blood particle stored at
  // first + b (FlowMeter::regions()); `velocities[i]` the smoothed velocity of particle i
  // (HeartSimulation::smoothedVelocities()); the phase went from `before` to `after`. Returns the
  // kinetic energy of the blood in the ventricle (J).
  double observe(const pbd::Particles& particles, std::span<const FlowRegion> regions,
                 std::span<const pbd::Vec3> velocities, HeartPhase before, HeartPhase after, double time);

  [[nodiscard]] const std::vector<BeatFlowComponents>& beats() const { return m_beats; }
  [[nodiscard]] const std::vector<CycleKineticEnergy>& cycles() const { return m_cycles; }
  // Per blood particle, by identity (id - first): its component in the beat shown, and whether
  // it has stayed more than three beats (FlowComponentTracker's rules), for pictures.
  [[nodiscard]] std::vector<FlowComponent> components() const { return m_tracker.components(); }
  [[nodiscard]] std::vector<Stay> stays() const { return m_tracker.stays(); }
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);

 private:
  pbd::Index m_first;
  FlowComponentTracker m_tracker;
  std::vector<std::uint8_t> m_inVentricle;  // scratch, by particle identity
  double m_endDiastole = -1;  // s; negative before the first
  std::vector<BeatFlowComponents> m_beats;
  double m_energySum = 0, m_fillingPeak = 0;  // since the last end-diastole
  std::int64_t m_energySteps = 0;
  std::vector<CycleKineticEnergy> m_cycles;
};

}  // namespace hs::cardiac
