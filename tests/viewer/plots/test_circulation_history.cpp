// The circulation panel's arithmetic: the history copies only what is new from the recorder and
// keeps whole beats; the beats are split where the recorder says they start; the valve events
// are the first and last of each valve's runs, so flickering flags add none; the phases lie
// between the events; the relations and the loop's axes are those of circulation_trace.h.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "cardiac/circulation/clinical_units.h"
#include "viewer/plots/circulation_history.h"

namespace hs::viewer {
namespace {

using cardiac::CirculationSample;
constexpr double kDt = 0.001;

// Samples of steps first..last-1 (step n ends at (n + 1) dt, as HeartSimulation times them).
std::vector<CirculationSample> steps(int first, int last) {
  std::vector<CirculationSample> samples;
  for (int n = first; n < last; ++n) {
    CirculationSample s;
    s.time = double(n + 1) * kDt;
    s.lvVolume = (100 + n % 800) * cardiac::kCubicMetresPerMl;
    samples.push_back(s);
  }
  return samples;
}

// One beat of 830 steps from `start`: mitral open, then shut (IVC), aortic open (ejection),
// both shut (IVR), mitral open (filling) with a few steps of no flow in diastasis.
std::vector<CirculationSample> textbookBeat(double start) {
  std::vector<CirculationSample> beat;
  for (int i = 0; i < 830; ++i) {
    CirculationSample s;
    s.time = start + double(i + 1) * kDt;
    s.mitralOpen = i < 20 || (i >= 380 && !(i >= 600 && i < 610));
    s.aorticOpen = i >= 60 && i < 300;
    beat.push_back(s);
  }
  return beat;
}

TEST(CirculationHistory, CopiesOnlyWhatIsNewAndKeepsWholeBeats) {
  CirculationHistory h;
  std::vector<CirculationSample> recorder = steps(0, 500);
  std::vector<double> starts = {0.0};
  h.update(recorder, starts);
  EXPECT_EQ(h.samples().size(), 500u);
  for (int beat = 1; beat <= 6; ++beat) {
    const std::vector<CirculationSample> more = steps(int(recorder.size()), beat * 800 + 300);
    recorder.insert(recorder.end(), more.begin(), more.end());
    starts.push_back(beat * 800 * kDt);
    h.update(recorder, starts);
    h.update(recorder, starts);  // nothing new: nothing added
  }
  ASSERT_EQ(h.beatStarts().size(), CirculationHistory::kKeptBeats);
  EXPECT_DOUBLE_EQ(h.beatStarts().front(), 3 * 800 * kDt);
  // From the first step of the oldest kept beat to the newest, once each, in order.
  EXPECT_DOUBLE_EQ(h.samples().front().time, (3 * 800 + 1) * kDt);
  EXPECT_DOUBLE_EQ(h.samples().back().time, recorder.back().time);
  EXPECT_EQ(h.samples().size(), std::size_t(6 * 800 + 300 - 3 * 800));
  for (std::size_t i = 1; i < h.samples().size(); ++i)
    ASSERT_LT(h.samples()[i - 1].time, h.samples()[i].time);
}

TEST(CirculationHistory, ARestartedRecorderStartsItOver) {
  CirculationHistory h;
  h.update(steps(0, 2000), std::vector<double>{0.0, 0.8, 1.6});
  h.update(steps(0, 100), std::vector<double>{0.0});
  EXPECT_EQ(h.samples().size(), 100u);
  EXPECT_EQ(h.beatStarts().size(), 1u);
}

TEST(CirculationHistory, BeatsSplitAtTheRecordersStarts) {
  const std::vector<CirculationSample> samples = steps(0, 3000);
  const std::vector<double> starts = {0.0, 0.8, 1.6, 2.4};
  const std::vector<BeatSpan> spans = beatSpans(samples, starts);
  ASSERT_EQ(spans.size(), 4u);
  EXPECT_EQ(spans[0].begin, 0u);
  EXPECT_EQ(spans[0].end, 800u);  // the step starting at 0.8 s is the next beat's first
  EXPECT_EQ(spans[1].begin, 800u);
  EXPECT_TRUE(spans[2].complete);
  EXPECT_FALSE(spans[3].complete);
  EXPECT_EQ(spans[3].end, 3000u);
  const std::optional<BeatSpan> last = lastCompleteBeat(samples, starts);
  ASSERT_TRUE(last);
  EXPECT_DOUBLE_EQ(last->start, 1.6);
  EXPECT_EQ(last->size(), 800u);
}

TEST(CirculationHistory, ABeatWhoseStartWasDroppedIsNotWhole) {
  const std::vector<CirculationSample> samples = steps(1000, 3000);  // from t = 1.0 s
  const std::vector<BeatSpan> spans = beatSpans(samples, std::vector<double>{0.8, 1.6, 2.4});
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_DOUBLE_EQ(spans[0].start, 1.6);
  EXPECT_FALSE(lastCompleteBeat(samples, std::vector<double>{0.8, 1.6}).has_value());
}

TEST(CirculationHistory, ValveEventsAreTheEdgesOfEachValvesRuns) {
  const double start = 2.0;
  const std::vector<CirculationSample> beat = textbookBeat(start);
  const ValveEvents e = valveEvents(beat, start);
  ASSERT_TRUE(e.mitralClose && e.aorticOpen && e.aorticClose && e.mitralOpen);
  EXPECT_NEAR(*e.mitralClose, start + 0.020, 1e-12);  // the end of the last mitral step
  EXPECT_NEAR(*e.aorticOpen, start + 0.060, 1e-12);   // the start of the first aortic step
  EXPECT_NEAR(*e.aorticClose, start + 0.300, 1e-12);
  EXPECT_NEAR(*e.mitralOpen, start + 0.380, 1e-12);  // the diastasis flicker adds nothing

  const std::vector<CyclePhase> phases = cyclePhases(e, beat.back().time);
  ASSERT_EQ(phases.size(), 4u);
  EXPECT_EQ(phases[0].kind, CyclePhaseKind::IsovolumicContraction);
  EXPECT_NEAR(phases[0].to - phases[0].from, 0.040, 1e-12);
  EXPECT_EQ(phases[1].kind, CyclePhaseKind::Ejection);
  EXPECT_EQ(phases[2].kind, CyclePhaseKind::IsovolumicRelaxation);
  EXPECT_NEAR(phases[2].to - phases[2].from, 0.080, 1e-12);
  EXPECT_EQ(phases[3].kind, CyclePhaseKind::Filling);
  EXPECT_DOUBLE_EQ(phases[3].to, beat.back().time);
  for (std::size_t i = 1; i < phases.size(); ++i) EXPECT_DOUBLE_EQ(phases[i].from, phases[i - 1].to);
}

TEST(CirculationHistory, ValveEventsWithoutAClearCycleNameOnlyWhatHappened) {
  std::vector<CirculationSample> beat = textbookBeat(0);
  // A mitral valve already shut when the beat starts closed at the start.
  for (int i = 0; i < 20; ++i) beat[std::size_t(i)].mitralOpen = false;
  EXPECT_DOUBLE_EQ(*valveEvents(beat, 0).mitralClose, 0.0);
  // Still ejecting when the next beat begins: no closure, no filling.
  for (CirculationSample& s : beat) s.aorticOpen = s.time > 0.1;
  ValveEvents e = valveEvents(beat, 0);
  EXPECT_TRUE(e.aorticOpen);
  EXPECT_FALSE(e.aorticClose);
  EXPECT_FALSE(e.mitralOpen);
  EXPECT_EQ(cyclePhases(e, 0.83).size(), 1u);  // isovolumic contraction only
  // No ejection at all: nothing to name.
  for (CirculationSample& s : beat) s.aorticOpen = false;
  e = valveEvents(beat, 0);
  EXPECT_FALSE(e.mitralClose || e.aorticOpen || e.aorticClose || e.mitralOpen);
  EXPECT_TRUE(cyclePhases(e, 0.83).empty());
}

TEST(CirculationHistory, MitralInflowHasAnEarlyAndAnAtrialWave) {
  std::vector<CirculationSample> beat = textbookBeat(0);
  // The last atrial kick fading at the start, E after the mitral valve opens, A from the
  // atrium's contraction 160 ms before the beat ends.
  for (std::size_t i = 0; i < beat.size(); ++i) {
    CirculationSample& s = beat[i];
    const double t = double(i);
    if (i < 20) s.mitralFlow = 300e-6, s.atrialActivation = 0.2;
    if (i >= 380) s.mitralFlow = 500e-6 * std::exp(-std::pow((t - 430) / 40, 2));
    if (i >= 670) s.atrialActivation = std::sin((t - 669) / 160 * 3.14159);
    if (i >= 670) s.mitralFlow += 250e-6 * std::exp(-std::pow((t - 740) / 30, 2));
  }
  const MitralWaves waves = mitralWaves(beat);
  ASSERT_TRUE(waves.early && waves.atrial);
  EXPECT_EQ(*waves.early, 430u);
  EXPECT_NEAR(double(*waves.atrial), 740, 1);
  // No atrial contraction (atrial fibrillation): E only.
  for (CirculationSample& s : beat) s.atrialActivation = 0;
  EXPECT_FALSE(mitralWaves(beat).atrial);
  // No inflow: neither.
  for (CirculationSample& s : beat) s.mitralFlow = 0;
  EXPECT_FALSE(mitralWaves(beat).early);
}

TEST(CirculationHistory, StackedPanelsAreFilledByTheirData) {
  const AxisRange volume = paddedRange(47, 119, false);
  EXPECT_NEAR(volume.lo, 47 - 0.06 * 72, 1e-9);
  EXPECT_NEAR(volume.hi, 119 + 0.06 * 72, 1e-9);
  const AxisRange flow = paddedRange(0, 600, true);
  EXPECT_LT(flow.lo, 0);  // zero is a little above the bottom, not on the border
  EXPECT_NEAR(flow.hi, 636, 1e-9);
  const AxisRange flat = paddedRange(5, 5, false);
  EXPECT_LT(flat.lo, 5);
  EXPECT_GT(flat.hi, 5);
  const AxisRange none = paddedRange(std::numeric_limits<double>::infinity(), -1, false);
  EXPECT_EQ(none.lo, 0);
  EXPECT_EQ(none.hi, 1);
}

TEST(CirculationHistory, RelationsAreTheTextbooksLines) {
  cardiac::PressureVolumeRelations r;
  r.endSystolicElastance = cardiac::elastanceFromClinical(2.5);
  r.unstressedVolume = 5 * cardiac::kCubicMetresPerMl;
  r.diastolicScale = 0.35 * cardiac::kPascalPerMmHg;
  r.diastolicExponent = 0.028 / cardiac::kCubicMetresPerMl;
  const double v = 45 * cardiac::kCubicMetresPerMl;
  EXPECT_NEAR(endSystolicPressure(r, v) / cardiac::kPascalPerMmHg, 100, 1e-9);  // 2.5 x (45 - 5)
  EXPECT_NEAR(endDiastolicPressure(r, v) / cardiac::kPascalPerMmHg, 0.35 * (std::exp(0.028 * 40) - 1), 1e-9);
  EXPECT_DOUBLE_EQ(endSystolicPressure(r, r.unstressedVolume), 0);
  EXPECT_DOUBLE_EQ(endDiastolicPressure(r, r.unstressedVolume), 0);
}

TEST(CirculationHistory, LoopAxesHoldTheLoopsFromZero) {
  cardiac::PressureVolumeRelations r;
  r.unstressedVolume = 5 * cardiac::kCubicMetresPerMl;
  r.diastolicScale = 0.35 * cardiac::kPascalPerMmHg;
  r.diastolicExponent = 0.028 / cardiac::kCubicMetresPerMl;
  std::vector<CirculationSample> loop(2);
  loop[0].lvVolume = 50 * cardiac::kCubicMetresPerMl, loop[0].lvPressure = 118 * cardiac::kPascalPerMmHg;
  loop[1].lvVolume = 122 * cardiac::kCubicMetresPerMl, loop[1].lvPressure = 9 * cardiac::kPascalPerMmHg;
  const LoopAxes axes = loopAxes(loop, r, 6, 6);
  EXPECT_EQ(axes.volume.lo, 0);
  EXPECT_GE(axes.volume.hi, 122);
  EXPECT_LT(axes.volume.hi, 160);
  EXPECT_EQ(axes.pressure.lo, 0);
  EXPECT_GE(axes.pressure.hi, 118);
  EXPECT_LT(axes.pressure.hi, 160);
}

}  // namespace
}  // namespace hs::viewer
