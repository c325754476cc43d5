#include "cardiac/circulation/beat_clock.h"

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

BeatClock::BeatClock(const BeatClockSettings& settings) : m_settings(settings), m_random(settings.seed) {
  if (settings.startDelay > 0) {
    m_phase = Phase::Diastole;
    m_delayed = true;
  }
}

BeatClock::Lengths BeatClock::lengths(Real dt) const {
  if (!m_settings.physiological) return {std::max(1, m_settings.systoleSteps), std::max(1, m_settings.diastoleSteps)};
  const double systole = double(m_settings.period) * double(m_settings.systolicFraction);
  const int systoleSteps = std::max(1, int(std::lround(systole / double(dt))));
  return {systoleSteps, std::max(1, int(std::lround(double(m_settings.period) / double(dt))) - systoleSteps)};
}

int BeatClock::diastoleLength(Real dt) const {
  const Lengths regular = lengths(dt);
  if (m_delayed) {
    // The start delay, a share of one whole cycle.
    const double cycle = m_settings.physiological ? double(m_settings.period) / double(dt)
                                                  : double(regular.systole + regular.diastole);
    return int(std::lround(cycle * double(m_settings.startDelay)));
  }
  return std::max(1, int(std::lround(regular.diastole * m_diastoleShare)));
}

int BeatClock::stepsSinceSystoleStarted(Real dt) const {
  if (m_phase == Phase::Systole) return m_steps;
  if (m_phase == Phase::Diastole && !m_delayed && m_systolesCompleted > 0) return lengths(dt).systole + m_steps;
  return -1;
}

int BeatClock::stepsUntilSystole(Real dt) const {
  if (m_phase == Phase::Diastole) {
    const bool last = m_settings.beats > 0 && m_systolesCompleted >= m_settings.beats;
    return last ? -1 : diastoleLength(dt) - m_steps;
  }
  if (m_phase != Phase::Systole) return -1;
  const bool last = m_settings.beats > 0 && m_systolesCompleted + 1 >= m_settings.beats;
  const Lengths regular = lengths(dt);
  return last ? -1 : regular.systole - m_steps + regular.diastole;
}

Real BeatClock::advance(Real dt) {
  if (m_phase == Phase::Rest) return 0;
  if (m_delayed && m_steps == 0 && diastoleLength(dt) <= 0) {  // a delay shorter than half a step
    m_delayed = false;
    m_phase = Phase::Systole;
  }
  const int systoleLength = lengths(dt).systole;
  const Real displacement = m_phase != Phase::Systole ? Real(0)
                            : m_settings.physiological ? physiologicalDisplacement(systoleLength)
                                                       : m_settings.displacePerStep;
  // Algorithm 2, lines 8-11 (steps++, switch when steps >= BEATING_DURATION), and Fig. 4.6's
  // switch out of diastole.
  ++m_steps;
  if (m_phase == Phase::Systole && m_steps >= systoleLength) enterDiastole();
  else if (m_phase == Phase::Diastole && m_steps >= diastoleLength(dt)) endDiastole();
  return displacement;
}

// The travel reached at the end of this systolic step, and the increment over the step.
Real BeatClock::physiologicalDisplacement(int systoleLength) {
  const double n = systoleLength;
  const double contraction = m_settings.contraction;
  m_travel = Real(contraction * smoothRamp((m_steps + 1) / n));
  return Real(contraction * (smoothRamp((m_steps + 1) / n) - smoothRamp(m_steps / n)));
}

void BeatClock::enterDiastole() {
  m_steps = 0;
  ++m_systolesCompleted;
  m_phase = Phase::Diastole;
  // Irregular beating: the next contraction comes early, before the wall has relaxed.
  m_diastoleShare = 1;
  if (m_settings.irregularity > 0 && m_settings.irregularBothWays) {
    std::uniform_real_distribution<double> share(-double(m_settings.irregularity), double(m_settings.irregularity));
    m_diastoleShare = 1.0 + share(m_random);
  } else if (m_settings.irregularity > 0) {
    std::uniform_real_distribution<double> share(0.0, double(m_settings.irregularity));
    m_diastoleShare = 1.0 - share(m_random);
  }
}

void BeatClock::endDiastole() {
  m_steps = 0;
  m_delayed = false;
  const bool limitReached = m_settings.beats > 0 && m_systolesCompleted >= m_settings.beats;
  m_phase = limitReached ? Phase::Rest : Phase::Systole;
}

void BeatClock::save(pbd::StateWriter& w) const {
  w.section("beat clock");
  w.fields(m_phase, m_steps, m_systolesCompleted, m_delayed, m_diastoleShare, m_travel, m_random);
}

void BeatClock::load(pbd::StateReader& r) {
  r.section("beat clock");
  r.fields(m_phase, m_steps, m_systolesCompleted, m_delayed, m_diastoleShare, m_travel, m_random);
}

}  // namespace hs::cardiac
