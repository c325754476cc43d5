#pragma once
// The heart as a pump, for the viewer's panel: the clinical figures of the beat in progress and
// of the last complete beat (EDV, ESV, SV, EF, cardiac output, regurgitation, heart rate), in
// the units a clinician reads, and the per-step values the live plots draw. Pure arithmetic on
// what the simulation reports after each step; no GL or ImGui, so it is unit-tested.
#include <array>
#include <vector>
#include <limits>
#include <optional>

#include "cardiac/circulation.h"
#include "cardiac/circulation/beat_metrics.h"
#include "cardiac/run_monitor.h"
#include "cardiac/scenario.h"

namespace hs::viewer {

// Display units: cardiac::VolumeScale (beat_metrics.h), shared with the command line.
using cardiac::kThesisScaleVolume;
using cardiac::VolumeScale;
using cardiac::volumeScaleFor;
using cardiac::kPascalPerMmHg;

// One beat's figures in display units (volumeScale), heart rate from the beat's length.
struct ClinicalFigures {
  double edv = 0, esv = 0, strokeVolume = 0;  // volume unit
  double ejectionFraction = 0;                // percent
  double cardiacOutput = 0;                   // output unit
  double regurgitantVolume = 0;               // volume unit
  double forwardStrokeVolume = 0;             // volume unit: SV - regurgitant volume
  double heartRate = 0;                       // beats per minute; 0 for an unfinished beat
  bool complete = false;                      // ended by the next systole
};
ClinicalFigures clinicalFigures(const cardiac::BeatSummary& beat, const VolumeScale& scale);

// What one step adds to the plots (SI): the cavity volume, the net valve flow rates (raw, and
// smoothed once the steps around it are known: plot_history.h) and the pressures.
struct PumpSample {
  double time = 0;                        // s, at the end of the step
  cardiac::Phase phase = cardiac::Phase::Rest;  // during the step: beats start with systole
  double cavity = 0;                      // m^3
  double mitralRate = 0, aorticRate = 0;  // m^3/s, forward - backward over the step
  // m^3/s, the centred mean over the smoothing window; NaN until the window's later half is in.
  double mitralSmoothed = kUnknown, aorticSmoothed = kUnknown;
  // Pa. With the lumped circulation: its LV, left atrial and proximal aortic pressures (the
  // clinical ones); otherwise the blood solver's mean gauge pressure in the LV, the inflow
  // vessel and the outflow vessel.
  double pressureLv = 0, pressureInflow = 0, pressureOutflow = 0;
  static constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();
};
// The flows of one step of length dt as rates (m^3/s).
void setFlowRates(PumpSample& sample, const cardiac::ValveFlows& flows, double dt);
// The plots' sample of a step the run monitor gathered.
PumpSample pumpSample(const cardiac::StepSample& step);

// When the beats after a restart have settled (the circulation starts from rest each time and
// takes a few beats to find its new balance: with the resistance doubled, EF climbs from 41% to
// 48% over ten beats). A regular rhythm has settled at the first beat whose end-diastolic and
// end-systolic volumes are both within `tolerance` of the beat before's. An irregular rhythm
// varies from beat to beat by design, so there the beats count from `settledAfter` seconds on
// (three time constants R C of the arterial Windkessel, or three regular beats without it:
// settlingRuleFor in the viewer's runner). Once settled, every later beat counts.
struct SettlingRule {
  bool irregular = false;
  double tolerance = 0.01;
  double settledAfter = 0;  // s, irregular rhythms only
};
// The rule for a scenario: irregular for the irregular and inconsistent patterns, which settle
// after three time constants R C of the lumped Windkessel (or three beats without one).
SettlingRule settlingRuleFor(const cardiac::Scenario& scenario);
// True when `beat` has settled, `previous` being the complete beat before it (none for the first).
bool beatSettles(const SettlingRule& rule, const cardiac::BeatSummary& beat,
                 const std::optional<cardiac::BeatSummary>& previous);

// The beat in progress, the last complete one and the few before it.
struct BeatReadings {
  std::optional<cardiac::BeatSummary> current;  // once its systole has ended (ESV known)
  std::optional<cardiac::BeatSummary> last;     // the last complete beat
  // The last complete beats since the circulation settled (SettlingRule), oldest first: what
  // `now` and `before` average. Empty while it settles.
  std::vector<cardiac::BeatSummary> recent;
  bool settled = false;  // a beat has settled
  std::vector<cardiac::BeatSummary> played;  // the last complete beats, settled or not (a lesson's table)
  int beatsCompleted = 0;
  bool beating = false;     // a beat is in progress
  double currentEdv = 0;    // m^3, the beat in progress's end-diastolic volume
  double currentStart = 0;  // s
};

// Feeds a cardiac::BeatTracker from the simulation as `heartsim run` does: record(start time
// of the step, phase during it, cavity volume at its end, flows) after each step. It keeps one
// tracker per beat, so reading the beat in progress (a copy closed with finish()) costs one
// beat however long the viewer runs.
class PumpReadout {
 public:
  // Complete beats kept for the means (run_comparison.h averages up to 5).
  static constexpr std::size_t kRecentBeats = 8;

  // initialVolume: the cavity volume before the first step (m^3); dt: the step (s).
  PumpReadout(double initialVolume, double dt, SettlingRule settling = {});
  void record(double startTime, cardiac::Phase phase, double volume, const cardiac::ValveFlows& flows);
  [[nodiscard]] BeatReadings readings() const;

 private:
  cardiac::BeatTracker m_tracker;  // the beat in progress (and, until the next starts, the last)
  std::optional<cardiac::BeatSummary> m_last;
  std::vector<cardiac::BeatSummary> m_recent, m_played;
  int m_completed = 0;
  SettlingRule m_settling;
  bool m_settled = false;
  double m_dt = 0;
  double m_lastVolume = 0;
  double m_currentEdv = 0, m_currentStart = 0;
  bool m_beating = false;
  cardiac::Phase m_previous = cardiac::Phase::Rest;
};

}  // namespace hs::viewer
