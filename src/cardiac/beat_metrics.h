#pragma once
// Per-beat cavity volumes and ejection fraction. A beat runs from the start of one systole to
// the start of the next (or to the end of the run). EDV is the end-diastolic volume, the
// cavity volume when its systole starts; ESV its smallest volume; SV = EDV - ESV,
// EF = SV / EDV. A beat counts once its systole has ended: a run that stops mid-systole does
// not report a half-ejected beat.
#include <vector>

#include "cardiac/beat_clock.h"

namespace hs::cardiac {

struct BeatSummary {
  int index = 0;          // 1-based
  double startTime = 0;   // s
  double edv = 0;         // m^3
  double esv = 0;         // m^3
  [[nodiscard]] double strokeVolume() const { return edv - esv; }
  [[nodiscard]] double ejectionFraction() const { return edv > 0 ? (edv - esv) / edv : 0; }
};

class BeatTracker {
 public:
  // initialVolume: the cavity volume before the first step (the first beat's EDV candidate).
  explicit BeatTracker(double initialVolume) : m_lastVolume(initialVolume) {}

  // Called once per step with the phase the wall was in during that step and the cavity
  // volume at its end.
  void record(double time, Phase phase, double volume);
  // Closes the beat in progress (if it contained a systole).
  void finish();

  [[nodiscard]] const std::vector<BeatSummary>& beats() const { return m_beats; }
  // Mean EF over the recorded beats (0 without beats).
  [[nodiscard]] double meanEjectionFraction() const;

 private:
  std::vector<BeatSummary> m_beats;
  BeatSummary m_current;
  bool m_open = false;
  bool m_systoleEnded = false;  // of the beat in progress
  Phase m_previous = Phase::Rest;
  double m_lastVolume = 0;  // at the end of the previous step
};

}  // namespace hs::cardiac
