// The pump plots' fixed axes: clinical ranges for a real heart, the thesis models' own ranges
// in SI units, widened only in whole steps when a value leaves them and never narrowed, so a
// 16 mL stroke looks smaller than a 69 mL one and the cycle's 0.0006 mL of noise stays flat.
#include <gtest/gtest.h>

#include <cmath>

#include "cardiac/circulation/clinical_units.h"
#include "viewer/plots/plot_axes.h"

namespace hs::viewer {
namespace {

constexpr double kMl = 1e-6;
constexpr double kMmHg = cardiac::kPascalPerMmHg;

void expectRange(const AxisRange& r, double lo, double hi, const char* what) {
  EXPECT_NEAR(r.lo, lo, 1e-9 * std::max(1.0, std::abs(lo))) << what;
  EXPECT_NEAR(r.hi, hi, 1e-9 * std::max(1.0, std::abs(hi))) << what;
}

PumpSample sample(double cavity, double flow, double pressure) {
  PumpSample s;
  s.cavity = cavity;
  s.mitralSmoothed = s.aorticSmoothed = flow;
  s.pressureLv = s.pressureInflow = s.pressureOutflow = pressure;
  return s;
}

TEST(PlotAxes, ARealHeartGetsClinicalRanges) {
  const PlotAxes axes(volumeScaleFor(128 * kMl), 128 * kMl);
  expectRange(axes.volume(), 0, 200, "mL");
  expectRange(axes.flow(), -200, 600, "mL/s");
  expectRange(axes.pressure(), 0, 150, "mmHg");
  EXPECT_NEAR(axes.pressureScale() * kMmHg, 1, 1e-12) << "pressures shown in mmHg";
}

TEST(PlotAxes, NoiseNeverRescalesThem) {
  PlotAxes axes(volumeScaleFor(128 * kMl), 128 * kMl);
  // The cycle off: the cavity still to 0.0006 mL, no flow, the pressures at rest.
  for (int i = 0; i < 1000; ++i)
    axes.hold(sample((128 + 0.0006 * std::sin(i)) * kMl, 1e-3 * kMl * std::sin(i), 8 * kMmHg));
  expectRange(axes.volume(), 0, 200, "mL");
  expectRange(axes.flow(), -200, 600, "mL/s");
  expectRange(axes.pressure(), 0, 150, "mmHg");
  // A beat of normal's size stays inside too: EDV 128, ESV 58, aortic peak 550 mL/s, LV 130 mmHg.
  axes.hold(sample(58 * kMl, 550 * kMl, 130 * kMmHg));
  axes.hold(sample(128 * kMl, -40 * kMl, 2 * kMmHg));
  expectRange(axes.volume(), 0, 200, "mL");
  expectRange(axes.flow(), -200, 600, "mL/s");
  expectRange(axes.pressure(), 0, 150, "mmHg");
}

TEST(PlotAxes, WidenInWholeStepsAndNeverNarrow) {
  // dilated-cardiomyopathy starts near 240 mL: room for its filling from the start.
  PlotAxes axes(volumeScaleFor(240 * kMl), 240 * kMl);
  expectRange(axes.volume(), 0, 300, "1.25 x 240 mL");
  axes.hold(sample(310 * kMl, 0, 0));
  expectRange(axes.volume(), 0, 350, "one step of 50 mL");
  axes.hold(sample(100 * kMl, 0, 0));
  expectRange(axes.volume(), 0, 350, "never narrows");
  axes.hold(sample(200 * kMl, -250 * kMl, 187 * kMmHg));  // a regurgitant jet, a stenosis's LV
  expectRange(axes.flow(), -400, 600, "a step of 200 mL/s down");
  expectRange(axes.pressure(), 0, 200, "a step of 50 mmHg");
}

TEST(PlotAxes, UnknownSmoothedFlowsAreLeftOut) {
  PlotAxes axes(volumeScaleFor(128 * kMl), 128 * kMl);
  PumpSample s = sample(120 * kMl, 0, 0);
  s.mitralSmoothed = s.aorticSmoothed = PumpSample::kUnknown;
  s.mitralRate = 5000 * kMl;  // a raw step's spike is not drawn, and not held
  axes.hold(s);
  expectRange(axes.flow(), -200, 600, "mL/s");
}

TEST(PlotAxes, ThesisScaleModelsHaveTheirOwnFixedRanges) {
  const double v0 = 7.4;  // paper-chamber: m^3
  PlotAxes axes(volumeScaleFor(v0), v0);
  EXPECT_EQ(axes.pressureScale(), 1) << "Pa: no clinical meaning at this scale";
  expectRange(axes.volume(), 0, 15, "m^3: 1.5 x 7.4 in steps of 5");
  expectRange(axes.flow(), -2, 2, "m^3/s: a quarter of the rest volume per second");
  expectRange(axes.pressure(), 0, 1e4, "Pa");
  // A beat of paper-chamber-beating's size (5.6 to 8.8 m^3, 1.5 m^3/s) and noise leave them.
  for (int i = 0; i < 500; ++i) axes.hold(sample(7.2 + 1.6 * std::sin(0.1 * i), 1.5 * std::sin(0.3 * i), 4000));
  expectRange(axes.volume(), 0, 15, "m^3");
  expectRange(axes.flow(), -2, 2, "m^3/s");
  // heart-only is larger: its own range from its rest volume.
  const PlotAxes large(volumeScaleFor(33.0), 33.0);
  expectRange(large.volume(), 0, 60, "m^3: 1.5 x 33 in steps of 20");
}

}  // namespace
}  // namespace hs::viewer
