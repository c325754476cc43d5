#pragma once
// Before and after: what the run before the last restart did, kept beside the run going on, so
// that a student who applies a beating region, moves a slider or picks a scenario sees the
// change instead of losing the old numbers (ViewerApp restarts the simulation from t = 0 for
// each). Each run keeps its last complete beats (their figures are averaged: one beat of
// `irregular` alternates between an EF of 41% and 54%), its last complete beat's curves (drawn
// in grey under the new run's) and its last pressure-volume loop. No GL or ImGui: unit-tested.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cardiac/blood/flow_components.h"
#include "cardiac/circulation/beat_metrics.h"
#include "cardiac/circulation/circulation_trace.h"
#include "viewer/plots/circulation_history.h"
#include "viewer/plots/plot_history.h"
#include "viewer/plots/pump_readout.h"

namespace hs::viewer {

// The mean of the last complete beats' figures and how many beats it covers.
struct BeatMean {
  ClinicalFigures figures;  // heart rate and output from the beats' own lengths
  int count = 0;
};
// The mean over the last `n` complete beats of `beats` (oldest first), fewer when fewer are
// complete; none without a complete beat (no figure is better than a 0 that reads as one).
std::optional<BeatMean> meanOfLastBeats(std::span<const cardiac::BeatSummary> beats, int n,
                                        const VolumeScale& scale);

// The samples of the last complete beat in `history` (from one systole's start to the next),
// their times counted from the beat's start; empty when no beat is whole in it.
std::vector<PumpSample> lastBeatCurve(const PlotHistory& history);
// The start times (s) of the beats in `history`: the start of each step in which systole began.
std::vector<double> beatOnsets(const PlotHistory& history);
// The lumped circulation's last complete beat (its samples as recorded); empty without one.
std::vector<cardiac::CirculationSample> lastLoop(const CirculationHistory& history);

// Where a one-beat curve of length `period` is laid under the plot's window [t0, t1]: at each
// of the current run's beat onsets, each drawn up to the next onset; with no onset (the cycle
// off) from t = 0 on, one period after another. Pairs of (start, end) in s.
struct OverlaySpan {
  double start, end;
};
std::vector<OverlaySpan> overlaySpans(std::span<const double> onsets, double period, double t0, double t1);

struct RunRecord {
  std::string label;  // "normal", "normal, region applied"
  VolumeScale scale;
  bool lumped = false;                          // pressures from the lumped circulation
  std::vector<cardiac::BeatSummary> beats;      // the last complete beats, oldest first
  std::vector<PumpSample> beatCurve;            // the last complete beat (kept at the restart)
  std::vector<cardiac::CirculationSample> loop;  // its pressure-volume loop (kept at the restart)
  // The 3D blood's flow components of its last beat (none without blood and valves).
  std::optional<cardiac::FlowComponents> flowComponents;
  [[nodiscard]] std::optional<BeatMean> mean(int n = kMeanBeats) const {
    return meanOfLastBeats(beats, n, scale);
  }
  static constexpr int kMeanBeats = 5;
};

// The run going on ("now") and the one before it ("before"). The app tells it each frame what
// the current run has done, and at each restart what the new run is: the current run, with its
// curves taken from the histories, becomes "before". A run that ended before completing a beat
// has nothing to compare: the older "before" stays.
class RunComparison {
 public:
  void update(std::span<const cardiac::BeatSummary> completeBeats, const VolumeScale& scale, bool lumped,
              const std::optional<cardiac::FlowComponents>& flowComponents = std::nullopt);
  // Call before the histories are cleared for the new run.
  void restart(std::string label, const PlotHistory& history, const CirculationHistory& circulation);

  [[nodiscard]] const RunRecord& current() const { return m_current; }
  [[nodiscard]] const std::optional<RunRecord>& previous() const { return m_previous; }
  // The two runs' curves can share an axis: both real-size or both thesis scale.
  [[nodiscard]] bool comparable() const { return m_previous && m_previous->scale.thesis == m_current.scale.thesis; }
  // The run before's last beat where it shares this run's units (empty otherwise), and its
  // pressure-volume loop (always mL and mmHg).
  [[nodiscard]] std::span<const PumpSample> previousCurve() const {
    return comparable() ? std::span<const PumpSample>(m_previous->beatCurve) : std::span<const PumpSample>();
  }
  [[nodiscard]] std::span<const cardiac::CirculationSample> previousLoop() const {
    return m_previous ? std::span<const cardiac::CirculationSample>(m_previous->loop)
                      : std::span<const cardiac::CirculationSample>();
  }

 private:
  RunRecord m_current;
  std::optional<RunRecord> m_previous;
};

}  // namespace hs::viewer
