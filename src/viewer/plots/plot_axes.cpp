#include "viewer/plots/plot_axes.h"

#include <algorithm>
#include <cmath>

namespace hs::viewer {
namespace {

// A range from zero (or symmetric about it) to `extent` in 1-2-5 ticks, and its tick step.
struct Stepped {
  AxisRange range;
  double step;
};
Stepped stepped(double lo, double hi) {
  const AxisRange r = niceRange(lo, hi, true, 5);
  return {r, niceTicks(r.lo, r.hi, 5).step};
}

}  // namespace

AxisRange widenToHold(AxisRange range, double value, double step) {
  if (!std::isfinite(value) || !(step > 0)) return range;
  if (value > range.hi) range.hi = std::ceil(value / step - 1e-9) * step;
  if (value < range.lo) range.lo = std::floor(value / step + 1e-9) * step;
  return range;
}

PlotAxes::PlotAxes(const VolumeScale& scale, double restVolume, std::span<const PumpSample> before)
    : m_scale(scale) {
  if (!scale.thesis) {
    m_pressureScale = 1 / kPascalPerMmHg;
    m_volume = {0, 200}, m_volumeStep = 50;
    m_flow = {-200, 600}, m_flowStep = 200;
    m_pressure = {0, 150}, m_pressureStep = 50;
  } else {
    // Thesis scale (paper-chamber 7.4 m^3, heart-only 33 m^3): the cavity up to half again its
    // rest volume; a quarter of it per second either way through a valve (the thesis's blood
    // crosses slowly: about 1.5 m^3/s at paper-chamber-beating's peaks); the blood solver's
    // gauge pressure from 0 to 10 kPa.
    const double v0 = std::max(restVolume * scale.volume, 1e-9);
    const Stepped volume = stepped(0, 1.5 * v0);
    const Stepped flow = stepped(-0.25 * v0, 0.25 * v0);
    m_volume = volume.range, m_volumeStep = volume.step;
    m_flow = flow.range, m_flowStep = flow.step;
    m_pressure = {0, 1e4}, m_pressureStep = 2e3;
  }
  m_volume = widenToHold(m_volume, 1.25 * restVolume * scale.volume, m_volumeStep);
  for (const PumpSample& sample : before) hold(sample);
}

void holdNewSamples(PlotAxes& axes, const PlotHistory& history, std::size_t added) {
  const std::size_t back = std::min(history.size(), added + std::size_t(std::max(0, history.smoothingHalfSteps())) + 1);
  for (std::size_t i = history.size() - back; i < history.size(); ++i) axes.hold(history[i]);
}

void PlotAxes::hold(const PumpSample& s) {
  m_volume = widenToHold(m_volume, s.cavity * m_scale.volume, m_volumeStep);
  for (const double rate : {s.mitralSmoothed, s.aorticSmoothed})
    m_flow = widenToHold(m_flow, rate * m_scale.volume, m_flowStep);
  for (const double p : {s.pressureLv, s.pressureInflow, s.pressureOutflow})
    m_pressure = widenToHold(m_pressure, p * m_pressureScale, m_pressureStep);
}

}  // namespace hs::viewer
