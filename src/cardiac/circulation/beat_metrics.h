#pragma once
// Per-beat cavity volumes and ejection fraction. A beat runs from the start of one systole to
// the start of the next (or to the end of the run). EDV is the end-diastolic volume, the
// cavity volume when its systole starts; ESV its smallest volume; SV = EDV - ESV,
// EF = SV / EDV. A beat counts once its systole has ended: a run that stops mid-systole does
// not report a half-ejected beat.
#include <algorithm>
#include <vector>

#include "cardiac/circulation/beat_clock.h"
#include "pbd/core/state_stream.h"

namespace hs::cardiac {

// Blood volumes (m^3) that crossed the two orifices in one step or one beat.
struct ValveFlows {
  double mitralForward = 0, mitralBackward = 0, aorticForward = 0, aorticBackward = 0;
  ValveFlows& operator+=(const ValveFlows& o) {
    mitralForward += o.mitralForward, mitralBackward += o.mitralBackward;
    aorticForward += o.aorticForward, aorticBackward += o.aorticBackward;
    return *this;
  }
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);
};

struct BeatSummary {
  int index = 0;          // 1-based
  double startTime = 0;   // s
  double duration = 0;    // s, to the next systole's start (or the end of the run)
  bool complete = false;  // ended by the next systole (not by the end of the run)
  double edv = 0;         // m^3
  double esv = 0;         // m^3
  ValveFlows flows;       // over the beat
  // Net forward volume (m^3, forward - backward) through the mitral valve during systole and
  // through the aortic valve during diastole: the phases in which each should be shut.
  double mitralNetInSystole = 0, aorticNetInDiastole = 0;
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);
  [[nodiscard]] double strokeVolume() const { return edv - esv; }
  [[nodiscard]] double ejectionFraction() const { return edv > 0 ? (edv - esv) / edv : 0; }
  // Cardiac output (m^3/s): the stroke volume once per beat, CO = SV / beat length.
  [[nodiscard]] double cardiacOutput() const { return duration > 0 ? strokeVolume() / duration : 0; }
  // Regurgitant volume (m^3): blood that went back through a valve while it should have been
  // shut, the net backward flow through the mitral valve in systole plus that through the
  // aortic valve in diastole. Particles that cross an open valve's plane to and fro count
  // both ways in `flows` and cancel here.
  [[nodiscard]] double regurgitantVolume() const {
    return std::max(0.0, -mitralNetInSystole) + std::max(0.0, -aorticNetInDiastole);
  }
};

// Display units. The thesis-scale models are metres across (cavity ~7 m^3): their volumes in
// mL would read 7,000,000, so they are shown in m^3, and their pressures have no clinical
// meaning, so no mmHg is given. A real heart's cavity is ~0.12 L.
struct VolumeScale {
  bool thesis = false;
  double volume = 1e6;               // m^3 -> shown volume unit
  const char* volumeUnit = "mL";     // also per beat: EDV, ESV, SV, regurgitation
  const char* flowUnit = "mL/s";     // valve flow rate
  double output = 1e3 * 60;          // m^3/s -> shown cardiac output unit
  const char* outputUnit = "L/min";  // cardiac output
};
// Cavity volumes of 10 L and more (no heart is that large) are thesis scale.
inline constexpr double kThesisScaleVolume = 1e-2;  // m^3
VolumeScale volumeScaleFor(double cavityVolume);

// Means over the complete beats after the first (the first starts from the initial state):
// the figures a run reports for the heart's pumping. count = 0 when there are none.
struct BeatMeans {
  int count = 0;
  double edv = 0, esv = 0, strokeVolume = 0, ejectionFraction = 0, cardiacOutput = 0, regurgitantVolume = 0;
  double aorticNet = 0;  // m^3 per beat through the aortic valve, forward - backward
};

class BeatTracker {
 public:
  // initialVolume: the cavity volume before the first step (the first beat's EDV candidate).
  // stepLength: dt (s); record() gets each step's start time, so a beat's duration ends one
  // step after the last step recorded in it.
  explicit BeatTracker(double initialVolume, double stepLength = 0)
      : m_lastVolume(initialVolume), m_stepLength(stepLength) {}

  // Called once per step with the phase the wall was in during that step and the cavity
  // volume at its end.
  void record(double time, Phase phase, double volume, const ValveFlows& flows = {});
  // Closes the beat in progress (if it contained a systole).
  void finish();

  [[nodiscard]] const std::vector<BeatSummary>& beats() const { return m_beats; }
  // Mean EF over the recorded beats (0 without beats).
  [[nodiscard]] double meanEjectionFraction() const;
  [[nodiscard]] BeatMeans means() const;
  // Checkpoints: the beats so far and the one in progress (the step length is a setting).
  void save(pbd::StateWriter& w) const;
  void load(pbd::StateReader& r);

 private:
  std::vector<BeatSummary> m_beats;
  BeatSummary m_current;
  bool m_open = false;
  bool m_systoleEnded = false;  // of the beat in progress
  Phase m_previous = Phase::Rest;
  double m_lastVolume = 0;  // at the end of the previous step
  double m_stepLength = 0;
  void close(bool complete);
};

}  // namespace hs::cardiac
