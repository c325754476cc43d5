// Plots: data land where PlotFrame says, the legend shows every series, ticks are nice, errors
// name the series or the path.
#include <gtest/gtest.h>

#include "thrown_message.h"

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "viz/plot.h"

namespace hs::viz {
namespace {

constexpr Rgb kGrid{225, 225, 225};

// (Designated initialisers that skip members trip -Wmissing-field-initializers.)
Series makeSeries(std::string label, std::vector<double> x, std::vector<double> y,
                  Rgb colour = paletteColour(0), Series::Style style = Series::Style::Line) {
  Series series;
  series.label = std::move(label);
  series.x = std::move(x);
  series.y = std::move(y);
  series.colour = colour;
  series.style = style;
  return series;
}

// A surge-front-like curve (line) and "experimental" points (markers).
PlotSpec exampleSpec() {
  PlotSpec spec;
  spec.title = "Dam break: surge front";
  spec.xLabel = "t sqrt(2g/a)";
  spec.yLabel = "z / a";
  Series simulation = makeSeries("simulation", {}, {}, paletteColour(0), Series::Style::Line);
  Series experiment = makeSeries("Martin & Moyce 1952", {}, {}, paletteColour(1), Series::Style::Markers);
  experiment.marker = MarkerShape::Square;
  for (int i = 0; i <= 30; ++i) {
    const double t = i * 0.1;
    simulation.x.push_back(t);
    simulation.y.push_back(1.0 + 0.4 * t * t);
  }
  for (const double t : {0.4, 0.9, 1.4, 1.9, 2.4}) {
    experiment.x.push_back(t);
    experiment.y.push_back(1.05 + 0.38 * t * t);
  }
  spec.series = {simulation, experiment};
  return spec;
}

std::size_t countColour(const Image& image, const Rect& r, Rgb colour) {
  std::size_t n = 0;
  for (int y = std::max(0, r.y); y < std::min(image.height(), r.y + r.height); ++y) {
    for (int x = std::max(0, r.x); x < std::min(image.width(), r.x + r.width); ++x)
      n += image.at(x, y) == colour;
  }
  return n;
}

TEST(Plot, MarkersLandWherePlotFrameMapsThem) {
  const PlotSpec spec = exampleSpec();
  const PlotFrame frame(spec);
  const Image image = renderPlot(spec);
  ASSERT_EQ(image.width(), spec.width);
  ASSERT_EQ(image.height(), spec.height);
  const Series& experiment = spec.series[1];
  for (std::size_t i = 0; i < experiment.x.size(); ++i) {
    const PlotFrame::Point p = frame.toPixel(experiment.x[i], experiment.y[i]);
    const int px = static_cast<int>(std::floor(p.x)), py = static_cast<int>(std::floor(p.y));
    ASSERT_TRUE(frame.area().contains(px, py));
    ASSERT_FALSE(frame.legend()->contains(px, py));
    EXPECT_EQ(image.at(px, py), experiment.colour) << "point " << i;
  }
}

TEST(Plot, LinePassesThroughItsDataPoints) {
  const PlotSpec spec = exampleSpec();
  const PlotFrame frame(spec);
  const Image image = renderPlot(spec);
  const Series& simulation = spec.series[0];
  for (const std::size_t i : {3u, 10u, 17u}) {
    const PlotFrame::Point p = frame.toPixel(simulation.x[i], simulation.y[i]);
    const Rect neighbourhood{static_cast<int>(std::floor(p.x)) - 1, static_cast<int>(std::floor(p.y)) - 1, 3,
                             3};
    EXPECT_GT(countColour(image, neighbourhood, simulation.colour), 0u) << "point " << i;
  }
}

TEST(Plot, LegendShowsEverySeriesColourAndAvoidsTheData) {
  const PlotSpec spec = exampleSpec();
  const PlotFrame frame(spec);
  ASSERT_TRUE(frame.legend());
  const Rect legend = *frame.legend();
  const Rect& area = frame.area();
  EXPECT_GE(legend.x, area.x);
  EXPECT_LE(legend.x + legend.width, area.x + area.width);
  // The curve rises to the top right, so the legend belongs top-left.
  EXPECT_LT(legend.x + legend.width / 2, area.x + area.width / 2);
  EXPECT_LT(legend.y + legend.height / 2, area.y + area.height / 2);
  const Image image = renderPlot(spec);
  for (const Series& series : spec.series)
    EXPECT_GT(countColour(image, legend, series.colour), 4u) << series.label;
  EXPECT_GT(countColour(image, legend, kBlack), 50u);  // the labels

  PlotSpec unlabelled = spec;
  for (Series& series : unlabelled.series) series.label.clear();
  EXPECT_FALSE(PlotFrame(unlabelled).legend());
}

TEST(Plot, ImageIsNotBlankAndHasAGrid) {
  const Image image = renderPlot(exampleSpec());
  double sum = 0.0, sumSquares = 0.0;
  const auto& pixels = image.pixels();
  for (const std::uint8_t v : pixels) {
    sum += v;
    sumSquares += static_cast<double>(v) * v;
  }
  const double n = static_cast<double>(pixels.size());
  const double variance = sumSquares / n - (sum / n) * (sum / n);
  EXPECT_GT(variance, 200.0);
  EXPECT_GT(countColour(image, {0, 0, image.width(), image.height()}, kGrid), 1000u);
}

TEST(Plot, AutomaticRangesContainTheDataWithASmallMargin) {
  const PlotFrame frame(exampleSpec());
  const auto [xMin, xMax] = frame.xRange();
  const auto [yMin, yMax] = frame.yRange();
  EXPECT_LT(xMin, 0.0);
  EXPECT_GT(xMin, -0.3);
  EXPECT_GT(xMax, 3.0);
  EXPECT_LT(xMax, 3.3);
  EXPECT_LT(yMin, 1.0);
  EXPECT_GT(yMax, 4.6);
  // A single value still gets a non-empty range around it.
  PlotSpec single;
  single.series = {makeSeries("", {2.0}, {0.0})};
  const PlotFrame one(single);
  EXPECT_LT(one.xRange().first, 2.0);
  EXPECT_GT(one.xRange().second, 2.0);
  EXPECT_LT(one.yRange().first, 0.0);
  EXPECT_GT(one.yRange().second, 0.0);
}

TEST(Plot, TicksAreNiceStepsInsideTheRange) {
  PlotSpec spec = exampleSpec();
  spec.xRange = {0.0, 10.0};
  spec.yRange = {-0.37, 123.0};
  const PlotFrame frame(spec);
  for (const AxisTicks* ticks : {&frame.xTicks(), &frame.yTicks()}) {
    EXPECT_GE(ticks->values.size(), 3u);
    EXPECT_LE(ticks->values.size(), 12u);
    const double mantissa = ticks->step / std::pow(10.0, std::floor(std::log10(ticks->step)));
    EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
                std::abs(mantissa - 5) < 1e-9)
        << ticks->step;
  }
  EXPECT_EQ(frame.xTicks().values.front(), 0.0);
  EXPECT_EQ(frame.xTicks().values.back(), 10.0);
  EXPECT_EQ(frame.xTicks().labels.front(), "0");
  EXPECT_EQ(frame.xTicks().labels.back(), "10");
  EXPECT_GE(frame.yTicks().values.front(), -0.37);
  EXPECT_LE(frame.yTicks().values.back(), 123.0);

