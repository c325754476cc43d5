#include "cardiac/beat_clock.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hs::cardiac {

const char* phaseName(Phase phase) {
  switch (phase) {
    case Phase::Systole: return "systole";
    case Phase::Diastole: return "diastole";
    case Phase::Rest: return "rest";
  }
  return "?";
}

namespace {
// Share of the systolic displacement done by time s in [0, 1] of systole.
double smoothRamp(double s) {
  s = std::clamp(s, 0.0, 1.0);
  return s - std::sin(2.0 * std::numbers::pi * s) / (2.0 * std::numbers::pi);
}
}  // namespace

BeatClock::BeatClock(const BeatClockSettings& settings, Real dt)
    : m_settings(settings), m_dt(dt), m_random(settings.seed) {
  if (settings.physiological) {
    const double systole = double(settings.period) * double(settings.systolicFraction);
    m_systoleLength = std::max(1, int(std::lround(systole / double(dt))));
    m_diastoleLength =
        std::max(1, int(std::lround(double(settings.period) / double(dt))) - m_systoleLength);
  } else {
    m_systoleLength = std::max(1, settings.systoleSteps);
    m_diastoleLength = std::max(1, settings.diastoleSteps);
  }
  m_nominalDiastoleLength = m_diastoleLength;
}

Real BeatClock::advance() {
  if (m_phase == Phase::Rest) return 0;
  const Real displacement = m_phase != Phase::Systole ? Real(0)
                            : m_settings.physiological ? physiologicalDisplacement()
                                                       : m_settings.displacePerStep;
  // Algorithm 2, lines 8-11 (steps++, switch when steps >= BEATING_DURATION), and Fig. 4.6's
  // switch out of diastole.
  ++m_steps;
  if (m_phase == Phase::Systole && m_steps >= m_systoleLength) enterDiastole();
  else if (m_phase == Phase::Diastole && m_steps >= m_diastoleLength) endDiastole();
  return displacement;
}

void BeatClock::delayStart(int steps) {
  if (steps <= 0) return;
  m_phase = Phase::Diastole;
  m_steps = 0;
  m_diastoleLength = steps;
}

// The travel reached at the end of this systolic step, and the increment over the step.
Real BeatClock::physiologicalDisplacement() {
  const double n = m_systoleLength;
  const double contraction = m_settings.contraction;
  m_travel = Real(contraction * smoothRamp((m_steps + 1) / n));
  return Real(contraction * (smoothRamp((m_steps + 1) / n) - smoothRamp(m_steps / n)));
}

void BeatClock::enterDiastole() {
  m_steps = 0;
  ++m_systolesCompleted;
  m_phase = Phase::Diastole;
  // Irregular beating: the next contraction comes early, before the wall has relaxed.
  if (m_settings.irregularity > 0) {
    std::uniform_real_distribution<double> share(0.0, double(m_settings.irregularity));
    const double cut = share(m_random);
    m_diastoleLength = std::max(1, int(std::lround(m_nominalDiastoleLength * (1.0 - cut))));
  } else {
    m_diastoleLength = m_nominalDiastoleLength;
  }
}

void BeatClock::endDiastole() {
  m_steps = 0;
  const bool limitReached = m_settings.beats > 0 && m_systolesCompleted >= m_settings.beats;
  m_phase = limitReached ? Phase::Rest : Phase::Systole;
}

}  // namespace hs::cardiac
