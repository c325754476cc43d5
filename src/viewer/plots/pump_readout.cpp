#include "viewer/plots/pump_readout.h"

#include <cmath>

namespace hs::viewer {

ClinicalFigures clinicalFigures(const cardiac::BeatSummary& beat, const VolumeScale& scale) {
  ClinicalFigures f;
  f.edv = beat.edv * scale.volume;
  f.esv = beat.esv * scale.volume;
  f.strokeVolume = beat.strokeVolume() * scale.volume;
  f.ejectionFraction = beat.ejectionFraction() * 100;
  f.regurgitantVolume = beat.regurgitantVolume() * scale.volume;
  f.forwardStrokeVolume = f.strokeVolume - f.regurgitantVolume;
  f.complete = beat.complete;
  // An unfinished beat's length is not known yet, and neither are its rate and output.
  if (beat.complete && beat.duration > 0) {
    f.heartRate = 60 / beat.duration;
    f.cardiacOutput = beat.cardiacOutput() * scale.output;
  }
  return f;
}

void setFlowRates(PumpSample& sample, const cardiac::ValveFlows& flows, double dt) {
  if (dt <= 0) return;
  sample.mitralRate = (flows.mitralForward - flows.mitralBackward) / dt;
  sample.aorticRate = (flows.aorticForward - flows.aorticBackward) / dt;
}

PumpSample pumpSample(const cardiac::StepSample& step) {
  PumpSample sample;
  sample.time = step.time;
  sample.phase = step.phase;
  sample.cavity = step.cavity;
  if (step.circulation) setFlowRates(sample, step.flows, step.time - step.startTime);
  if (step.lumped) {
    sample.pressureLv = step.lumped->lvPressure;
    sample.pressureInflow = step.lumped->laPressure;
    sample.pressureOutflow = step.lumped->aorticPressure;
  } else if (step.circulation) {
    sample.pressureLv = step.pressure(cardiac::FlowRegion::Ventricle);
    sample.pressureInflow = step.pressure(cardiac::FlowRegion::InflowVessel);
    sample.pressureOutflow = step.pressure(cardiac::FlowRegion::OutflowVessel);
  }
  return sample;
}

SettlingRule settlingRuleFor(const cardiac::Scenario& scenario) {
  SettlingRule rule;
  rule.irregular = scenario.cycle.pattern != cardiac::BeatPattern::Normal;
  const cardiac::LumpedParameters& p = scenario.circulation.lumpedParameters;
  rule.settledAfter = scenario.circulation.lumped ? 3 * p.peripheralResistance * p.arterialCompliance
                                                  : 3 * 60.0 / double(scenario.cycle.heartRateBpm);
  return rule;
}

bool beatSettles(const SettlingRule& rule, const cardiac::BeatSummary& beat,
                 const std::optional<cardiac::BeatSummary>& previous) {
  if (rule.irregular) return beat.startTime >= rule.settledAfter;
  if (!previous || !(previous->edv > 0) || !(previous->esv > 0)) return false;
  return std::abs(beat.edv / previous->edv - 1) <= rule.tolerance &&
         std::abs(beat.esv / previous->esv - 1) <= rule.tolerance;
}

PumpReadout::PumpReadout(double initialVolume, double dt, SettlingRule settling)
    : m_tracker(initialVolume, dt), m_settling(settling), m_dt(dt), m_lastVolume(initialVolume) {}

void PumpReadout::record(double startTime, cardiac::Phase phase, double volume,
                         const cardiac::ValveFlows& flows) {
  const bool systoleStarts = phase == cardiac::Phase::Systole && m_previous != cardiac::Phase::Systole;
  m_previous = phase;
  if (systoleStarts) {
    // This step closes the beat in progress (complete, as `heartsim run` counts it); a fresh
    // tracker, starting from the volume before the step, takes the new beat.
    m_tracker.record(startTime, phase, volume, flows);
    if (!m_tracker.beats().empty()) {
      const std::optional<cardiac::BeatSummary> previous = m_last;
      m_last = m_tracker.beats().back();
      m_last->index = ++m_completed;
      m_settled = m_settled || beatSettles(m_settling, *m_last, previous);
      if (m_settled) m_recent.push_back(*m_last);
      if (m_recent.size() > kRecentBeats) m_recent.erase(m_recent.begin());
      m_played.push_back(*m_last);
      if (m_played.size() > kRecentBeats) m_played.erase(m_played.begin());
    }
    m_tracker = cardiac::BeatTracker(m_lastVolume, m_dt);
    m_currentEdv = m_lastVolume;
    m_currentStart = startTime;
    m_beating = true;
  }
  m_tracker.record(startTime, phase, volume, flows);
  m_lastVolume = volume;
}

BeatReadings PumpReadout::readings() const {
  BeatReadings r;
  r.last = m_last;
  r.recent = m_recent;
  r.settled = m_settled;
  r.played = m_played;
  r.beatsCompleted = m_completed;
  r.beating = m_beating;
  r.currentEdv = m_currentEdv;
  r.currentStart = m_currentStart;
  // A copy closed now: the beat in progress as it stands (only once its systole has ended).
  cardiac::BeatTracker copy = m_tracker;
  copy.finish();
  if (!copy.beats().empty() && !copy.beats().back().complete) {
    r.current = copy.beats().back();
    r.current->index = m_completed + 1;
  }
  return r;
}

}  // namespace hs::viewer
