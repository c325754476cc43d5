#include "io/output/circulation_plots.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "io/output/circulation_plots_internal.h"

namespace hs::io {

using cardiac::CirculationSample;
using cardiac::PressureVolumeRelations;

void validateCirculationSamples(const std::vector<CirculationSample>& samples, const std::string& what) {
  if (samples.empty()) throw std::invalid_argument(what + ": no samples");
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const CirculationSample& s = samples[i];
    const std::pair<const char*, double> fields[] = {{"time", s.time},
                                                     {"lvVolume", s.lvVolume},
                                                     {"lvPressure", s.lvPressure},
                                                     {"laPressure", s.laPressure},
                                                     {"aorticPressure", s.aorticPressure},
                                                     {"mitralFlow", s.mitralFlow},
                                                     {"aorticFlow", s.aorticFlow}};
    for (const auto& [name, value] : fields) {
      if (!std::isfinite(value)) {
        throw std::invalid_argument(what + ": sample " + std::to_string(i) + " has a non-finite " + name +
                                    " (" + std::to_string(value) + ")");
      }
    }
  }
}

void makeRoomForLegend(viz::PlotSpec& spec, std::size_t first, std::size_t end) {
  const auto [bottom, top] = *spec.yRange;
  double lowestTop = std::numeric_limits<double>::infinity();
  viz::LegendCorner best = viz::LegendCorner::TopRight;
  for (const viz::LegendCorner corner : {viz::LegendCorner::TopRight, viz::LegendCorner::TopLeft}) {
    spec.legendCorner = corner;
    const viz::PlotFrame frame(spec);
    if (!frame.legend()) {
      spec.legendCorner.reset();
      return;
    }
    const viz::Rect& legend = *frame.legend();
    const viz::Rect& area = frame.area();
    const int gap = 6 * frame.textScale();
    double highest = bottom;  // of the series in the legend's columns
    for (std::size_t i = first; i < end; ++i) {
      for (std::size_t k = 0; k < spec.series[i].x.size(); ++k) {
        const double x = frame.toPixel(spec.series[i].x[k], 0.0).x;
        if (x >= legend.x - gap && x < legend.x + legend.width + gap)
          highest = std::max(highest, spec.series[i].y[k]);
      }
    }
    // The row of y, area.y + H (top' - y) / (top' - bottom), must lie f H below area.y:
    // top' >= (y - f bottom) / (1 - f).
    const double f = static_cast<double>(legend.y + legend.height + gap - area.y) / area.height;
    const double needed = (highest - f * bottom) / std::max(1.0 - f, 0.1);
    if (needed < lowestTop) {
      lowestTop = needed;
      best = corner;
    }
  }
  spec.legendCorner = best;
  spec.yRange->second = std::max(top, lowestTop);
}

const char* valveEventAbbreviation(ValveEvent::Kind kind) {
  switch (kind) {
    case ValveEvent::Kind::MitralCloses:
      return "MC";
    case ValveEvent::Kind::AorticOpens:
      return "AO";
    case ValveEvent::Kind::AorticCloses:
      return "AC";
    case ValveEvent::Kind::MitralOpens:
      return "MO";
  }
  return "?";
}

std::vector<ValveEvent> valveEvents(const std::vector<CirculationSample>& samples) {
  validateCirculationSamples(samples, "valve events");
  std::vector<ValveEvent> events;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    const CirculationSample& before = samples[i - 1];
    const CirculationSample& after = samples[i];
    const auto add = [&](ValveEvent::Kind kind) { events.push_back({kind, before.time, i - 1}); };
    // Closures first: a valve that closes in the step the other opens still closed first (the
    // ventricle never connects atrium and aorta in a healthy beat).
    if (before.mitralOpen && !after.mitralOpen) add(ValveEvent::Kind::MitralCloses);
    if (before.aorticOpen && !after.aorticOpen) add(ValveEvent::Kind::AorticCloses);
    if (!before.aorticOpen && after.aorticOpen) add(ValveEvent::Kind::AorticOpens);
    if (!before.mitralOpen && after.mitralOpen) add(ValveEvent::Kind::MitralOpens);
  }
  return events;
}

std::vector<CirculationSample> lastCompleteBeat(const std::vector<CirculationSample>& samples,
                                                const std::vector<double>& beatStartTimes) {
  for (std::size_t k = 0; k < beatStartTimes.size(); ++k) {
    if (!std::isfinite(beatStartTimes[k]) || (k > 0 && beatStartTimes[k] <= beatStartTimes[k - 1])) {
      throw std::invalid_argument("last complete beat: beat start " + std::to_string(k) + " (" +
                                  std::to_string(beatStartTimes[k]) +
                                  " s) is not finite or not after the previous one");
    }
  }
  if (samples.empty()) return {};
  validateCirculationSamples(samples, "last complete beat");
  const double firstStep = samples.size() > 1 ? samples[1].time - samples[0].time : 0.0;
  for (std::size_t k = beatStartTimes.size(); k-- > 1;) {
    const double start = beatStartTimes[k - 1], end = beatStartTimes[k];
    if (samples.back().time < end) continue;
    // Recording began after this beat's first step: earlier beats are incomplete as well.
    if (samples.front().time > start + firstStep * (1.0 + 1e-9)) return {};
    std::vector<CirculationSample> beat;
    for (const CirculationSample& s : samples) {
      if (s.time > start && s.time <= end) beat.push_back(s);
    }
    return beat;
  }
  return {};
}

