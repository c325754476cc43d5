// The Wiggers diagram (C. J. Wiggers, 1915, and after him every physiology textbook): pressures,
// volume and valve flows of one beat on a shared time axis, the valve events as vertical lines,
// the isovolumic phases shaded and every phase named along the top.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "io/output/circulation_plots.h"
#include "io/output/circulation_plots_internal.h"
#include "cardiac/circulation/heart_phase.h"

namespace hs::io {
namespace {

using cardiac::CirculationSample;

// One font size for every panel: the panels are short, so the automatic (height-based) size
// would be smaller than a lecture slide needs.
constexpr int kTextScale = 2;
constexpr int kWidth = 1000, kHeight = 1100;
// Share of the panels' height: pressures, volume, flows, the ECG.
constexpr std::array<double, 4> kPanelShares{0.33, 0.24, 0.27, 0.16};
// Pressures and flows keep their zero line in view; the volume zooms in on its swing.
constexpr std::array<bool, 4> kFromZero{true, false, true, true};
constexpr int kMaxTiers = 2;

int pad() { return 6 * kTextScale; }
int titleHeight() { return 3 * pad() + 10 * (kTextScale + 1); }
int eventRowHeight() { return viz::Image::capHeight(kTextScale) + pad(); }
int tierHeight() { return 2 * viz::Image::lineHeight(kTextScale); }
int phaseBandHeight(int tiers) { return tiers * tierHeight() + eventRowHeight(); }

// The phases as runs of the samples' phases, each read from the valves by the rule every front
// end uses (cardiac/circulation/heart_phase.h): the band, the pump panel and metrics.csv agree
// step by step. A beat starts at the ventricle's onset, after filling; sample k covers
// [timeMs[k-1], timeMs[k]] (the first from 0).
std::vector<WiggersLayout::Phase> namedPhases(const std::vector<CirculationSample>& beat,
                                              const std::vector<double>& timeMs) {
  std::vector<WiggersLayout::Phase> result;
  cardiac::HeartPhase phase = cardiac::HeartPhase::Filling;
  for (std::size_t k = 0; k < beat.size(); ++k) {
    const CirculationSample& s = beat[k];
    phase = cardiac::heartPhaseAfter(phase, {true, s.mitralOpen, s.aorticOpen, s.ventricularActivation > 0});
    const double from = k == 0 ? 0.0 : timeMs[k - 1];
    const std::string name = cardiac::heartPhaseName(phase);
    if (result.empty() || result.back().name != name)
      result.push_back({name, from, timeMs[k]});
    else
      result.back().toMs = timeMs[k];
  }
  if (result.size() > 2 && result.front().name == result.back().name) {
    const bool frontShorter =
        result.front().toMs - result.front().fromMs < result.back().toMs - result.back().fromMs;
    (frontShorter ? result.front() : result.back()).labelled = false;
  }
  std::erase_if(result, [](const WiggersLayout::Phase& p) { return p.toMs <= p.fromMs; });
  return result;
}

std::string phaseText(const WiggersLayout::Phase& phase) {
  std::string text = phase.name;
  if (phase.wrapped) text[text.find(' ')] = '\n';
  return text;
}

// Columns [left, right) of a phase's name: centred on its interval, kept inside the plot area.
std::pair<int, int> phaseLabelSpan(const viz::PlotFrame& frame, const WiggersLayout::Phase& phase) {
  const viz::Rect& area = frame.area();
  const int width = viz::Image::textWidth(phaseText(phase), kTextScale);
  const double from = frame.toPixel(phase.fromMs, 0.0).x, to = frame.toPixel(phase.toMs, 0.0).x;
  const int left = std::clamp(static_cast<int>((from + to - width) / 2), area.x, area.x + area.width - width);
  return {left, left + width};
}

// Each name on one line if it fits its interval, else on two; in the lowest tier where it keeps
// a pad from the names already placed (short phases of a slow beat crowd their neighbours).
void placePhaseNames(WiggersLayout& layout) {
  const viz::PlotFrame frame(layout.panels.front());
  std::array<std::vector<std::pair<int, int>>, kMaxTiers> taken;
  for (WiggersLayout::Phase& phase : layout.phases) {
    if (!phase.labelled) continue;
    const double width = frame.toPixel(phase.toMs, 0.0).x - frame.toPixel(phase.fromMs, 0.0).x;
    phase.wrapped =
        phase.name.find(' ') != std::string::npos && viz::Image::textWidth(phase.name, kTextScale) > width;
    const std::pair<int, int> span = phaseLabelSpan(frame, phase);
    const auto overlaps = [&](const std::pair<int, int>& other) {
      return span.first < other.second + pad() && other.first < span.second + pad();
    };
    phase.tier = 0;
    while (phase.tier + 1 < kMaxTiers && std::ranges::any_of(taken[phase.tier], overlaps)) ++phase.tier;
    taken[phase.tier].push_back(span);
  }
}

// The y range: the curves' extent with a margin, raised so the legend hides none of them.
void fitYRange(viz::PlotSpec& panel, bool fromZero) {
  double lo = fromZero ? 0.0 : panel.series.front().y.front(), hi = lo;
  for (const viz::Series& curve : panel.series) {
    lo = std::min(lo, std::ranges::min(curve.y));
    hi = std::max(hi, std::ranges::max(curve.y));
  }
  const double span = std::max(hi - lo, 1.0);
  panel.yRange = std::pair{fromZero && lo == 0.0 ? 0.0 : lo - 0.08 * span, hi + 0.08 * span};
  makeRoomForLegend(panel, 0, panel.series.size());
}

// Heights and tops under a band of `tiers` rows of phase names; one left edge for all panels.
void arrangePanels(WiggersLayout& layout, int tiers) {
  layout.phaseBand = {0, titleHeight(), layout.width, phaseBandHeight(tiers)};
  // Panel 0's top margin (no title: 2 pads) lies under the band, so the band meets its plot area.
  const int firstTop = layout.phaseBand.y + layout.phaseBand.height - 2 * pad();
  const int panelsHeight = layout.height - firstTop;
  int top = firstTop, areaLeft = 0;
  layout.panelTops.clear();
  for (std::size_t i = 0; i < layout.panels.size(); ++i) {
    viz::PlotSpec& panel = layout.panels[i];
    const bool last = i + 1 == layout.panels.size();
    panel.height = last ? layout.height - top : static_cast<int>(kPanelShares[i] * panelsHeight);
    fitYRange(panel, kFromZero[i]);
    layout.panelTops.push_back(top);
    top += panel.height;
    areaLeft = std::max(areaLeft, viz::PlotFrame(panel).area().x);
  }
  for (viz::PlotSpec& panel : layout.panels) panel.minAreaLeft = areaLeft;
}

// One panel: the curves against time in ms.
viz::PlotSpec panelSpec(std::string yLabel, std::vector<viz::Series> curves,
                        const std::vector<double>& timeMs) {
  viz::PlotSpec spec;
  spec.yLabel = std::move(yLabel);
  spec.width = kWidth;
  spec.textScale = kTextScale;
  spec.xRange = std::pair{0.0, timeMs.back()};
  for (viz::Series& curve : curves) {
    curve.x = timeMs;
    spec.series.push_back(std::move(curve));
  }
  return spec;
}

// The four panels' curves, converted to mmHg, mL, mL/s and mV.
std::array<std::vector<viz::Series>, 4> panelCurves(const std::vector<CirculationSample>& beat) {
  viz::Series aorta = plotSeries("aorta", viz::paletteColour(1));
  viz::Series ventricle = plotSeries("left ventricle", viz::paletteColour(0));
  viz::Series atrium = plotSeries("left atrium", viz::paletteColour(2));
  viz::Series volume = plotSeries("", viz::paletteColour(0));
  viz::Series mitral = plotSeries("mitral", viz::paletteColour(2));
  viz::Series aortic = plotSeries("aortic", viz::paletteColour(1));
  viz::Series ecg = plotSeries("", viz::kBlack);
  for (const CirculationSample& s : beat) {
    ecg.y.push_back(s.ecg);
    aorta.y.push_back(toMmHg(s.aorticPressure));
    ventricle.y.push_back(toMmHg(s.lvPressure));
    atrium.y.push_back(toMmHg(s.laPressure));
    volume.y.push_back(toMl(s.lvVolume));
    mitral.y.push_back(toMl(s.mitralFlow));
    aortic.y.push_back(toMl(s.aorticFlow));
  }
  return {std::vector{aorta, ventricle, atrium}, std::vector{volume}, std::vector{mitral, aortic}, std::vector{ecg}};
}

void validateBeat(const std::vector<CirculationSample>& beat) {
  validateCirculationSamples(beat, "Wiggers diagram");
  if (beat.size() < 2)
    throw std::invalid_argument("Wiggers diagram: a beat needs at least two samples, got 1");
  for (std::size_t i = 1; i < beat.size(); ++i) {
    if (beat[i].time <= beat[i - 1].time) {
      throw std::invalid_argument("Wiggers diagram: sample " + std::to_string(i) + " (t = " +
                                  std::to_string(beat[i].time) + " s) is not after the previous sample");
    }
  }
}

// Paints the pixels of rect (clipped to the image) that show background only: white, and for
// lines also the light neutral greys of the grid and the shading. The curves, the text and the
// legend (skipped) stay on top, as if these had been drawn first; drawn as series instead they
// would count as data the legend must not hide and push it onto a curve.
void paintBehind(viz::Image& image, const viz::Rect& rect, viz::Rgb colour, bool overGreys,
                 const std::optional<viz::Rect>& legend) {
  for (int y = std::max(rect.y, 0); y < std::min(rect.y + rect.height, image.height()); ++y) {
    for (int x = std::max(rect.x, 0); x < std::min(rect.x + rect.width, image.width()); ++x) {
      const viz::Rgb old = image.at(x, y);
      const bool background =
          old == viz::kWhite || (overGreys && old.r == old.g && old.g == old.b && old.r >= 200);
      if (background && !(legend && legend->contains(x, y))) image.set(x, y, colour);
    }
  }
}

// The isovolumic phases shaded (both valves closed: the volume stays flat) and the valve event
// lines, 2 px wide, through panel i's plot area.
void drawUnderCurves(viz::Image& image, const WiggersLayout& layout, std::size_t i) {
  const viz::PlotFrame frame(layout.panels[i]);
  const int top = layout.panelTops[i];
  const viz::Rect area{frame.area().x, top + frame.area().y, frame.area().width, frame.area().height};
  std::optional<viz::Rect> legend = frame.legend();
  if (legend) legend->y += top;
  const auto column = [&](double ms) { return static_cast<int>(std::lround(frame.toPixel(ms, 0.0).x)); };
  for (const WiggersLayout::Phase& phase : layout.phases) {
    if (phase.name.starts_with("isovolumic")) {
      const int from = column(phase.fromMs), to = column(phase.toMs);
      paintBehind(image, {from, area.y, to - from, area.height}, kIsovolumicShade, false, legend);
    }
  }
  for (const double t : layout.eventTimesMs) {
    paintBehind(image, {column(t) - 1, area.y, 2, area.height}, kValveEventColour, true, legend);
  }
}

// Valve event labels along the band's bottom with a stub of their line down to the first
// panel; above them the phase names in their tiers.
void drawPhaseBand(viz::Image& image, const WiggersLayout& layout) {
  const viz::PlotFrame frame(layout.panels.front());
  const int s = kTextScale, bandBottom = layout.phaseBand.y + layout.phaseBand.height;
  const int rowTop = bandBottom - eventRowHeight();
  for (std::size_t i = 0; i < layout.events.size(); ++i) {
    const char* label = valveEventAbbreviation(layout.events[i].kind);
    const double x = frame.toPixel(layout.eventTimesMs[i], 0.0).x;
    image.drawText(static_cast<int>(x) - viz::Image::textWidth(label, s) / 2, rowTop, label, s, viz::kBlack);
    image.drawLine(x, rowTop + viz::Image::capHeight(s) + 2, x, bandBottom, kValveEventColour,
                   frame.lineThickness());
  }
  for (const WiggersLayout::Phase& phase : layout.phases) {
    if (!phase.labelled) continue;
    const int bottom = rowTop - pad() / 2 - phase.tier * tierHeight();
    const int lines = phase.wrapped ? 2 : 1;
    image.drawText(phaseLabelSpan(frame, phase).first,
                   bottom - (lines - 1) * viz::Image::lineHeight(s) - viz::Image::capHeight(s),
                   phaseText(phase), s, viz::kBlack);
  }
}

// The heart sounds on the ECG panel: S1 where the isovolumic contraction begins (the mitral
// valve closes), S2 where the isovolumic relaxation begins (the aortic valve closes), as
// metrics.csv's heart_sound column has them (cardiac::heartSoundAt).
void drawHeartSounds(viz::Image& image, const WiggersLayout& layout) {
  const std::size_t ecg = layout.panels.size() - 1;
  const viz::PlotFrame frame(layout.panels[ecg]);
  const int s = kTextScale, top = layout.panelTops[ecg] + frame.area().y + pad() / 2;
  for (const WiggersLayout::Phase& phase : layout.phases) {
    const char* sound = phase.name == cardiac::heartPhaseName(cardiac::HeartPhase::IsovolumicContraction) ? "S1"
                        : phase.name == cardiac::heartPhaseName(cardiac::HeartPhase::IsovolumicRelaxation) ? "S2"
                                                                                                             : nullptr;
    if (!sound) continue;
    const int x = static_cast<int>(std::lround(frame.toPixel(phase.fromMs, 0.0).x));
    image.drawText(x + pad() / 2, top, sound, s, viz::Rgb{150, 70, 20});
  }
}

}  // namespace

WiggersLayout wiggersLayout(const std::vector<CirculationSample>& beat, const std::string& title) {
  validateBeat(beat);
  WiggersLayout layout;
  layout.title = title;
  layout.width = kWidth;
  layout.height = kHeight;
  layout.beatStart = beat[0].time - (beat[1].time - beat[0].time);
  layout.events = valveEvents(beat);
  for (const ValveEvent& e : layout.events) layout.eventTimesMs.push_back((e.time - layout.beatStart) * 1e3);
  std::vector<double> timeMs;
  for (const CirculationSample& s : beat) timeMs.push_back((s.time - layout.beatStart) * 1e3);

  std::array<std::vector<viz::Series>, 4> curves = panelCurves(beat);
  layout.panels = {panelSpec("Pressure (mmHg)", std::move(curves[0]), timeMs),
                   panelSpec("LV volume (mL)", std::move(curves[1]), timeMs),
                   panelSpec("Flow (mL/s)", std::move(curves[2]), timeMs),
                   panelSpec("ECG (mV)", std::move(curves[3]), timeMs)};
  layout.panels.back().xLabel = "Time from the beat's start (ms)";
  layout.phases = namedPhases(beat, timeMs);
  // The names' tiers depend on the plot area's columns, the band's height on the tiers used:
  // place them under the tallest band, then shrink it (the left edge only moves right, by at
  // most a few pixels, which the pad between names absorbs).
  arrangePanels(layout, kMaxTiers);
  placePhaseNames(layout);
  int tiers = 1;
  for (const WiggersLayout::Phase& phase : layout.phases) tiers = std::max(tiers, phase.tier + 1);
  arrangePanels(layout, tiers);
  return layout;
}

viz::Image wiggersDiagramImage(const std::vector<CirculationSample>& beat, const std::string& title) {
  const WiggersLayout layout = wiggersLayout(beat, title);
  viz::Image image(layout.width, layout.height, viz::kWhite);
  for (std::size_t i = 0; i < layout.panels.size(); ++i) {
    image.blit(viz::renderPlot(layout.panels[i]), 0, layout.panelTops[i]);
    drawUnderCurves(image, layout, i);
  }
  const int titleScale = kTextScale + 1;
  image.drawText((layout.width - viz::Image::textWidth(title, titleScale)) / 2, 2 * pad(), title, titleScale,
                 viz::kBlack);
  drawPhaseBand(image, layout);
  drawHeartSounds(image, layout);
  return image;
}

void writeWiggersPng(const std::string& path, const std::vector<CirculationSample>& beat,
                     const std::string& title) {
  wiggersDiagramImage(beat, title).savePng(path);
}

}  // namespace hs::io
