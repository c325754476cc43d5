#pragma once
// Velocities as echocardiography reads them (issue 39): pulsed-wave Doppler puts a sample volume
// of a few millimetres in the orifice and reads the blood's mean velocity along the beam, which
// an apical view aligns with the flow through the valve. heartsim's sample volume is the slab of
// blood within one particle spacing of an orifice's disc and inside its rim; the reading is the
// spatial mean over that slab of the smoothed velocity's component along the orifice's forward
// normal (pbd/fluid/velocity_field.h; one particle's speed reads PBF's noise, ~0.5 m/s):
//   u_orifice = (1/N) sum_{i in slab} v~_i . n_forward.
// FlowMeter measures it each step (FlowStep::aorticEcho, mitralEcho); this tracker keeps, per
// cardiac cycle from one end-diastole to the next, the peaks an echocardiographer reports
// (Quinones et al. 2002, ASE recommendations for Doppler quantification; Nagueh et al. 2016 for
// E and A):
//   aortic peak: the largest aortic reading while the ventricle ejects;
//   mitral E: the largest mitral reading while it fills before the atrium contracts;
//   mitral A: the largest mitral reading while it fills during the atrial kick; none in a cycle
//             without one (atrial fibrillation, or scenarios without an atrium's timing).
#include <optional>
#include <vector>

#include "cardiac/circulation/heart_phase.h"
#include "pbd/core/state_stream.h"

namespace hs::cardiac {

// One cycle's peaks (m/s), from the end-diastole at `start` to the next at `end` (s).
struct CycleEcho {
  double start = 0, end = 0;
  double aorticPeak = 0, mitralE = 0;
  std::optional<double> mitralA;
  void save(pbd::StateWriter& w) const { w.fields(start, end, aorticPeak, mitralE, mitralA); }
  void load(pbd::StateReader& r) { r.fields(start, end, aorticPeak, mitralE, mitralA); }
};

// End-diastole: filling gives way to isovolumic contraction, or straight to ejection.
bool endDiastoleBetween(HeartPhase before, HeartPhase after);

class EchoVelocities {
 public:
  // After a step ending at `time`: the step's orifice readings (m/s, along each orifice's forward
  // normal), the phase from `before` to `after`, `atrialKick` while the atrium contracts.
  void observe(double aortic, double mitral, HeartPhase before, HeartPhase after, bool atrialKick, double time);
  // The complete cycles (end-diastole to end-diastole), in order.
  [[nodiscard]] const std::vector<CycleEcho>& cycles() const { return m_cycles; }
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);

 private:
  CycleEcho m_current;
  bool m_started = false;   // an end-diastole has been seen
  bool m_kickSeen = false;  // the atrial kick has begun in this cycle's filling
  std::vector<CycleEcho> m_cycles;
};

}  // namespace hs::cardiac