namespace {

std::string loopName(const PvLoopCurve& loop, std::size_t index) {
  return "pressure-volume loop " +
         (loop.label.empty() ? "#" + std::to_string(index) : "'" + loop.label + "'");
}

void validatePvInput(const std::vector<PvLoopCurve>& loops, const PressureVolumeRelations& r) {
  if (loops.empty()) throw std::invalid_argument("pressure-volume loop plot: no loops to draw");
  for (std::size_t i = 0; i < loops.size(); ++i)
    validateCirculationSamples(loops[i].samples, loopName(loops[i], i));
  const std::pair<const char*, double> fields[] = {{"endSystolicElastance", r.endSystolicElastance},
                                                   {"unstressedVolume", r.unstressedVolume},
                                                   {"diastolicScale", r.diastolicScale},
                                                   {"diastolicExponent", r.diastolicExponent}};
  for (const auto& [name, value] : fields) {
    if (!std::isfinite(value) || (value < 0 && std::string(name) != "unstressedVolume")) {
      throw std::invalid_argument(std::string("pressure-volume relations: ") + name + " (" +
                                  std::to_string(value) + ") must be finite and not negative");
    }
  }
}

// The end-diastolic and end-systolic samples: the last closure of the mitral / aortic valve
// (the corners of the loop), or the largest / smallest volume in a loop without them.
std::pair<std::size_t, std::size_t> endDiastoleAndSystole(const std::vector<CirculationSample>& samples) {
  const auto byVolume = [](const CirculationSample& a, const CirculationSample& b) {
    return a.lvVolume < b.lvVolume;
  };
  std::size_t ed =
      static_cast<std::size_t>(std::max_element(samples.begin(), samples.end(), byVolume) - samples.begin());
  std::size_t es =
      static_cast<std::size_t>(std::min_element(samples.begin(), samples.end(), byVolume) - samples.begin());
  for (const ValveEvent& e : valveEvents(samples)) {
    if (e.kind == ValveEvent::Kind::MitralCloses) ed = e.lastBefore;
    if (e.kind == ValveEvent::Kind::AorticCloses) es = e.lastBefore;
  }
  return {ed, es};
}

// Volumes from 0 (or below, for a negative V0 or volume) so V0 and the ESPVR's foot show, as in
// the textbook figure; pressures from 0 (makeRoomForLegend adds the legend's headroom).
void setPvRanges(viz::PlotSpec& spec, const std::vector<PvLoopCurve>& loops, double v0Ml) {
  double vMin = std::min(0.0, v0Ml), vMax = v0Ml, pMin = 0.0, pMax = 0.0;
  for (const PvLoopCurve& loop : loops) {
    for (const CirculationSample& s : loop.samples) {
      vMin = std::min(vMin, toMl(s.lvVolume));
      vMax = std::max(vMax, toMl(s.lvVolume));
      pMin = std::min(pMin, toMmHg(s.lvPressure));
      pMax = std::max(pMax, toMmHg(s.lvPressure));
    }
  }
  const double vSpan = std::max(vMax - vMin, 1.0), pSpan = std::max(pMax - pMin, 1.0);
  spec.xRange = std::pair{vMin < 0 ? vMin - 0.05 * vSpan : 0.0, vMax + 0.1 * vSpan};
  spec.yRange = std::pair{pMin < 0 ? pMin - 0.05 * pSpan : 0.0, pMax + 0.08 * pSpan};
}

// P = Ees (V - V0) from V0 to the right edge (the plot clips what rises above it).
viz::Series endSystolicRelation(const PressureVolumeRelations& r, double vRightMl) {
  viz::Series series = plotSeries("", kEndSystolicRelationColour);
  const double v0 = toMl(r.unstressedVolume);
  for (const double v : {v0, vRightMl}) {
    series.x.push_back(v);
    series.y.push_back(toMmHg(r.endSystolicElastance * (v - v0) * kCubicMetresPerMl));
  }
  return series;
}

// P = A (exp(B (V - V0)) - 1), sampled finely, ending at the first point above the plot (the
// exponential would overflow long before the right edge for a stiff ventricle).
viz::Series endDiastolicRelation(const PressureVolumeRelations& r, double vLeftMl, double vRightMl,
                                 double pTopMmHg) {
  viz::Series series = plotSeries("", kEndDiastolicRelationColour);
  const double v0 = toMl(r.unstressedVolume), from = std::max(v0, vLeftMl);
  constexpr int kPoints = 400;
  for (int i = 0; i <= kPoints; ++i) {
    const double v = from + (vRightMl - from) * i / kPoints;
    const double p =
        toMmHg(r.diastolicScale * std::expm1(r.diastolicExponent * (v - v0) * kCubicMetresPerMl));
    series.x.push_back(v);
    series.y.push_back(p);
    if (p > pTopMmHg) break;
  }
  return series;
}

viz::Series loopLine(const PvLoopCurve& loop, viz::Rgb colour) {
  viz::Series line = plotSeries(loop.label, colour);
  for (const CirculationSample& s : loop.samples) {
    line.x.push_back(toMl(s.lvVolume));
    line.y.push_back(toMmHg(s.lvPressure));
  }
  line.x.push_back(line.x.front());  // closed
  line.y.push_back(line.y.front());
  return line;
}

// Markers at end-diastole, then end-systole.
viz::Series cornerMarkers(const PvLoopCurve& loop, viz::Rgb colour) {
  viz::Series corners = plotSeries("", colour, viz::Series::Style::Markers);
  const auto [ed, es] = endDiastoleAndSystole(loop.samples);
  for (const std::size_t k : {ed, es}) {
    corners.x.push_back(toMl(loop.samples[k].lvVolume));
    corners.y.push_back(toMmHg(loop.samples[k].lvPressure));
  }
  return corners;
}

}  // namespace

