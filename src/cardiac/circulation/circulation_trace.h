#pragma once
// What the lumped circulation (lumped_circulation.h) did in one step, as the plots, the CSV and
// the viewer read it. SI units: m^3, Pa, m^3/s, s.
#include <vector>

#include "pbd/core/state_stream.h"

namespace hs::cardiac {

struct CirculationSample {
  double time = 0;            // s, at the end of the step
  double lvVolume = 0;        // m^3
  double lvPressure = 0;      // Pa
  double laPressure = 0;      // Pa, left atrium
  double aorticPressure = 0;  // Pa, proximal aorta (after the characteristic impedance)
  double mitralFlow = 0;      // m^3/s, atrium -> ventricle (negative: regurgitation)
  double aorticFlow = 0;      // m^3/s, ventricle -> aorta (negative: regurgitation)
  bool mitralOpen = false;    // forward flow through the valve during the step
  bool aorticOpen = false;
  double ventricularActivation = 0;  // in [0, 1] during the step (times the beating share)
  double atrialActivation = 0;       // in [0, 1]
  double ecg = 0;  // mV, the synthetic ECG at the step's end (set by the run monitor: motion/ecg.h)
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);
};

// The ventricle's pressure-volume relations, for drawing them under the loop:
// end-systolic  P = Ees (V - V0)                       (Suga & Sagawa 1974)
// end-diastolic P = A (exp(B (V - V0)) - 1)
struct PressureVolumeRelations {
  double endSystolicElastance = 0;  // Ees, Pa/m^3 (effective: scaled by the beating share)
  double unstressedVolume = 0;      // V0, m^3
  double diastolicScale = 0;        // A, Pa
  double diastolicExponent = 0;     // B, 1/m^3
};

}  // namespace hs::cardiac
