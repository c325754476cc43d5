#include "cardiac/circulation/lumped_beat.h"

#include <algorithm>
#include <stdexcept>

namespace hs::cardiac {
namespace {

// The length of a run of samples with both valves closed that begins when the `from` valve
// closes (or at the beat's start, for the mitral valve: the atrium's relaxation may close it
// just before the ventricle's onset) and ends when the other valve opens. 0 without one.
double isovolumicTime(const std::vector<CirculationSample>& beat, double dt, bool mitralFirst) {
  auto open = [&](const CirculationSample& s, bool mitral) { return mitral ? s.mitralOpen : s.aorticOpen; };
  for (std::size_t i = 0; i < beat.size(); ++i) {
    const bool closesHere = i > 0 ? open(beat[i - 1], mitralFirst) && !open(beat[i], mitralFirst)
                                  : mitralFirst && !beat[0].mitralOpen && !beat[0].aorticOpen;
    if (!closesHere) continue;
    std::size_t j = i;
    while (j < beat.size() && !beat[j].mitralOpen && !beat[j].aorticOpen) ++j;
    if (j < beat.size() && open(beat[j], !mitralFirst)) return double(j - i) * dt;
  }
  return 0;
}

}  // namespace

LumpedBeatFigures analyseLumpedBeat(const std::vector<CirculationSample>& beat, double dt,
                                    std::optional<double> atrialOnset) {
  if (beat.size() < 2) throw std::invalid_argument("analyseLumpedBeat: a beat needs at least two samples");
  LumpedBeatFigures f;
  f.lvEndDiastolic = beat.front().lvPressure;
  f.edv = beat.front().lvVolume;
  f.esv = beat.front().lvVolume;
  f.aorticSystolic = f.aorticDiastolic = beat.front().aorticPressure;
  double gradientSum = 0;
  std::size_t ejecting = 0;
  double earlyPeak = 0, atrialPeak = 0;
  for (const CirculationSample& s : beat) {
    f.aorticSystolic = std::max(f.aorticSystolic, s.aorticPressure);
    f.aorticDiastolic = std::min(f.aorticDiastolic, s.aorticPressure);
    f.lvPeak = std::max(f.lvPeak, s.lvPressure);
    f.esv = std::min(f.esv, s.lvVolume);
    f.forwardStrokeVolume += s.aorticFlow * dt;
    f.regurgitantVolume += std::max(0.0, -s.mitralFlow) * dt + std::max(0.0, -s.aorticFlow) * dt;
    if (s.aorticOpen) {
      gradientSum += s.lvPressure - s.aorticPressure;
      ++ejecting;
    }
    if (s.mitralOpen && s.aorticOpen) ++f.bothValvesOpenSamples;
    const bool atrialWave = atrialOnset && s.time > *atrialOnset;
    (atrialWave ? atrialPeak : earlyPeak) = std::max(atrialWave ? atrialPeak : earlyPeak, s.mitralFlow);
  }
  f.aorticMeanGradient = ejecting > 0 ? gradientSum / double(ejecting) : 0;
  f.isovolumicContraction = isovolumicTime(beat, dt, true);
  f.isovolumicRelaxation = isovolumicTime(beat, dt, false);
  if (atrialOnset && atrialPeak > 0) f.eToA = earlyPeak / atrialPeak;
  return f;
}

void LumpedBeatFigures::save(pbd::StateWriter& w) const {
  w.fields(aorticSystolic, aorticDiastolic, lvPeak, lvEndDiastolic, edv, esv, isovolumicContraction, isovolumicRelaxation, eToA, forwardStrokeVolume, regurgitantVolume, aorticMeanGradient, bothValvesOpenSamples);
}

void LumpedBeatFigures::load(pbd::StateReader& r) {
  r.fields(aorticSystolic, aorticDiastolic, lvPeak, lvEndDiastolic, edv, esv, isovolumicContraction, isovolumicRelaxation, eToA, forwardStrokeVolume, regurgitantVolume, aorticMeanGradient, bothValvesOpenSamples);
}

}  // namespace hs::cardiac
