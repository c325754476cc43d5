// The circulation's figures: the PV loop and its relations land on the pixels PlotFrame gives,
// the Wiggers diagram's valve lines stand at the event times in every panel, the beat picker
// picks the last whole beat, the PNGs round-trip, bad input is named.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/output/circulation_plots.h"
#include "io/output/circulation_plots_internal.h"
#include "thrown_message.h"

namespace hs::io {
namespace {

using cardiac::CirculationSample;
using cardiac::PressureVolumeRelations;

constexpr double kPa = 133.322;  // per mmHg
constexpr double kMl = 1e-6;     // m^3
constexpr double kPi = std::numbers::pi;
// Valve events of the synthetic beat (ms): the last sample in the old state.
constexpr double kMitralCloses = 20, kAorticOpens = 70, kAorticCloses = 370, kMitralOpens = 450,
                 kBeatMs = 800;

double bump(double t, double from, double length) { return std::sin(kPi * (t - from) / length); }
double rise(double t, double from, double length) {
  return 0.5 * (1.0 - std::cos(kPi * (t - from) / length));
}

// One analytic beat from the ventricle's activation, one sample per ms (t in ms): isovolumic
// contraction 10 -> 80 mmHg, ejection of 70 mL (120 -> 50 mL) with a 130 mmHg peak, isovolumic
// relaxation to 4 mmHg, early (E, 45 mL) and atrial (A, 25 mL) filling back to 120 mL; the
// aorta follows the ventricle while the aortic valve is open and decays 100 -> 80 mmHg after.
CirculationSample syntheticSample(double t) {
  const double tau = 500.0 / std::log(1.25);
  CirculationSample s;
  s.time = t * 1e-3;
  s.mitralOpen = t <= kMitralCloses || t > kMitralOpens;
  s.aorticOpen = t > kAorticOpens && t <= kAorticCloses;
  // The ventricle contracts from the mitral valve's closure until it has relaxed (the phase
  // band reads the isovolumic contraction from both valves shut while it contracts).
  s.ventricularActivation = t > kMitralCloses && t <= 450 ? 1.0 : 0.0;
  double lv = 8 + 2 * t / kMitralCloses, volume = 120, aortic = 100 * std::exp(-(t + kBeatMs - 370) / tau);
  double mitralFlow = 0, aorticFlow = 0;
  if (t > 20 && t <= 70) lv = 10 + 70 * rise(t, 20, 50);
  if (s.aorticOpen) {
    lv = 80 + 40 * bump(t, 70, 300) + 20 * (t - 70) / 300;
    aortic = lv - 3 * bump(t, 70, 300);
    volume = 120 - 70 * rise(t, 70, 300);
    aorticFlow = 70 * kPi / (2 * 0.3) * bump(t, 70, 300);
  }
  if (t > 370) {
    lv = t <= 450 ? 4 + 96 * (1 - rise(t, 370, 80)) : 4 + 4 * (t - 450) / 350;
    aortic = 100 * std::exp(-(t - 370) / tau) - 5 * std::exp(-std::pow((t - 376) / 6, 2));
    volume = t <= 450   ? 50
             : t <= 650 ? 50 + 45 * rise(t, 450, 200)
             : t <= 680 ? 95
                        : 95 + 25 * rise(t, 680, 120);
    if (t > 450 && t <= 650) mitralFlow = 45 * kPi / (2 * 0.2) * bump(t, 450, 200);
    if (t > 680) mitralFlow = 25 * kPi / (2 * 0.12) * bump(t, 680, 120);
  }
  const double la =
      6 + 5 * std::exp(-std::pow((t - 450) / 60, 2)) + 4 * std::exp(-std::pow((t - 740) / 40, 2));
  s.lvPressure = lv * kPa;
  s.aorticPressure = aortic * kPa;
  s.laPressure = la * kPa;
  s.lvVolume = volume * kMl;
  s.mitralFlow = mitralFlow * kMl;
  s.aorticFlow = aorticFlow * kMl;
  return s;
}

std::vector<CirculationSample> syntheticBeat() {
  std::vector<CirculationSample> beat;
  for (int i = 1; i <= static_cast<int>(kBeatMs); ++i) beat.push_back(syntheticSample(i));
  return beat;
}

// V0 = 10 mL; the ESPVR through the end-systolic corner (50 mL, 100 mmHg); the EDPVR through
// (120 mL, 10 mmHg) with A = 0.5 mmHg.
PressureVolumeRelations syntheticRelations() {
  PressureVolumeRelations r;
  r.unstressedVolume = 10 * kMl;
  r.endSystolicElastance = 2.5 * kPa / kMl;
  r.diastolicScale = 0.5 * kPa;
  r.diastolicExponent = std::log(21.0) / 110.0 / kMl;
  return r;
}

struct Pixel {
  int x, y;
};
Pixel pixelOf(const viz::PlotFrame& frame, double x, double y) {
  const viz::PlotFrame::Point p = frame.toPixel(x, y);
  return {static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y))};
}

