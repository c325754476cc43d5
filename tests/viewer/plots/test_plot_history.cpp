// The live plots' history: a ring buffer that keeps the last N seconds of simulated time in
// order across its wrap-around, starts over when the simulation restarts, and is bounded
// however small the step; and the axis arithmetic the plots draw with.
#include <gtest/gtest.h>

#include <cmath>

#include "viewer/plots/plot_history.h"

namespace hs::viewer {
namespace {

PumpSample at(double time, double cavity = 0) {
  PumpSample s;
  s.time = time;
  s.cavity = cavity;
  return s;
}

void expectIncreasing(const PlotHistory& h) {
  for (std::size_t i = 1; i < h.size(); ++i) ASSERT_LT(h[i - 1].time, h[i].time) << "at " << i;
}

TEST(PlotHistory, KeepsTheLastWindowOfSimulatedTime) {
  PlotHistory h(1.0);
  for (int i = 1; i <= 500; ++i) h.push(at(i * 0.01, i));
  expectIncreasing(h);
  EXPECT_DOUBLE_EQ(h.newest().time, 5.0);
  // One sample at or before the left edge (t = 4), so the line reaches it; none older.
  EXPECT_LE(h[0].time, 4.0 + 1e-12);
  EXPECT_GT(h[1].time, 4.0 + 1e-12);
  EXPECT_EQ(h.size(), 101u);
  EXPECT_DOUBLE_EQ(h[0].cavity, 400);  // the values travel with their times
}

TEST(PlotHistory, StaysInOrderAcrossManyWrapArounds) {
  PlotHistory h(0.37);
  for (int i = 1; i <= 10000; ++i) {
    h.push(at(i * 0.003));
    if (i % 997 == 0) expectIncreasing(h);
  }
  expectIncreasing(h);
  EXPECT_NEAR(h.newest().time - h[1].time, 0.37, 0.003 + 1e-9);
}

TEST(PlotHistory, StartsOverWhenTheSimulationRestarts) {
  PlotHistory h(5.0);
  for (int i = 1; i <= 100; ++i) h.push(at(i * 0.01));
  h.push(at(0.01));  // Reset: time starts again
  ASSERT_EQ(h.size(), 1u);
  EXPECT_DOUBLE_EQ(h.newest().time, 0.01);
  h.push(at(0.02));
  h.push(at(0.02));  // the same time again is a restart too (a restart after one step)
  EXPECT_EQ(h.size(), 1u);
  h.clear();
  EXPECT_TRUE(h.empty());
  h.push(at(3.0));
  EXPECT_EQ(h.size(), 1u);
}

TEST(PlotHistory, ChangingTheWindow) {
  PlotHistory h(10.0);
  for (int i = 1; i <= 1000; ++i) h.push(at(i * 0.01));
  EXPECT_EQ(h.size(), 1000u);
  h.setWindow(2.0);  // narrower: the older samples go at once
  EXPECT_EQ(h.size(), 201u);
  h.setWindow(5.0);  // wider: fills as time goes on
  for (int i = 1001; i <= 1100; ++i) h.push(at(i * 0.01));
  EXPECT_EQ(h.size(), 301u);
  expectIncreasing(h);
}

TEST(PlotHistory, IsBoundedHoweverSmallTheStep) {
  PlotHistory h(1e9);
  const std::size_t n = PlotHistory::kMaxSamples + 1000;
  for (std::size_t i = 1; i <= n; ++i) h.push(at(double(i) * 1e-6));
  EXPECT_EQ(h.size(), PlotHistory::kMaxSamples);
  EXPECT_DOUBLE_EQ(h.newest().time, double(n) * 1e-6);
  EXPECT_DOUBLE_EQ(h[0].time, double(n - PlotHistory::kMaxSamples + 1) * 1e-6);
}

TEST(PlotHistory, LowerBoundFindsTheFirstSampleAtOrAfterATime) {
  PlotHistory h(100.0);
  EXPECT_EQ(h.lowerBound(1.0), 0u);
  for (int i = 1; i <= 10; ++i) h.push(at(i));
  EXPECT_EQ(h.lowerBound(0.5), 0u);
  EXPECT_EQ(h.lowerBound(3.0), 2u);
  EXPECT_EQ(h.lowerBound(3.5), 3u);
  EXPECT_EQ(h.lowerBound(11.0), 10u);
}

TEST(PlotAxis, TicksAreOneTwoOrFiveTimesAPowerOfTen) {
  const AxisTicks a = niceTicks(0, 1, 6);
  EXPECT_DOUBLE_EQ(a.step, 0.2);
  EXPECT_DOUBLE_EQ(a.first, 0);
  EXPECT_EQ(a.count, 6);
  const AxisTicks b = niceTicks(3.7, 8.1, 5);  // seconds along a plot
  EXPECT_DOUBLE_EQ(b.step, 2);
  EXPECT_DOUBLE_EQ(b.first, 4);
  EXPECT_EQ(b.count, 3);  // 4, 6, 8
  for (const double span : {0.0003, 0.7, 13.0, 4200.0, 7.5e6}) {
    const AxisTicks t = niceTicks(-span / 3, span, 5);
    EXPECT_LE(t.count, 5) << span;
    EXPECT_GE(t.count, 2) << span;
    const double mantissa = t.step / std::pow(10.0, std::floor(std::log10(t.step)));
    EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
                std::abs(mantissa - 5) < 1e-9)
        << t.step;
    EXPECT_GE(t.first, -span / 3 - 1e-12);
    EXPECT_LT(t.first - t.step, -span / 3);
  }
}

TEST(PlotAxis, RangeHoldsTheDataAndZeroWhenAsked) {
  const AxisRange volume = niceRange(5.5, 8.4, false, 5);  // thesis-scale cavity, m^3
  EXPECT_LE(volume.lo, 5.5);
  EXPECT_GE(volume.hi, 8.4);
  EXPECT_GT(volume.lo, 0) << "a volume plot need not reach down to zero";
  const AxisRange flow = niceRange(-12, 300, true, 5);
  EXPECT_LT(flow.lo, -12);
  EXPECT_GE(flow.hi, 300);
  const AxisRange pressure = niceRange(200, 900, true, 5);
  EXPECT_DOUBLE_EQ(pressure.lo, 0);
  const AxisRange flat = niceRange(7, 7, false, 5);
  EXPECT_LT(flat.lo, 7);
  EXPECT_GT(flat.hi, 7);
  const AxisRange zeros = niceRange(0, 0, true, 5);
  EXPECT_LT(zeros.lo, 0);
  EXPECT_GT(zeros.hi, 0);
}

}  // namespace
}  // namespace hs::viewer
