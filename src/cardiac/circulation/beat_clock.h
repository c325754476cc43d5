#pragma once
// Timing of one beating region: when it contracts and by how much per step.
//
// Thesis mode (Algorithms 2-3, Fig. 4.6, Table 5.4): a Systole/Diastole state machine counting
// steps. In systole the region moves BEATING_DISPLACE toward the centre every step; after
// BEATING_DURATION steps the state switches. Algorithm 2 as printed counts steps only in
// systole (so diastole would never end); Fig. 4.6 switches both ways after BEATING_DURATION,
// which we follow (docs/cardiac-cycle.md).
// Physiological mode: heart rate (bpm) and systolic fraction; the inward travel since systole
// began follows contraction * F(s), F(s) = s - sin(2 pi s)/(2 pi), s = time in systole /
// systole length, whose rate sin^2(pi s) starts and ends at zero: smooth in time.
#include <cstdint>
#include <random>

#include "pbd/core/state_stream.h"
#include "pbd/core/types.h"

namespace hs::cardiac {

using pbd::Real;

enum class Phase : std::uint8_t { Systole = 0, Diastole = 1, Rest = 2 };

const char* phaseName(Phase phase);

struct BeatClockSettings {
  bool physiological = false;
  // Thesis mode.
  int systoleSteps = 8;         // BEATING_DURATION
  int diastoleSteps = 8;        // BEATING_DURATION (Fig. 4.6)
  Real displacePerStep = Real(0.08);  // BEATING_DISPLACE (m)
  // Physiological mode.
  Real period = Real(60.0 / 72.0);  // s
  Real systolicFraction = Real(0.35);
  Real contraction = Real(0.3);  // m per systole
  // Both.
  int beats = 0;          // systoles to perform, then rest; 0 = no limit
  Real irregularity = 0;  // each diastole shortened by a random share in [0, irregularity)
  // Irregular beating varies each diastole both ways instead, by a share in (-irregularity,
  // irregularity): the mean rate stays, as in atrial fibrillation.
  bool irregularBothWays = false;
  unsigned seed = 1;
  // Phase offset: the first systole starts after this share of one cycle (systole plus
  // diastole) spent relaxed.
  Real startDelay = 0;
};

// The clock counts steps; in physiological mode the lengths in steps follow from the time
// step of each call (the step context's), so the clock stores no time step of its own.
class BeatClock {
 public:
  explicit BeatClock(const BeatClockSettings& settings);

  // Advances one step of dt seconds; returns the inward displacement (m) to apply during it.
  Real advance(Real dt);
  // Physiological mode: inward travel (m) since the current systole began, after the last
  // advance() (the full contraction once systole is over).
  [[nodiscard]] Real travel() const { return m_travel; }
  [[nodiscard]] bool physiological() const { return m_settings.physiological; }
  [[nodiscard]] Phase phase() const { return m_phase; }
  [[nodiscard]] int stepsInPhase() const { return m_steps; }
  [[nodiscard]] int systolesCompleted() const { return m_systolesCompleted; }
  // Length (steps of dt) of the diastole in progress or to come.
  [[nodiscard]] int diastoleLength(Real dt) const;
  // Steps since the current or last systole began (-1 before the first and at rest), and until
  // the next begins (-1 at rest or when the beats are over). In systole the diastole to come is
  // taken as a regular one (an irregular rhythm draws its length when it begins).
  [[nodiscard]] int stepsSinceSystoleStarted(Real dt) const;
  [[nodiscard]] int stepsUntilSystole(Real dt) const;
  // Checkpoints: the phase, its step count and the random stream (state_stream.h).
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);

 private:
  struct Lengths {
    int systole = 0, diastole = 0;  // steps of a regular beat
  };
  [[nodiscard]] Lengths lengths(Real dt) const;
  Real physiologicalDisplacement(int systoleLength);
  void enterDiastole();
  void endDiastole();

  BeatClockSettings m_settings;
  Phase m_phase = Phase::Systole;
  int m_steps = 0;  // steps spent in the current phase
  int m_systolesCompleted = 0;
  bool m_delayed = false;   // in the start delay (a diastole of startDelay cycles)
  double m_diastoleShare = 1;  // this diastole's share of the regular one (irregular beating)
  Real m_travel = 0;
  std::mt19937 m_random;
};

}  // namespace hs::cardiac