int countColour(const viz::Image& image, const viz::Rect& r, viz::Rgb colour) {
  int n = 0;
  for (int y = std::max(0, r.y); y < std::min(image.height(), r.y + r.height); ++y) {
    for (int x = std::max(0, r.x); x < std::min(image.width(), r.x + r.width); ++x)
      n += image.at(x, y) == colour;
  }
  return n;
}

bool colourNear(const viz::Image& image, Pixel p, viz::Rgb colour) {
  return countColour(image, {p.x - 1, p.y - 1, 3, 3}, colour) > 0;
}

// The points of the labelled series that fall under the legend box.
int pointsUnderLegend(const viz::PlotSpec& spec) {
  const viz::PlotFrame frame(spec);
  int hidden = 0;
  for (const viz::Series& series : spec.series) {
    for (std::size_t i = 0; !series.label.empty() && i < series.x.size(); ++i) {
      const Pixel p = pixelOf(frame, series.x[i], series.y[i]);
      hidden += frame.legend()->contains(p.x, p.y);
    }
  }
  return hidden;
}

std::string tempPath(const std::string& name) {
  return (std::filesystem::path(::testing::TempDir()) / name).string();
}

TEST(CirculationPlots, ValveEventsAreTheFlagTransitions) {
  const std::vector<ValveEvent> events = valveEvents(syntheticBeat());
  ASSERT_EQ(events.size(), 4u);
  const ValveEvent::Kind kinds[] = {ValveEvent::Kind::MitralCloses, ValveEvent::Kind::AorticOpens,
                                    ValveEvent::Kind::AorticCloses, ValveEvent::Kind::MitralOpens};
  const double times[] = {kMitralCloses, kAorticOpens, kAorticCloses, kMitralOpens};
  const std::string names[] = {"MC", "AO", "AC", "MO"};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(events[i].kind, kinds[i]) << i;
    EXPECT_NEAR(events[i].time, times[i] * 1e-3, 1e-12) << i;
    EXPECT_EQ(events[i].lastBefore, static_cast<std::size_t>(times[i]) - 1) << i;
    EXPECT_EQ(valveEventAbbreviation(events[i].kind), names[i]);
  }
}

