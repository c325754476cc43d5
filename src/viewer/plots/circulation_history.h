#pragma once
// The lumped circulation's recent past for the viewer's pressure-volume loop and Wiggers
// diagram (circulation_panel.h), and the arithmetic the two figures rest on: which samples form
// the last beats, when the valves opened and closed, the phases between those events, the
// pressure-volume relations and the loop's axes. SI units in, as the recorder gives them; the
// figures convert (clinical_units.h). No GL or ImGui, so it is unit-tested
// (tests/viewer/plots/test_circulation_history.cpp).
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "cardiac/circulation/circulation_trace.h"
#include "viewer/plots/plot_history.h"

namespace hs::viewer {

// The samples of the last few beats, copied from the run monitor's CirculationRecorder one
// frame at a time. The recorder keeps seconds of samples (MonitorSettings::lumpedSamples) and
// drops half of them when full; copying only what is new and keeping only whole beats keeps
// the frame's visit to the simulation thread short whatever the run's length.
class CirculationHistory {
 public:
  // The beat in progress and three complete ones: the loop draws three, the Wiggers diagram one.
  static constexpr std::size_t kKeptBeats = 4;
  // Bounds the copy when no beat starts (a heart rate far below any the panel offers).
  static constexpr std::size_t kMaxSamples = std::size_t(1) << 15;

  // Appends the recorder's samples and beat starts newer than the newest held. A recorder
  // whose newest sample is older than the newest held belongs to a restarted simulation: the
  // history starts over with it.
  void update(std::span<const cardiac::CirculationSample> samples, std::span<const double> beatStarts);
  void clear();

  [[nodiscard]] const std::vector<cardiac::CirculationSample>& samples() const { return m_samples; }
  [[nodiscard]] const std::vector<double>& beatStarts() const { return m_beatStarts; }

 private:
  void trim();

  std::vector<cardiac::CirculationSample> m_samples;
  std::vector<double> m_beatStarts;  // s, onsets of the ventricle's activation
};

// One beat's samples [begin, end): those whose step ended after the beat's start and no later
// than the next beat's start (a sample's time is its step's end; the recorder's beat starts are
// step starts).
struct BeatSpan {
  std::size_t begin = 0, end = 0;
  double start = 0;       // s
  bool complete = false;  // the next beat has started
  [[nodiscard]] std::size_t size() const { return end - begin; }
};

// The beats whose samples are all held, oldest first; the last one is in progress (possibly
// still empty). A beat is whole when a sample lies at or before its start, or the first sample
// ends the step that starts it.
std::vector<BeatSpan> beatSpans(std::span<const cardiac::CirculationSample> samples,
                                std::span<const double> beatStarts);
// The newest complete beat with at least two samples, if any.
std::optional<BeatSpan> lastCompleteBeat(std::span<const cardiac::CirculationSample> samples,
                                         std::span<const double> beatStarts);

// The four valve events of a beat that starts with the ventricle's activation, in seconds, from
// the lumped valves' open flags (forward flow during a step). A step's flag says what the valve
// did between the previous sample's time and its own, so a valve opens at the end of the last
// step it was shut and closes at the end of the last step it was open. Taken as the first and
// last of each run rather than every change, so a flag that flickers (a few steps of zero flow
// in diastasis) cannot add events:
//   AO: the first step the aortic valve is open; AC: the end of its last open step, unless it
//   is still open when the beat ends; MC: the end of the last mitral-open step before AO (the
//   beat's start when the mitral valve was already shut); MO: the first mitral-open step after
//   AC. Without ejection (no AO) none is named.
struct ValveEvents {
  std::optional<double> mitralClose, aorticOpen, aorticClose, mitralOpen;
};
ValveEvents valveEvents(std::span<const cardiac::CirculationSample> beat, double beatStart);

// The two waves of mitral inflow, as sample indices of their peaks: E (early, rapid filling as
// the ventricle relaxes) after the aortic valve's last open step and before the atrium's
// contraction, A (the atrium's kick) from the last rise of its activation from zero (the
// contraction that ends this beat; the one that began the beat may still be fading at its
// start), as cardiac/circulation/lumped_beat.cpp splits them for E/A. None without forward flow.
struct MitralWaves {
  std::optional<std::size_t> early, atrial;
};
MitralWaves mitralWaves(std::span<const cardiac::CirculationSample> beat);

// The phases of the cardiac cycle between the valve events (Wiggers 1915, as every physiology
// text draws them), from `beatStart` to `beatEnd`. Only phases with both ends known are listed.
enum class CyclePhaseKind { IsovolumicContraction, Ejection, IsovolumicRelaxation, Filling };
struct CyclePhase {
  CyclePhaseKind kind;
  const char* name;       // "isovolumic contraction"
  const char* shortName;  // "IVC": for a span too narrow for the name
  double from, to;        // s
};
std::vector<CyclePhase> cyclePhases(const ValveEvents& events, double beatEnd);

// The relations the loop moves between (circulation_trace.h), in Pa for a volume in m^3.
double endSystolicPressure(const cardiac::PressureVolumeRelations& r, double volume);
double endDiastolicPressure(const cardiac::PressureVolumeRelations& r, double volume);

// A stacked chart's value range (the Wiggers diagram's panels): the data's, widened to hold
// zero when asked, padded by `pad` of its span on both sides and not rounded out to whole tick
// steps, so the curves fill a short panel; a flat line gets a range around it.
AxisRange paddedRange(double dataMin, double dataMax, bool includeZero, double pad = 0.06);

// The loop's axes in display units (mL, mmHg) over the samples drawn: volume from the
// unstressed volume V0 (where the end-systolic line meets zero pressure, so its slope reads
// true) to the largest volume, pressure from zero to the highest pressure of the loops or of
// the end-diastolic relation at the largest volume. maxTicks: per axis, as niceRange takes it.
struct LoopAxes {
  AxisRange volume, pressure;
};
LoopAxes loopAxes(std::span<const cardiac::CirculationSample> samples,
                  const cardiac::PressureVolumeRelations& r, int maxVolumeTicks, int maxPressureTicks);

}  // namespace hs::viewer
