#include "viewer/plots/plot_history.h"

#include <algorithm>
#include <cmath>

namespace hs::viewer {

void PlotHistory::setWindow(double seconds) {
  m_window = std::max(seconds, 0.0);
  dropOld();
}

void PlotHistory::push(const PumpSample& sample) {
  if (m_size > 0 && sample.time <= newest().time) clear();
  if (m_size == m_ring.size()) grow();
  m_ring[(m_head + m_size) % m_ring.size()] = sample;
  ++m_size;
  smoothNewest();
  dropOld();
}

double PlotHistory::smoothingSeconds() const {
  return m_halfSteps < 0 ? m_smoothing : double(2 * m_halfSteps + 1) * m_step;
}

// A centred mean over whole steps: each step's rate is the volume that crossed in it over dt,
// so the mean of 2 half + 1 rates is the volume that crossed in the window over its length.
void PlotHistory::smoothNewest() {
  if (m_halfSteps < 0 && m_size >= 2) {
    m_step = newest().time - (*this)[m_size - 2].time;
    m_halfSteps = m_step > 0 ? std::max(0, int(std::lround((m_smoothing / m_step - 1) / 2))) : 0;
  }
  if (m_halfSteps < 0) return;
  const auto width = std::size_t(2 * m_halfSteps + 1);
  if (m_size < width) return;
  double mitral = 0, aortic = 0;
  for (std::size_t i = m_size - width; i < m_size; ++i) mitral += (*this)[i].mitralRate, aortic += (*this)[i].aorticRate;
  PumpSample& centre = at(m_size - 1 - std::size_t(m_halfSteps));
  centre.mitralSmoothed = mitral / double(width);
  centre.aorticSmoothed = aortic / double(width);
}

std::size_t PlotHistory::lowerBound(double time) const {
  std::size_t lo = 0, hi = m_size;
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if ((*this)[mid].time < time)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo;
}

// Keeps one sample at or before the window's left edge, so the line reaches the edge.
void PlotHistory::dropOld() {
  if (m_size == 0) return;
  const double edge = newest().time - m_window;
  while (m_size > 1 && ((*this)[1].time <= edge || m_size > kMaxSamples)) {
    m_head = (m_head + 1) % m_ring.size();
    --m_size;
  }
}

// Doubles the ring (up to one more than the cap: the sample just pushed, before dropOld),
// unrolled so the oldest sample comes first again.
void PlotHistory::grow() {
  const std::size_t capacity = std::min(std::max<std::size_t>(64, 2 * m_ring.size()), kMaxSamples + 1);
  std::vector<PumpSample> ring(capacity);
  for (std::size_t i = 0; i < m_size; ++i) ring[i] = (*this)[i];
  m_ring = std::move(ring);
  m_head = 0;
}

AxisTicks niceTicks(double lo, double hi, int maxTicks) {
  maxTicks = std::max(maxTicks, 2);
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return {lo, 1, std::isfinite(lo) ? 1 : 0};
  const double rough = (hi - lo) / double(maxTicks - 1);
  const double decade = std::pow(10.0, std::floor(std::log10(rough)));
  double step = 10 * decade;
  for (const double m : {1.0, 2.0, 5.0})
    if (m * decade >= rough * (1 - 1e-9)) {
      step = m * decade;
      break;
    }
  AxisTicks t;
  t.step = step;
  t.first = std::ceil(lo / step - 1e-9) * step;
  t.count = int(std::floor((hi - t.first) / step + 1e-9)) + 1;
  return t;
}

AxisRange niceRange(double dataMin, double dataMax, bool includeZero, int maxTicks) {
  if (!std::isfinite(dataMin) || !std::isfinite(dataMax) || dataMin > dataMax) return {0, 1};
  if (includeZero) {
    dataMin = std::min(dataMin, 0.0);
    dataMax = std::max(dataMax, 0.0);
  }
  if (dataMax - dataMin <= 1e-12 * std::max(std::abs(dataMin), std::abs(dataMax))) {
    // A flat line (or nothing but zeros): a range of +-10% around it, or -1..1 at zero.
    const double half = dataMax != 0 ? 0.1 * std::abs(dataMax) : 1.0;
    dataMin -= half;
    dataMax += half;
  }
  const double pad = 0.04 * (dataMax - dataMin);
  const double lo = dataMin < 0 || !includeZero ? dataMin - pad : dataMin;
  const double hi = dataMax + pad;
  const AxisTicks t = niceTicks(lo, hi, maxTicks);
  return {std::floor(lo / t.step + 1e-9) * t.step, std::ceil(hi / t.step - 1e-9) * t.step};
}

}  // namespace hs::viewer