  spec.xRange = {0.0, 0.001};
  EXPECT_EQ(PlotFrame(spec).xTicks().labels.back(), "0.0010");
}

TEST(Plot, SeriesAreClippedToThePlotArea) {
  PlotSpec spec;
  const Rgb colour = paletteColour(2);
  spec.series = {makeSeries("", {0.0, 1.0, 2.0}, {-5.0, 50.0, 0.5}, colour, Series::Style::LineAndMarkers)};
  spec.yRange = {0.0, 1.0};
  const PlotFrame frame(spec);
  const Image image = renderPlot(spec);
  const Rect& a = frame.area();
  EXPECT_GT(countColour(image, a, colour), 0u);
  EXPECT_EQ(countColour(image, {0, 0, image.width(), image.height()}, colour), countColour(image, a, colour));
}

TEST(Plot, BadSeriesThrowNamingTheSeries) {
  PlotSpec spec = exampleSpec();
  spec.series.push_back(makeSeries("bad", {1.0, 2.0}, {1.0}));
  const std::string mismatch = hs::testing::thrownMessage<std::invalid_argument>([&] { renderPlot(spec); });
  EXPECT_NE(mismatch.find("series 'bad'"), std::string::npos) << mismatch;
  EXPECT_NE(mismatch.find("x has 2 values but y has 1"), std::string::npos) << mismatch;

  spec.series.back() = makeSeries("nan", {1.0, 2.0}, {1.0, std::nan("")});
  EXPECT_NE(hs::testing::thrownMessage<std::invalid_argument>([&] { PlotFrame{spec}; }).find("series 'nan': point 1"), std::string::npos);
  spec.series.back() = makeSeries("", {std::numeric_limits<double>::infinity()}, {1.0});
  EXPECT_NE(hs::testing::thrownMessage<std::invalid_argument>([&] { validatePlotSpec(spec); }).find("series #2"), std::string::npos);
}

TEST(Plot, BadRangesAndSizesThrow) {
  PlotSpec spec = exampleSpec();
  spec.xRange = {1.0, 1.0};
  EXPECT_NE(hs::testing::thrownMessage<std::invalid_argument>([&] { renderPlot(spec); }).find("xRange"), std::string::npos);
  spec.xRange.reset();
  spec.yRange = {0.0, std::numeric_limits<double>::infinity()};
  EXPECT_NE(hs::testing::thrownMessage<std::invalid_argument>([&] { renderPlot(spec); }).find("yRange"), std::string::npos);
  spec.yRange.reset();
  spec.width = 10;
  EXPECT_THROW(renderPlot(spec), std::invalid_argument);
}

TEST(Plot, WritePngRoundTripsAndNamesAnUnwritablePath) {
  const PlotSpec spec = exampleSpec();
  const std::string path = (std::filesystem::path(::testing::TempDir()) / "viz-plot.png").string();
  writePlotPng(path, spec);
  EXPECT_EQ(Image::loadPng(path).pixels(), renderPlot(spec).pixels());
  try {
    writePlotPng("/nonexistent-dir/x.png", spec);
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("'/nonexistent-dir/x.png'"), std::string::npos) << e.what();
  }
}