TEST(CirculationPlots, LoopPassesThroughItsEndSystolicCornerInItsColour) {
  const std::vector<PvLoopCurve> loops{{"baseline", syntheticBeat()}};
  const viz::PlotSpec spec = pressureVolumeLoopSpec(loops, syntheticRelations(), "PV loop");
  const viz::PlotFrame frame(spec);
  const viz::Image image = pressureVolumeLoopImage(loops, syntheticRelations(), "PV loop");
  const viz::Rgb colour = viz::paletteColour(0);
  // End-systole: the aortic valve's closure, 50 mL at 100 mmHg.
  EXPECT_EQ(image.at(pixelOf(frame, 50.0, 100.0).x, pixelOf(frame, 50.0, 100.0).y), colour);
  EXPECT_EQ(image.at(pixelOf(frame, 120.0, 10.0).x, pixelOf(frame, 120.0, 10.0).y), colour);  // end-diastole
  // Unmarked points: mid-ejection and mid-filling (just above the EDPVR, which the loop covers).
  for (const std::size_t i : {219u, 549u}) {
    const CirculationSample& s = loops[0].samples[i];
    EXPECT_TRUE(colourNear(image, pixelOf(frame, s.lvVolume / kMl, s.lvPressure / kPa), colour)) << i;
  }
  // Inside the loop there is nothing.
  EXPECT_EQ(countColour(image, {pixelOf(frame, 85, 60).x - 5, pixelOf(frame, 85, 60).y - 5, 11, 11}, colour),
            0);
  ASSERT_TRUE(frame.legend());
  EXPECT_EQ(pointsUnderLegend(spec), 0);
  EXPECT_EQ(frame.xRange().first, 0.0);  // volumes from 0 so V0 shows

  // A loop whose samples do not return to the start is closed by a straight line, here across
  // the empty inside of the full loop.
  const std::vector<PvLoopCurve> open{{"open", {loops[0].samples.begin() + 219, loops[0].samples.end()}}};
  const viz::PlotFrame openFrame(pressureVolumeLoopSpec(open, syntheticRelations(), ""));
  const CirculationSample& first = open[0].samples.front();
  const double midV = 0.5 * (first.lvVolume / kMl + 120.0), midP = 0.5 * (first.lvPressure / kPa + 8.0);
  EXPECT_TRUE(colourNear(pressureVolumeLoopImage(open, syntheticRelations(), ""),
                         pixelOf(openFrame, midV, midP), colour));
}

TEST(CirculationPlots, RelationsPassThroughTheirPixels) {
  const std::vector<PvLoopCurve> loops{{"baseline", syntheticBeat()}};
  const viz::PlotFrame frame(pressureVolumeLoopSpec(loops, syntheticRelations(), ""));
  const viz::Image image = pressureVolumeLoopImage(loops, syntheticRelations(), "");
  // ESPVR: P = 2.5 mmHg/mL (V - 10 mL); EDPVR: 0.5 (21^((V - 10)/110) - 1) mmHg, right of the loop.
  EXPECT_TRUE(colourNear(image, pixelOf(frame, 30.0, 50.0), kEndSystolicRelationColour));
  EXPECT_TRUE(colourNear(image, pixelOf(frame, 10.5, 1.25), kEndSystolicRelationColour));
  EXPECT_FALSE(colourNear(image, pixelOf(frame, 30.0, 80.0), kEndSystolicRelationColour));
  const double v = 128.0, p = 0.5 * (std::pow(21.0, (v - 10) / 110) - 1);
  ASSERT_FALSE(frame.legend()->contains(pixelOf(frame, v, p).x, pixelOf(frame, v, p).y));
  EXPECT_TRUE(colourNear(image, pixelOf(frame, v, p), kEndDiastolicRelationColour));
  EXPECT_FALSE(colourNear(image, pixelOf(frame, v, p + 15.0), kEndDiastolicRelationColour));
}

