#pragma once
// The clinical figures of one beat of the lumped circulation (circulation_trace.h samples from
// the ventricle's activation onset to the next): pressures, isovolumic times, mitral E/A,
// regurgitation, the aortic gradient. SI units; the JSON summary converts.
#include <optional>
#include <vector>

#include "cardiac/circulation/circulation_trace.h"
#include "pbd/core/state_stream.h"

namespace hs::cardiac {

struct LumpedBeatFigures {
  double aorticSystolic = 0, aorticDiastolic = 0;  // Pa: max and min aortic pressure
  double lvPeak = 0, lvEndDiastolic = 0;           // Pa: max, and at the onset (first sample)
  double edv = 0, esv = 0;                         // m^3: at the onset, smallest
  double isovolumicContraction = 0;  // s: mitral closed to aortic open (0 if none seen)
  double isovolumicRelaxation = 0;   // s: aortic closed to mitral open (0 if none seen)
  std::optional<double> eToA;        // peak early / peak atrial mitral flow; none without an A wave
  double forwardStrokeVolume = 0;    // m^3 out through the aortic valve (net)
  double regurgitantVolume = 0;      // m^3 back through the mitral valve plus back through the aortic
  double aorticMeanGradient = 0;     // Pa: mean LV - aortic pressure while the aortic valve is open
  std::size_t bothValvesOpenSamples = 0;
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);
  [[nodiscard]] double totalStrokeVolume() const { return edv - esv; }
  // Regurgitant volume over the ventricle's total stroke volume.
  [[nodiscard]] double regurgitantFraction() const {
    return totalStrokeVolume() > 0 ? regurgitantVolume / totalStrokeVolume() : 0;
  }
};

// `beat`: the samples of one beat in time order (each sample's flows are means over its step
// of length dt). `atrialOnset`: time (s) the atrium began to contract for the next beat, or
// none (no atrial contraction: atrial fibrillation); the A wave is the mitral flow after it.
LumpedBeatFigures analyseLumpedBeat(const std::vector<CirculationSample>& beat, double dt,
                                    std::optional<double> atrialOnset);

}  // namespace hs::cardiac
