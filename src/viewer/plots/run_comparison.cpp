#include "viewer/plots/run_comparison.h"

#include <algorithm>
#include <limits>

namespace hs::viewer {
namespace {

bool startsBeat(const PlotHistory& h, std::size_t i) {
  return h[i].phase == cardiac::Phase::Systole && (i == 0 || h[i - 1].phase != cardiac::Phase::Systole);
}

// The step's length, from the two newest samples (the viewer's dt is fixed during a run).
double stepLength(const PlotHistory& h) { return h.size() >= 2 ? h.newest().time - h[h.size() - 2].time : 0; }

}  // namespace

std::optional<BeatMean> meanOfLastBeats(std::span<const cardiac::BeatSummary> beats, int n,
                                        const VolumeScale& scale) {
  BeatMean m;
  ClinicalFigures& sum = m.figures;
  for (auto it = beats.rbegin(); it != beats.rend() && m.count < n; ++it) {
    if (!it->complete) continue;
    const ClinicalFigures f = clinicalFigures(*it, scale);
    sum.edv += f.edv, sum.esv += f.esv, sum.strokeVolume += f.strokeVolume;
    sum.forwardStrokeVolume += f.forwardStrokeVolume, sum.ejectionFraction += f.ejectionFraction;
    sum.cardiacOutput += f.cardiacOutput, sum.regurgitantVolume += f.regurgitantVolume;
    sum.heartRate += f.heartRate;
    ++m.count;
  }
  if (m.count == 0) return std::nullopt;
  for (double* v : {&sum.edv, &sum.esv, &sum.strokeVolume, &sum.forwardStrokeVolume, &sum.ejectionFraction,
                    &sum.cardiacOutput, &sum.regurgitantVolume, &sum.heartRate})
    *v /= m.count;
  sum.complete = true;
  return m;
}

std::vector<double> beatOnsets(const PlotHistory& history) {
  std::vector<double> onsets;
  const double dt = stepLength(history);
  for (std::size_t i = 0; i < history.size(); ++i)
    if (startsBeat(history, i)) onsets.push_back(i > 0 ? history[i - 1].time : history[i].time - dt);
  return onsets;
}

std::vector<PumpSample> lastBeatCurve(const PlotHistory& history) {
  std::vector<std::size_t> starts;
  for (std::size_t i = history.size(); i-- > 0 && starts.size() < 2;)
    if (startsBeat(history, i)) starts.push_back(i);
  // The older start must have a sample before it, or be the run's first step: else the beat
  // may have begun before the history's oldest sample.
  const double dt = stepLength(history);
  if (starts.size() < 2 || (starts[1] == 0 && history[0].time > 1.5 * dt)) return {};
  const double start = starts[1] > 0 ? history[starts[1] - 1].time : history[0].time - dt;
  std::vector<PumpSample> curve;
  for (std::size_t i = starts[1]; i < starts[0]; ++i) {
    PumpSample s = history[i];
    s.time -= start;
    curve.push_back(s);
  }
  return curve;
}

std::vector<cardiac::CirculationSample> lastLoop(const CirculationHistory& history) {
  const std::optional<BeatSpan> beat = lastCompleteBeat(history.samples(), history.beatStarts());
  if (!beat) return {};
  const auto begin = history.samples().begin() + std::ptrdiff_t(beat->begin);
  return {begin, begin + std::ptrdiff_t(beat->size())};
}

std::vector<OverlaySpan> overlaySpans(std::span<const double> onsets, double period, double t0, double t1) {
  std::vector<OverlaySpan> spans;
  if (!(period > 0) || !(t1 > t0)) return spans;
  const double infinity = std::numeric_limits<double>::infinity();
  if (onsets.empty()) {
    for (double s = std::max(0.0, std::floor(t0 / period) * period); s < t1; s += period)
      spans.push_back({s, s + period});
    return spans;
  }
  for (std::size_t k = 0; k < onsets.size(); ++k) {
    const double end = k + 1 < onsets.size() ? onsets[k + 1] : infinity;
    if (end > t0 && onsets[k] < t1) spans.push_back({onsets[k], std::min(end, onsets[k] + period)});
  }
  return spans;
}

void RunComparison::update(std::span<const cardiac::BeatSummary> completeBeats, const VolumeScale& scale,
                           bool lumped, const std::optional<cardiac::FlowComponents>& flowComponents) {
  m_current.beats.assign(completeBeats.begin(), completeBeats.end());
  m_current.flowComponents = flowComponents;
  m_current.scale = scale;
  m_current.lumped = lumped;
}

void RunComparison::restart(std::string label, const PlotHistory& history, const CirculationHistory& circulation) {
  if (!m_current.beats.empty()) {
    m_current.beatCurve = lastBeatCurve(history);
    m_current.loop = lastLoop(circulation);
    m_previous = std::move(m_current);
  }
  m_current = RunRecord{};
  m_current.label = std::move(label);
}

}  // namespace hs::viewer
