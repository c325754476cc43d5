#include "viewer/plots/circulation_history.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cardiac/circulation/clinical_units.h"
#include "cardiac/circulation/heart_phase.h"

namespace hs::viewer {
namespace {

using cardiac::CirculationSample;

// The first sample whose step ended after `time`.
std::size_t firstAfter(std::span<const CirculationSample> samples, double time) {
  const auto it = std::upper_bound(samples.begin(), samples.end(), time,
                                   [](double t, const CirculationSample& s) { return t < s.time; });
  return std::size_t(it - samples.begin());
}

}  // namespace

void CirculationHistory::update(std::span<const CirculationSample> samples,
                                std::span<const double> beatStarts) {
  if (samples.empty()) return;
  if (!m_samples.empty() && samples.back().time < m_samples.back().time) clear();
  const double newest = m_samples.empty() ? -std::numeric_limits<double>::infinity() : m_samples.back().time;
  m_samples.insert(m_samples.end(), samples.begin() + std::ptrdiff_t(firstAfter(samples, newest)),
                   samples.end());
  const double lastStart =
      m_beatStarts.empty() ? -std::numeric_limits<double>::infinity() : m_beatStarts.back();
  for (const double start : beatStarts)
    if (start > lastStart) m_beatStarts.push_back(start);
  trim();
}

void CirculationHistory::clear() {
  m_samples.clear();
  m_beatStarts.clear();
}

// Whole beats only: everything before the oldest kept beat's start goes.
void CirculationHistory::trim() {
  if (m_beatStarts.size() > kKeptBeats) {
    m_beatStarts.erase(m_beatStarts.begin(), m_beatStarts.end() - std::ptrdiff_t(kKeptBeats));
    const std::size_t from = firstAfter(m_samples, m_beatStarts.front());
    m_samples.erase(m_samples.begin(), m_samples.begin() + std::ptrdiff_t(from));
  }
  if (m_samples.size() > kMaxSamples)
    m_samples.erase(m_samples.begin(), m_samples.end() - std::ptrdiff_t(kMaxSamples / 2));
}

std::vector<BeatSpan> beatSpans(std::span<const CirculationSample> samples,
                                std::span<const double> beatStarts) {
  std::vector<BeatSpan> spans;
  if (samples.empty()) return spans;
  const double step = samples.size() >= 2 ? samples[1].time - samples[0].time : 0;
  for (std::size_t k = 0; k < beatStarts.size(); ++k) {
    BeatSpan b;
    b.start = beatStarts[k];
    b.begin = firstAfter(samples, b.start);
    b.complete = k + 1 < beatStarts.size();
    b.end = b.complete ? firstAfter(samples, beatStarts[k + 1]) : samples.size();
    // Half a step of slack: the two times are sums of the same dt, not equal bit for bit.
    const bool whole = b.begin > 0 || samples.front().time <= b.start + 1.5 * step;
    if (whole) spans.push_back(b);
  }
  return spans;
}

std::optional<BeatSpan> lastCompleteBeat(std::span<const CirculationSample> samples,
                                         std::span<const double> beatStarts) {
  const std::vector<BeatSpan> spans = beatSpans(samples, beatStarts);
  for (auto it = spans.rbegin(); it != spans.rend(); ++it)
    if (it->complete && it->size() >= 2) return *it;
  return std::nullopt;
}

ValveEvents valveEvents(std::span<const CirculationSample> beat, double beatStart) {
  ValveEvents e;
  const auto stepStart = [&](std::size_t i) { return i == 0 ? beatStart : beat[i - 1].time; };
  std::optional<std::size_t> firstAortic, lastAortic;
  for (std::size_t i = 0; i < beat.size(); ++i)
    if (beat[i].aorticOpen) {
      if (!firstAortic) firstAortic = i;
      lastAortic = i;
    }
  if (!firstAortic) return e;
  e.aorticOpen = stepStart(*firstAortic);
  e.mitralClose = beatStart;
  for (std::size_t i = 0; i < *firstAortic; ++i)
    if (beat[i].mitralOpen) e.mitralClose = beat[i].time;
  if (*lastAortic + 1 >= beat.size()) return e;  // still ejecting when the next beat began
  e.aorticClose = beat[*lastAortic].time;
  for (std::size_t i = *lastAortic + 1; i < beat.size(); ++i)
    if (beat[i].mitralOpen) {
      e.mitralOpen = stepStart(i);
      break;
    }
  return e;
}

MitralWaves mitralWaves(std::span<const CirculationSample> beat) {
  std::size_t from = 0, onset = beat.size();
  for (std::size_t i = 0; i < beat.size(); ++i) {
    if (beat[i].aorticOpen) from = i + 1;
    if (i > 0 && beat[i].atrialActivation > 0 && beat[i - 1].atrialActivation == 0) onset = i;
  }
  const auto peak = [&](std::size_t begin, std::size_t end) -> std::optional<std::size_t> {
    std::optional<std::size_t> best;
    for (std::size_t i = begin; i < end; ++i)
      if (beat[i].mitralFlow > 0 && (!best || beat[i].mitralFlow > beat[*best].mitralFlow)) best = i;
    return best;
  };
  MitralWaves waves;
  waves.early = peak(from, std::max(from, onset));
  waves.atrial = peak(std::max(from, onset), beat.size());
  return waves;
}

std::vector<CyclePhase> cyclePhases(const ValveEvents& e, double beatEnd) {
  using cardiac::HeartPhase;
  std::vector<CyclePhase> phases;
  auto add = [&](CyclePhaseKind kind, HeartPhase phase, double from, double to) {
    phases.push_back({kind, cardiac::heartPhaseName(phase), cardiac::heartPhaseShortName(phase), from, to});
  };
  if (e.mitralClose && e.aorticOpen)
    add(CyclePhaseKind::IsovolumicContraction, HeartPhase::IsovolumicContraction, *e.mitralClose, *e.aorticOpen);
  if (e.aorticOpen && e.aorticClose) add(CyclePhaseKind::Ejection, HeartPhase::Ejection, *e.aorticOpen, *e.aorticClose);
  if (e.aorticClose && e.mitralOpen)
    add(CyclePhaseKind::IsovolumicRelaxation, HeartPhase::IsovolumicRelaxation, *e.aorticClose, *e.mitralOpen);
  if (e.mitralOpen) add(CyclePhaseKind::Filling, HeartPhase::Filling, *e.mitralOpen, beatEnd);
  return phases;
}

double endSystolicPressure(const cardiac::PressureVolumeRelations& r, double volume) {
  return r.endSystolicElastance * (volume - r.unstressedVolume);
}

double endDiastolicPressure(const cardiac::PressureVolumeRelations& r, double volume) {
  return r.diastolicScale * (std::exp(r.diastolicExponent * (volume - r.unstressedVolume)) - 1);
}

AxisRange paddedRange(double dataMin, double dataMax, bool includeZero, double pad) {
  if (!std::isfinite(dataMin) || !std::isfinite(dataMax) || dataMin > dataMax) return {0, 1};
  if (includeZero) dataMin = std::min(dataMin, 0.0), dataMax = std::max(dataMax, 0.0);
  double span = dataMax - dataMin;
  if (span <= 1e-12 * std::max(std::abs(dataMin), std::abs(dataMax)))
    span = dataMax != 0 ? 0.2 * std::abs(dataMax) : 1;
  return {dataMin - pad * span, dataMax + pad * span};
}

LoopAxes loopAxes(std::span<const CirculationSample> samples, const cardiac::PressureVolumeRelations& r,
                  int maxVolumeTicks, int maxPressureTicks) {
  using cardiac::kCubicMetresPerMl;
  using cardiac::kPascalPerMmHg;
  const double v0 = r.unstressedVolume;
  double vMin = v0, vMax = v0, pMax = 0;
  for (const CirculationSample& s : samples) {
    vMin = std::min(vMin, s.lvVolume);
    vMax = std::max(vMax, s.lvVolume);
    pMax = std::max(pMax, s.lvPressure);
  }
  // The filling curve up to the fullest volume drawn, so the loop's lower right corner sits on it.
  pMax = std::max(pMax, endDiastolicPressure(r, vMax));
  LoopAxes axes;
  axes.volume = niceRange(vMin / kCubicMetresPerMl, vMax / kCubicMetresPerMl, true, maxVolumeTicks);
  axes.pressure = niceRange(0, pMax / kPascalPerMmHg, true, maxPressureTicks);
  return axes;
}

}  // namespace hs::viewer