TEST(CirculationPlots, CompareModeGivesEachLoopItsColourAndLegendEntry) {
  std::vector<CirculationSample> failing = syntheticBeat();
  for (CirculationSample& s : failing) {
    s.lvVolume += 40 * kMl;
    s.lvPressure *= 0.7;
  }
  const std::vector<PvLoopCurve> loops{{"baseline", syntheticBeat()}, {"heart failure", failing}};
  const viz::PlotSpec spec = pressureVolumeLoopSpec(loops, syntheticRelations(), "compare");
  std::vector<std::string> labels;
  for (const viz::Series& series : spec.series) {
    if (!series.label.empty()) labels.push_back(series.label);
  }
  EXPECT_EQ(labels, (std::vector<std::string>{"baseline", "heart failure", "ESPVR", "EDPVR"}));
  const viz::PlotFrame frame(spec);
  const viz::Image image = pressureVolumeLoopImage(loops, syntheticRelations(), "compare");
  for (const viz::Rgb colour : {viz::paletteColour(0), viz::paletteColour(1), kEndSystolicRelationColour})
    EXPECT_GT(countColour(image, *frame.legend(), colour), 4);
  EXPECT_NE(viz::paletteColour(0), viz::paletteColour(1));
  // The failing heart's end-systolic corner: 90 mL at 70 mmHg.
  EXPECT_EQ(image.at(pixelOf(frame, 90.0, 70.0).x, pixelOf(frame, 90.0, 70.0).y), viz::paletteColour(1));
}

TEST(CirculationPlots, ValveLinesStandAtTheEventTimesInEveryPanel) {
  const WiggersLayout layout = wiggersLayout(syntheticBeat(), "Wiggers");
  const viz::Image image = wiggersDiagramImage(syntheticBeat(), "Wiggers");
  ASSERT_EQ(layout.panels.size(), 4u) << "pressures, volume, flows, the ECG";
  EXPECT_EQ(layout.eventTimesMs,
            (std::vector<double>{kMitralCloses, kAorticOpens, kAorticCloses, kMitralOpens}));
  const viz::Rect first = viz::PlotFrame(layout.panels[0]).area();
  for (std::size_t p = 0; p < layout.panels.size(); ++p) {
    const viz::PlotFrame frame(layout.panels[p]);
    EXPECT_EQ(frame.area().x, first.x) << "panel " << p;  // one time axis
    EXPECT_EQ(frame.area().width, first.width) << "panel " << p;
    const viz::Rect area{frame.area().x, layout.panelTops[p] + frame.area().y, frame.area().width,
                         frame.area().height};
    for (const double t : layout.eventTimesMs) {
      const int column = pixelOf(frame, t, 0.0).x;
      EXPECT_GT(countColour(image, {column, area.y, 1, area.height}, kValveEventColour), area.height / 2)
          << "panel " << p << ", t = " << t << " ms";
      EXPECT_LT(countColour(image, {column + 8, area.y, 1, area.height}, kValveEventColour), area.height / 10)
          << "panel " << p << ", t = " << t << " ms";
    }
  }
  EXPECT_EQ(layout.panelTops.front() + first.y, layout.phaseBand.y + layout.phaseBand.height);
  EXPECT_EQ(layout.panelTops.back() + layout.panels.back().height, image.height());

  // Flows of thousands of mL/s need wider tick labels than the volume's: the axes still align.
  std::vector<CirculationSample> strong = syntheticBeat();
  for (CirculationSample& s : strong) s.aorticFlow *= 10;
  const WiggersLayout wide = wiggersLayout(strong, "");
  viz::PlotSpec volumeAlone = wide.panels[1];
  volumeAlone.minAreaLeft = 0;
  ASSERT_LT(viz::PlotFrame(volumeAlone).area().x, viz::PlotFrame(wide.panels[2]).area().x);
  EXPECT_EQ(viz::PlotFrame(wide.panels[1]).area().x, viz::PlotFrame(wide.panels[2]).area().x);
  EXPECT_EQ(viz::PlotFrame(wide.panels[0]).area().x, viz::PlotFrame(wide.panels[2]).area().x);
}

