#pragma once
// The value axes of the pump panel's plots, fixed so that the size of a curve means something:
// a self-rescaling axis draws a 16 mL stroke as tall as a 69 mL one, and with the cycle off it
// blows 0.0006 mL of noise up to the plot's height. A real-size heart gets clinical ranges
// (volume 0-200 mL, flow -200..600 mL/s, pressure 0-150 mmHg; `normal`'s aortic peak is about
// 550 mL/s, its LV peak about 130 mmHg). The thesis's metre-scale models get ranges of their
// own in SI units, from the cavity's rest volume. A range only ever widens, in whole steps,
// when a value leaves it (a dilated ventricle's 250 mL, a stenosis's 190 mmHg), and never
// narrows during a run, so no noise can rescale it. No GL or ImGui: unit-tested.
#include <cstddef>
#include <span>

#include "viewer/plots/plot_history.h"
#include "viewer/plots/pump_readout.h"

namespace hs::viewer {

class PlotAxes {
 public:
  // restVolume: the cavity at the start (m^3). A rest volume beyond the volume range widens it
  // at once, with room for the filling to come.
  // before: the grey curve of the run before (run_comparison.h), held too.
  PlotAxes(const VolumeScale& scale, double restVolume, std::span<const PumpSample> before = {});
  PlotAxes() : PlotAxes(VolumeScale{}, 0) {}

  // Widens the ranges to hold the values a sample draws (the smoothed flows, once known).
  void hold(const PumpSample& sample);

  // Display units: mL, mL/s, mmHg for a real heart; m^3, m^3/s, Pa at thesis scale.
  [[nodiscard]] const AxisRange& volume() const { return m_volume; }
  [[nodiscard]] const AxisRange& flow() const { return m_flow; }
  [[nodiscard]] const AxisRange& pressure() const { return m_pressure; }
  // Shown pressure = Pa x pressureScale().
  [[nodiscard]] double pressureScale() const { return m_pressureScale; }
  [[nodiscard]] const VolumeScale& scale() const { return m_scale; }

 private:
  VolumeScale m_scale;
  double m_pressureScale = 1;
  AxisRange m_volume, m_flow, m_pressure;
  double m_volumeStep = 1, m_flowStep = 1, m_pressureStep = 1;
};

// Holds the `added` newest samples of `history` and those whose smoothed flows they made known.
void holdNewSamples(PlotAxes& axes, const PlotHistory& history, std::size_t added);

// `range` widened to hold `value` (display units), its ends moved out to whole `step`s; a
// value inside it (or not a number) leaves it as it is.
AxisRange widenToHold(AxisRange range, double value, double step);

}  // namespace hs::viewer
