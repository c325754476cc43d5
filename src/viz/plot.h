#pragma once
// Validation plots as PNG: x–y series (lines and/or markers) with axes, "nice" ticks (steps of
// 1, 2 or 5 times a power of ten), light grid, title, axis labels and a legend. Meant for figures
// such as the dam-break surge front against Martin & Moyce (1952) or pressure–volume loops; not a
// general plotting library.
//
// The layout is computed once by PlotFrame and renderPlot draws exactly that layout, so callers
// (and tests) can find the pixel of any data point with PlotFrame(spec).toPixel(x, y).
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "viz/image.h"

namespace hs::viz {

// Colour-blind-safe palette (Okabe & Ito, "Color Universal Design", 2008), cycling with index.
Rgb paletteColour(std::size_t index);

struct Series {
  enum class Style { Line, Markers, LineAndMarkers };

  std::string label;  // shown in the legend; a series with an empty label is not listed
  std::vector<double> x, y;
  Rgb colour = paletteColour(0);
  Style style = Style::Line;
  MarkerShape marker = MarkerShape::Circle;
};

enum class LegendCorner { TopRight, TopLeft, BottomRight, BottomLeft };

struct PlotSpec {
  std::string title, xLabel, yLabel;
  std::vector<Series> series;
  // (min, max) in data units; when absent, the range of the data plus a 5% margin on each side
  // (with xRange given, the automatic y range uses only the points inside it).
  std::optional<std::pair<double, double>> xRange, yRange;
  int width = 900, height = 600;  // pixels
  // Font pixel size (1..8) of the labels; when absent it grows with the smaller image side. Panels
  // stacked into one figure give the same value so their text matches although their heights differ.
  std::optional<int> textScale;
  // Least number of pixel columns left of the plot area (0: just room for the labels). Panels stacked
  // over a shared x axis give the largest of their own left margins, so their time axes line up.
  int minAreaLeft = 0;
  // The legend's corner of the plot area; when absent, the corner that hides the fewest data
  // (which counts reference lines as data: a caller that made room above its curves says where).
  std::optional<LegendCorner> legendCorner;
};

// Throws std::invalid_argument naming the series when x and y differ in size or hold a
// non-finite value, and for an empty/inverted/non-finite range, a size too small to plot, a text
// scale outside 1..8 or a negative minAreaLeft.
void validatePlotSpec(const PlotSpec& spec);

struct AxisTicks {
  double step = 1.0;
  std::vector<double> values;       // multiples of step inside the axis range
  std::vector<std::string> labels;  // formatted with the decimals the step needs
};

// The geometry of a plot. Construction validates the spec (see validatePlotSpec).
class PlotFrame {
 public:
  struct Point {
    double x, y;
  };

  explicit PlotFrame(const PlotSpec& spec);

  // Continuous pixel coordinates of a data point: the point lies in pixel (floor(x), floor(y)).
  // The x range maps onto [area.x, area.x + area.width], the y range onto the same span of rows
  // upwards (y grows downwards in the image).
  Point toPixel(double x, double y) const;

  // Where the data are drawn (series are clipped to it); the axis frame surrounds it.
  const Rect& area() const { return m_area; }
  std::pair<double, double> xRange() const { return {m_xMin, m_xMax}; }
  std::pair<double, double> yRange() const { return {m_yMin, m_yMax}; }
  const AxisTicks& xTicks() const { return m_xTicks; }
  const AxisTicks& yTicks() const { return m_yTicks; }
  // Legend box inside the plot area, in spec.legendCorner or else the corner that hides the
  // fewest data; none when no series has a label.
  const std::optional<Rect>& legend() const { return m_legend; }
  // Size of a font pixel for tick and axis labels (grows with the image).
  int textScale() const { return m_textScale; }
  double lineThickness() const { return 1.0 + 0.5 * m_textScale; }
  double markerRadius() const { return 2.0 + m_textScale; }

 private:
  Rect m_area;
  double m_xMin = 0, m_xMax = 1, m_yMin = 0, m_yMax = 1;
  AxisTicks m_xTicks, m_yTicks;
  std::optional<Rect> m_legend;
  int m_textScale = 1;
};

// White background, grid, series, axis frame with ticks and labels, title, legend.
Image renderPlot(const PlotSpec& spec);
// renderPlot + Image::savePng (throws std::runtime_error naming the path if it cannot write).
void writePlotPng(const std::string& path, const PlotSpec& spec);

}  // namespace hs::viz
