#include "cardiac/circulation/circulation_recorder.h"

#include <algorithm>
#include <cmath>

namespace hs::cardiac {

double CoupledBeat::aorticFlowError() const {
  const double lumpedNet = lumped.forwardStrokeVolume;
  return lumpedNet > 0 ? std::abs(aorticNet3d - lumpedNet) / lumpedNet : 0;
}

void CirculationRecorder::record(const CoupledStep& step) {
  // A beat begins with each onset of the ventricle's activation.
  if (step.phase == Phase::Systole && m_previous != Phase::Systole) {
    if (m_open) close(true);
    m_open = true;
    m_current = {};
    m_current.index = int(m_beats.size()) + 1;
    m_current.startTime = step.startTime;
    m_beatStarts.push_back(step.startTime);
    m_beat.clear();
    m_atrialOnset.reset();
  }
  m_previous = step.phase;
  const CirculationSample& s = step.lumped;
  if (m_samples.size() >= m_keep) m_samples.erase(m_samples.begin(), m_samples.begin() + std::ptrdiff_t(m_keep / 2 + 1));
  m_samples.push_back(s);
  // The atrium's onset: its activation rising from zero (the A wave that ends this beat).
  if (s.atrialActivation > 0 && m_lastAtrial == 0) m_atrialOnset = step.startTime;
  m_lastAtrial = s.atrialActivation;
  m_bothOpen += s.mitralOpen && s.aorticOpen;
  if (s.lvVolume > 0) m_cavityErrorMax = std::max(m_cavityErrorMax, std::abs(step.cavity - s.lvVolume) / s.lvVolume);
  if (m_lastCavity) m_cavityStepMax = std::max(m_cavityStepMax, std::abs(step.cavity - *m_lastCavity));
  m_lastCavity = step.cavity;
  m_fillMin = std::min(m_fillMin, step.vesselFill);
  if (!m_open) return;
  m_beat.push_back(s);
  m_current.aorticNet3d += step.aorticForward - step.aorticBackward;
  m_current.aorticJet = std::max(m_current.aorticJet, step.aorticJet);
  m_current.duration = step.time - m_current.startTime;
}

void CirculationRecorder::finish() {
  if (m_open) close(false);
  m_open = false;
}

void CirculationRecorder::close(bool complete) {
  m_current.complete = complete;
  if (m_beat.size() >= 2) m_current.lumped = analyseLumpedBeat(m_beat, m_dt, m_atrialOnset);
  m_beats.push_back(m_current);
}

CoupledMeans CirculationRecorder::means() const {
  CoupledMeans m;
  bool everyBeatHasAnAWave = true;
  double eToA = 0;
  for (std::size_t k = 1; k < m_beats.size(); ++k) {
    const CoupledBeat& b = m_beats[k];
    if (!b.complete) continue;
    const LumpedBeatFigures& f = b.lumped;
    ++m.count;
    m.aorticSystolic += f.aorticSystolic;
    m.aorticDiastolic += f.aorticDiastolic;
    m.lvPeak += f.lvPeak;
    m.lvEndDiastolic += f.lvEndDiastolic;
    m.isovolumicContraction += f.isovolumicContraction;
    m.isovolumicRelaxation += f.isovolumicRelaxation;
    m.regurgitantFraction += f.regurgitantFraction();
    m.aorticMeanGradient += f.aorticMeanGradient;
    m.aorticJet += b.aorticJet;
    m.strokeVolume += f.forwardStrokeVolume;
    everyBeatHasAnAWave = everyBeatHasAnAWave && f.eToA.has_value();
    eToA += f.eToA.value_or(0);
  }
  if (m.count == 0) return m;
  const double n = m.count;
  for (double* v : {&m.aorticSystolic, &m.aorticDiastolic, &m.lvPeak, &m.lvEndDiastolic, &m.isovolumicContraction,
                    &m.isovolumicRelaxation, &m.regurgitantFraction, &m.aorticMeanGradient, &m.aorticJet,
                    &m.strokeVolume})
    *v /= n;
  if (everyBeatHasAnAWave) m.eToA = eToA / n;
  return m;
}

std::optional<double> CirculationRecorder::aorticFlowErrorMax() const {
  std::optional<double> worst;
  for (std::size_t k = 1; k < m_beats.size(); ++k)
    if (m_beats[k].complete) worst = std::max(worst.value_or(0), m_beats[k].aorticFlowError());
  return worst;
}

void CoupledBeat::save(pbd::StateWriter& w) const {
  w.fields(index, startTime, duration, complete, lumped, aorticNet3d, aorticJet);
}

void CoupledBeat::load(pbd::StateReader& r) {
  r.fields(index, startTime, duration, complete, lumped, aorticNet3d, aorticJet);
}

void CirculationRecorder::save(pbd::StateWriter& w) const {
  w.section("circulation recorder");
  w.fields(m_samples, m_beatStarts, m_beats, m_beat, m_current, m_atrialOnset, m_lastAtrial, m_open, m_previous, m_lastCavity, m_bothOpen, m_cavityErrorMax, m_cavityStepMax, m_fillMin);
}

void CirculationRecorder::load(pbd::StateReader& r) {
  r.section("circulation recorder");
  r.fields(m_samples, m_beatStarts, m_beats, m_beat, m_current, m_atrialOnset, m_lastAtrial, m_open, m_previous, m_lastCavity, m_bothOpen, m_cavityErrorMax, m_cavityStepMax, m_fillMin);
}

}  // namespace hs::cardiac