viz::PlotSpec pressureVolumeLoopSpec(const std::vector<PvLoopCurve>& loops,
                                     const PressureVolumeRelations& relations, const std::string& title) {
  validatePvInput(loops, relations);
  viz::PlotSpec spec;
  spec.title = title;
  spec.xLabel = "LV volume (mL)";
  spec.yLabel = "LV pressure (mmHg)";
  spec.width = 900;
  spec.height = 750;
  spec.textScale = 2;  // as the Wiggers diagram's, so the two figures read alike side by side
  setPvRanges(spec, loops, toMl(relations.unstressedVolume));
  for (std::size_t i = 0; i < loops.size(); ++i)
    spec.series.push_back(loopLine(loops[i], viz::paletteColour(i)));
  // The relations' legend entries are point-less series after the loops; their lines go first
  // (below) so the loops, whose filling limb runs along the EDPVR, draw over them.
  const bool endSystolic = relations.endSystolicElastance > 0;
  const bool endDiastolic = relations.diastolicScale > 0 && relations.diastolicExponent > 0;
  if (endSystolic) spec.series.push_back(plotSeries("ESPVR", kEndSystolicRelationColour));
  if (endDiastolic) spec.series.push_back(plotSeries("EDPVR", kEndDiastolicRelationColour));
  makeRoomForLegend(spec, 0, loops.size());
  const auto [vLeft, vRight] = *spec.xRange;
  if (endDiastolic) {
    spec.series.insert(spec.series.begin(),
                       endDiastolicRelation(relations, vLeft, vRight, spec.yRange->second));
  }
  if (endSystolic) spec.series.insert(spec.series.begin(), endSystolicRelation(relations, vRight));
  for (std::size_t i = 0; i < loops.size(); ++i)
    spec.series.push_back(cornerMarkers(loops[i], viz::paletteColour(i)));
  return spec;
}

viz::Image pressureVolumeLoopImage(const std::vector<PvLoopCurve>& loops,
                                   const PressureVolumeRelations& relations, const std::string& title) {
  const viz::PlotSpec spec = pressureVolumeLoopSpec(loops, relations, title);
  const viz::PlotFrame frame(spec);
  viz::Image image = viz::renderPlot(spec);
  const int s = frame.textScale(), gap = static_cast<int>(frame.markerRadius()) + 3 * s;
  image.setClip(frame.area());
  // The corner markers are the last series, one per loop: end-diastole then end-systole.
  for (std::size_t i = spec.series.size() - loops.size(); i < spec.series.size(); ++i) {
    const viz::Series& corners = spec.series[i];
    const viz::PlotFrame::Point ed = frame.toPixel(corners.x[0], corners.y[0]);
    const viz::PlotFrame::Point es = frame.toPixel(corners.x[1], corners.y[1]);
    // ED sits at the loop's lower right, ES at its upper left: label them outside the loop.
    image.drawText(static_cast<int>(ed.x) + gap, static_cast<int>(ed.y) - viz::Image::capHeight(s) - gap,
                   "ED", s, viz::kBlack);
    image.drawText(static_cast<int>(es.x) - gap - viz::Image::textWidth("ES", s),
                   static_cast<int>(es.y) - viz::Image::capHeight(s) - gap, "ES", s, viz::kBlack);
  }
  image.clearClip();
  return image;
}

void writePvLoopPng(const std::string& path, const std::vector<PvLoopCurve>& loops,
                    const PressureVolumeRelations& relations, const std::string& title) {
  pressureVolumeLoopImage(loops, relations, title).savePng(path);
}

}  // namespace hs::io