TEST(Plot, SmallAndLargeImagesStillLayOut) {
  PlotSpec spec = exampleSpec();
  for (const auto& [w, h] : {std::pair{200, 150}, std::pair{1800, 1200}}) {
    spec.width = w;
    spec.height = h;
    const PlotFrame frame(spec);
    EXPECT_GT(frame.area().width, w / 3);
    EXPECT_GT(frame.area().height, h / 3);
    EXPECT_EQ(renderPlot(spec).width(), w);
  }
}

TEST(Plot, LegendGoesToTheCornerAsked) {
  PlotSpec spec = exampleSpec();
  const Rect automatic = *PlotFrame(spec).legend();  // top-left: the curve rises to the right
  spec.legendCorner = LegendCorner::TopRight;
  const PlotFrame frame(spec);
  const Rect& area = frame.area();
  const Rect asked = *frame.legend();
  EXPECT_EQ(asked.width, automatic.width);
  EXPECT_EQ(asked.y, automatic.y);
  EXPECT_GT(asked.x + asked.width / 2, area.x + area.width / 2);
  EXPECT_LT(automatic.x + automatic.width / 2, area.x + area.width / 2);
  spec.legendCorner = LegendCorner::BottomLeft;
  EXPECT_EQ(PlotFrame(spec).legend()->x, automatic.x);
  EXPECT_GT(PlotFrame(spec).legend()->y, area.y + area.height / 2);
  const Image image = renderPlot(spec);
  EXPECT_GT(countColour(image, *PlotFrame(spec).legend(), spec.series[1].colour), 4u);
}

TEST(Plot, StackedPanelsShareTextScaleAndLeftEdge) {
  // Two panels of one figure: different heights and y tick widths, yet the same font and the
  // same plot-area columns once each takes the larger left margin.
  PlotSpec top = exampleSpec(), bottom = exampleSpec();
  top.height = 300;
  bottom.height = 500;
  bottom.yRange = {-1000.0, 1000.0};  // wider tick labels than "0.0".."5.0"
  EXPECT_NE(PlotFrame(top).textScale(), PlotFrame(bottom).textScale());
  top.textScale = bottom.textScale = 2;
  EXPECT_EQ(PlotFrame(top).textScale(), 2);
  EXPECT_EQ(PlotFrame(bottom).textScale(), 2);
  EXPECT_LT(PlotFrame(top).area().x, PlotFrame(bottom).area().x);
  const int left = std::max(PlotFrame(top).area().x, PlotFrame(bottom).area().x);
  top.minAreaLeft = bottom.minAreaLeft = left;
  EXPECT_EQ(PlotFrame(top).area().x, left);
  EXPECT_EQ(PlotFrame(bottom).area().x, left);
  EXPECT_EQ(PlotFrame(top).area().width, PlotFrame(bottom).area().width);
  EXPECT_EQ(PlotFrame(top).toPixel(1.5, 0.0).x, PlotFrame(bottom).toPixel(1.5, 0.0).x);

  top.textScale = 0;
  EXPECT_NE(hs::testing::thrownMessage<std::invalid_argument>([&] { PlotFrame{top}; }).find("textScale 0"),
            std::string::npos);
  top.textScale.reset();
  top.minAreaLeft = -1;
  EXPECT_NE(hs::testing::thrownMessage<std::invalid_argument>([&] { PlotFrame{top}; }).find("minAreaLeft"),
            std::string::npos);
}

}  // namespace
}  // namespace hs::viz