TEST(CirculationPlots, LegendGetsRoomAboveTheCurves) {
  // A flat line near the top of its range would run under a legend in either top corner.
  viz::PlotSpec spec;
  viz::Series line = plotSeries("flat", viz::paletteColour(0));
  line.x = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  line.y.assign(line.x.size(), 1.0);
  spec.series = {line};
  spec.yRange = std::pair{0.0, 1.08};
  spec.legendCorner = viz::LegendCorner::TopRight;
  ASSERT_GT(pointsUnderLegend(spec), 0);
  makeRoomForLegend(spec, 0, 1);
  EXPECT_EQ(pointsUnderLegend(spec), 0);
  EXPECT_GT(spec.yRange->second, 1.08);
  EXPECT_LT(spec.yRange->second, 3.0);                        // room for the legend, not a squashed plot
  EXPECT_EQ(spec.legendCorner, viz::LegendCorner::TopRight);  // the tie goes to the usual corner
}

TEST(CirculationPlots, PhasesAreNamedBetweenTheEventsAndTheIsovolumicOnesShaded) {
  const WiggersLayout layout = wiggersLayout(syntheticBeat(), "Wiggers");
  std::vector<std::string> names;
  for (const WiggersLayout::Phase& phase : layout.phases) {
    names.push_back(phase.name + (phase.labelled ? "" : " (unlabelled)") + " " +
                    std::to_string(phase.fromMs) + "-" + std::to_string(phase.toMs));
  }
  // Filling is cut in two by the beat's ends: named on its longer piece only.
  EXPECT_EQ(names, (std::vector<std::string>{
                       "filling (unlabelled) 0.000000-20.000000",
                       "isovolumic contraction 20.000000-70.000000", "ejection 70.000000-370.000000",
                       "isovolumic relaxation 370.000000-450.000000", "filling 450.000000-800.000000"}));
  EXPECT_TRUE(layout.phases[1].wrapped);   // 50 ms is narrower than "isovolumic contraction"
  EXPECT_FALSE(layout.phases[2].wrapped);  // "ejection" fits its 300 ms

  // The volume panel's background near its bottom: shaded during the isovolumic contraction,
  // white during ejection and filling.
  const viz::Image image = wiggersDiagramImage(syntheticBeat(), "Wiggers");
  const viz::PlotFrame frame(layout.panels[1]);
  const int row = layout.panelTops[1] + frame.area().y + frame.area().height - 3;
  const auto shaded = [&](double fromMs, double toMs) {
    const int from = pixelOf(frame, fromMs, 0).x, to = pixelOf(frame, toMs, 0).x;
    return countColour(image, {from, row, to - from, 1}, kIsovolumicShade);
  };
  EXPECT_GT(shaded(25, 65), 20);
  EXPECT_GT(shaded(380, 440), 40);
  EXPECT_EQ(shaded(100, 340), 0);
  EXPECT_EQ(shaded(460, 790), 0);
  for (const viz::PlotSpec& panel : layout.panels) EXPECT_EQ(pointsUnderLegend(panel), 0);
}

TEST(CirculationPlots, LastCompleteBeatIsTheLastWholeIntervalBetweenStarts) {
  // Exact binary times: a step of 2^-10 s, beats of 800 steps.
  const double dt = 1.0 / 1024, beat = 800 * dt;
  const auto steps = [&](int first, int last) {  // samples at the ends of steps first..last
    std::vector<CirculationSample> samples;
    for (int i = first; i <= last; ++i) {
      samples.push_back(syntheticSample(std::fmod(i, 800.0)));
      samples.back().time = i * dt;
    }
    return samples;
  };
  const std::vector<double> starts{0.0, beat, 2 * beat, 3 * beat};  // the third beat is unfinished
  const std::vector<CirculationSample> last = lastCompleteBeat(steps(1, 2100), starts);
  ASSERT_EQ(last.size(), 800u);
  EXPECT_EQ(last.front().time, beat + dt);
  EXPECT_EQ(last.back().time, 2 * beat);

  const std::vector<CirculationSample> first = lastCompleteBeat(steps(1, 1000), starts);
  ASSERT_EQ(first.size(), 800u);
  EXPECT_EQ(first.back().time, beat);
  EXPECT_TRUE(lastCompleteBeat(steps(1, 799), starts).empty());
  EXPECT_TRUE(lastCompleteBeat(steps(300, 1000), starts).empty());  // recording began inside beat 0
  EXPECT_TRUE(lastCompleteBeat({}, starts).empty());
  EXPECT_EQ(lastCompleteBeat(steps(0, 1000), starts).size(), 800u);  // a sample at t = 0 is no step of beat 0

  const std::string message = hs::testing::thrownMessage<std::invalid_argument>([&] {
    lastCompleteBeat(steps(1, 10), {0.0, 0.5, 0.4});
  });
  EXPECT_NE(message.find("beat start 2"), std::string::npos) << message;
}

