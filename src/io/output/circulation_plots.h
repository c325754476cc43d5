#pragma once
// The lumped circulation's figures as PNG (issue 13, item 5): the pressure-volume loop with the
// ventricle's end-systolic and end-diastolic relations (pv_loop.png), and the Wiggers diagram of
// one beat (wiggers.png): pressures, volume and valve flows over time, the valve events and the
// phases they bound. Built on viz::renderPlot; the samples are SI (circulation_trace.h), the
// figures clinical (mmHg, mL, mL/s, ms).
//
// The layouts are returned by the *Spec / wiggersLayout functions so callers and tests can find
// the pixel of any data point with viz::PlotFrame(spec).toPixel(x, y).
#include <cstddef>
#include <string>
#include <vector>

#include "cardiac/circulation/circulation_trace.h"
#include "viz/image.h"
#include "viz/plot.h"

namespace hs::io {

// Neutral greys, distinct from every palette colour, so no curve shares one: the Wiggers
// diagram's valve event lines and the shading of its isovolumic phases, the PV plot's relations.
inline constexpr viz::Rgb kValveEventColour{150, 150, 150};
inline constexpr viz::Rgb kIsovolumicShade{238, 238, 238};
inline constexpr viz::Rgb kEndSystolicRelationColour{90, 90, 90};
inline constexpr viz::Rgb kEndDiastolicRelationColour{150, 150, 150};

// One pressure-volume loop: a legend entry and its samples (typically the last complete beat),
// drawn as a line closed from the last sample back to the first.
struct PvLoopCurve {
  std::string label;
  std::vector<cardiac::CirculationSample> samples;
};

// A valve opening or closing, found where a sample's mitralOpen / aorticOpen differs from the
// previous sample's.
struct ValveEvent {
  enum class Kind { MitralCloses, AorticOpens, AorticCloses, MitralOpens };
  Kind kind = Kind::MitralCloses;
  // s: the end of the last step in the old state (the time of sample `lastBefore`), since a
  // sample's flag describes its whole step.
  double time = 0;
  std::size_t lastBefore = 0;  // index of the last sample in the old state
};

// "MC", "AO", "AC", "MO".
const char* valveEventAbbreviation(ValveEvent::Kind kind);

// The valve events of `samples` in time order. Throws std::invalid_argument as the plots do.
std::vector<ValveEvent> valveEvents(const std::vector<cardiac::CirculationSample>& samples);

// The samples of the last beat the samples cover completely: a beat runs from one start time to
// the next, and holds the samples whose step lies in it (start < time <= next start; a sample's
// time is its step's end). Complete: the samples reach the next start and began no later than
// one step after the beat's start. Empty when no beat is complete (a run shorter than a beat).
// Throws std::invalid_argument for beat starts out of order or non-finite.
std::vector<cardiac::CirculationSample> lastCompleteBeat(
    const std::vector<cardiac::CirculationSample>& samples, const std::vector<double>& beatStartTimes);

// x: LV volume (mL), y: LV pressure (mmHg). Each loop closed, in paletteColour(index), with
// markers at end-diastole (mitral closure, else the largest volume) and end-systole (aortic
// closure, else the smallest volume); then the ESPVR (when Ees > 0) and EDPVR (when A, B > 0)
// over the plotted volumes. Throws std::invalid_argument (one line, naming the loop, the sample
// and the field) for no loops, a loop without samples, non-finite values or negative relations.
viz::PlotSpec pressureVolumeLoopSpec(const std::vector<PvLoopCurve>& loops,
                                     const cardiac::PressureVolumeRelations& relations,
                                     const std::string& title);
// renderPlot of that spec with "ED" / "ES" written next to the markers.
viz::Image pressureVolumeLoopImage(const std::vector<PvLoopCurve>& loops,
                                   const cardiac::PressureVolumeRelations& relations,
                                   const std::string& title);
// Throws std::runtime_error("cannot write PNG '<path>': ...") when it cannot write.
void writePvLoopPng(const std::string& path, const std::vector<PvLoopCurve>& loops,
                    const cardiac::PressureVolumeRelations& relations, const std::string& title);

// The Wiggers diagram's geometry: three panels sharing the time axis (ms from the beat's start,
// the start of the first sample's step), stacked under a title and a band naming the phases.
struct WiggersLayout {
  // A phase between two valve events (or a valve event and the beat's end), named in the band.
  struct Phase {
    std::string name;  // "isovolumic contraction", "ejection", "isovolumic relaxation", "filling"
    double fromMs = 0, toMs = 0;
    bool wrapped = false;  // written on two lines: one is wider than the interval
    int tier = 0;          // 0: the row just above the event labels; 1: the row above that
    // False for the shorter piece of a phase the beat's ends cut in two (filling, for a beat
    // from activation to activation): the name is written once, on the longer piece.
    bool labelled = true;
  };

  std::string title;
  int width = 1000, height = 1100;
  viz::Rect phaseBand;                // phase names above, valve event labels along its bottom
  std::vector<viz::PlotSpec> panels;  // pressures (mmHg), LV volume (mL), flows (mL/s)
  std::vector<int> panelTops;         // image row of each panel's top edge
  std::vector<ValveEvent> events;
  std::vector<double> eventTimesMs;  // events[i].time on the axis
  std::vector<Phase> phases;         // in time order, covering the beat
  double beatStart = 0;              // s: time zero of the axis
};

// Throws std::invalid_argument for fewer than two samples, non-finite values or times that do
// not increase.
WiggersLayout wiggersLayout(const std::vector<cardiac::CirculationSample>& beat, const std::string& title);
viz::Image wiggersDiagramImage(const std::vector<cardiac::CirculationSample>& beat, const std::string& title);
// Throws std::runtime_error("cannot write PNG '<path>': ...") when it cannot write.
void writeWiggersPng(const std::string& path, const std::vector<cardiac::CirculationSample>& beat,
                     const std::string& title);

}  // namespace hs::io