TEST(CirculationPlots, PngsRoundTripAndNameAnUnwritablePath) {
  const std::vector<PvLoopCurve> loops{{"baseline", syntheticBeat()}};
  writePvLoopPng(tempPath("pv_loop.png"), loops, syntheticRelations(), "PV loop");
  writeWiggersPng(tempPath("wiggers.png"), syntheticBeat(), "Wiggers");
  const viz::Image pv = viz::Image::loadPng(tempPath("pv_loop.png"));
  const viz::Image wiggers = viz::Image::loadPng(tempPath("wiggers.png"));
  EXPECT_EQ(pv.pixels(), pressureVolumeLoopImage(loops, syntheticRelations(), "PV loop").pixels());
  EXPECT_EQ(wiggers.pixels(), wiggersDiagramImage(syntheticBeat(), "Wiggers").pixels());
  EXPECT_EQ(wiggers.width(), 1000);
  EXPECT_EQ(wiggers.height(), 1100);
  const std::string message = hs::testing::thrownMessage<std::runtime_error>(
      [&] { writeWiggersPng("/nonexistent-dir/wiggers.png", syntheticBeat(), ""); });
  EXPECT_NE(message.find("'/nonexistent-dir/wiggers.png'"), std::string::npos) << message;
}

TEST(CirculationPlots, BadInputThrowsOneLineNamingWhatIsWrong) {
  const auto expectMessage = [](const std::string& message, const std::vector<std::string>& parts) {
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    for (const std::string& part : parts) EXPECT_NE(message.find(part), std::string::npos) << message;
  };
  using hs::testing::thrownMessage;
  const PressureVolumeRelations relations = syntheticRelations();
  expectMessage(thrownMessage<std::invalid_argument>([&] { wiggersDiagramImage({}, ""); }), {"no samples"});
  expectMessage(thrownMessage<std::invalid_argument>([&] { pressureVolumeLoopImage({}, relations, ""); }),
                {"no loops"});
  std::vector<CirculationSample> beat = syntheticBeat();
  beat[7].lvPressure = std::numeric_limits<double>::quiet_NaN();
  expectMessage(thrownMessage<std::invalid_argument>([&] {
                  pressureVolumeLoopImage({{"baseline", beat}}, relations, "");
                }),
                {"'baseline'", "sample 7", "lvPressure"});
  expectMessage(thrownMessage<std::invalid_argument>([&] { wiggersLayout(beat, ""); }),
                {"sample 7", "lvPressure"});
  beat = syntheticBeat();
  beat[5].time = beat[4].time;
  expectMessage(thrownMessage<std::invalid_argument>([&] { wiggersDiagramImage(beat, ""); }),
                {"sample 5", "not after"});
  expectMessage(thrownMessage<std::invalid_argument>([&] { wiggersDiagramImage({beat[0]}, ""); }),
                {"two samples"});
  PressureVolumeRelations negative = relations;
  negative.endSystolicElastance = -1;
  expectMessage(thrownMessage<std::invalid_argument>([&] {
                  pressureVolumeLoopSpec({{"a", syntheticBeat()}}, negative, "");
                }),
                {"endSystolicElastance"});
}

}  // namespace
}  // namespace hs::io
