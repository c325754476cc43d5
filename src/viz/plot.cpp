#include "viz/plot.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <tuple>

namespace hs::viz {
namespace {

constexpr Rgb kGridColour{225, 225, 225};
constexpr Rgb kLegendBorder{160, 160, 160};
constexpr int kMinSize = 64, kMaxSize = 16384;

// Spacing of the layout, all multiples of the font pixel so a larger image scales uniformly.
struct Metrics {
  explicit Metrics(int scale)
      : s(scale),
        pad(6 * scale),
        tick(3 * scale),
        frameWidth(std::max(1, scale / 2)),
        titleScale(scale + 1) {}
  int s, pad, tick, frameWidth, titleScale;
  int cap() const { return Image::capHeight(s); }
  // Rows a line of text can touch, descenders included (stb_easy_font: font rows 0..9).
  static int glyphBox(int scale) { return 10 * scale; }
  int legendSampleWidth() const { return 16 * s; }
};

int textScaleFor(int width, int height) {
  return std::clamp(static_cast<int>(std::lround(std::min(width, height) / 300.0)), 1, 4);
}

std::string seriesName(const Series& series, std::size_t index) {
  return series.label.empty() ? "#" + std::to_string(index) : "'" + series.label + "'";
}

void validateRange(const std::optional<std::pair<double, double>>& range, const char* name) {
  if (range &&
      !(std::isfinite(range->first) && std::isfinite(range->second) && range->first < range->second)) {
    throw std::invalid_argument(std::string("PlotSpec.") + name + " must be finite with min < max, got (" +
                                std::to_string(range->first) + ", " + std::to_string(range->second) + ")");
  }
}

// The data extent along one axis plus a 5% margin; a single value gets a symmetric +-10% (or +-1
// around zero) so it does not sit on the frame. With an x window (a fixed x range) the y extent
// considers only the points inside it, which is what a zoomed-in plot needs.
std::pair<double, double> autoRange(const PlotSpec& spec, bool yAxis,
                                    const std::optional<std::pair<double, double>>& xWindow) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  const auto scan = [&](bool useWindow) {
    for (const Series& series : spec.series) {
      for (std::size_t i = 0; i < series.x.size(); ++i) {
        if (useWindow && (series.x[i] < xWindow->first || series.x[i] > xWindow->second)) continue;
        const double v = yAxis ? series.y[i] : series.x[i];
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    }
  };
  scan(xWindow.has_value());
  if (lo > hi && xWindow) scan(false);
  if (lo > hi) return {0.0, 1.0};
  if (lo == hi) {
    const double d = lo == 0.0 ? 1.0 : std::abs(lo) * 0.1;
    return {lo - d, hi + d};
  }
  const double margin = 0.05 * (hi - lo);
  if (!std::isfinite(margin)) throw std::invalid_argument("PlotSpec: data span too large to plot");
  return {lo - margin, hi + margin};
}

// The step of the form {1, 2, 5} x 10^k closest to raw (by ratio).
double niceStepNear(double raw) {
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double best = power;
  for (const double f : {2.0, 5.0, 10.0}) {
    if (std::abs(std::log(f * power / raw)) < std::abs(std::log(best / raw))) best = f * power;
  }
  return best;
}

// The next step of the form {1, 2, 5} x 10^k above step.
double nextNiceStep(double step) {
  const double power = std::pow(10.0, std::floor(std::log10(step) + 1e-9));
  const double mantissa = step / power;
  return (mantissa < 1.5 ? 2.0 : mantissa < 3.5 ? 5.0 : 10.0) * power;
}

std::string formatTick(double value, double step) {
  if (std::abs(value) < step * 1e-6) value = 0.0;  // avoid "-0.0" and 1e-17 from k * step
  const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  char text[64];
  if (decimals > 6 || std::abs(value) >= 1e7) {
    std::snprintf(text, sizeof text, "%g", value);
  } else {
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
  }
  return text;
}

// Ticks at multiples of the nice step nearest to targetIntervals intervals; the step grows
// (1 -> 2 -> 5 -> 10) until neighbouring labels are at least minSpacing pixels apart.
AxisTicks makeTicks(double lo, double hi, double targetIntervals, double pixelLength, bool horizontal,
                    int scale, int minGap) {
  AxisTicks ticks;
  ticks.step = niceStepNear((hi - lo) / std::max(targetIntervals, 1.0));
  for (;;) {
    ticks.values.clear();
    ticks.labels.clear();
    const double kFirst = std::ceil(lo / ticks.step - 1e-9), kLast = std::floor(hi / ticks.step + 1e-9);
    for (double k = kFirst; k <= kLast; k += 1.0) {
      ticks.values.push_back(k * ticks.step);
      ticks.labels.push_back(formatTick(k * ticks.step, ticks.step));
    }
    int labelExtent = Image::capHeight(scale);
    if (horizontal) {
      for (const std::string& label : ticks.labels)
        labelExtent = std::max(labelExtent, Image::textWidth(label, scale));
    }
    const double spacing = ticks.step / (hi - lo) * pixelLength;
    if (ticks.values.size() < 2 || spacing >= labelExtent + minGap) return ticks;
    ticks.step = nextNiceStep(ticks.step);
  }
}

// Points along every series in pixel space (segments sampled every few pixels): what a legend
// box placed on top would hide.
std::vector<PlotFrame::Point> dataSamples(const PlotSpec& spec, const PlotFrame& frame) {
  std::vector<PlotFrame::Point> samples;
  for (const Series& series : spec.series) {
    for (std::size_t i = 0; i < series.x.size(); ++i) {
      const PlotFrame::Point p = frame.toPixel(series.x[i], series.y[i]);
      samples.push_back(p);
      if (i == 0 || series.style == Series::Style::Markers) continue;
      const PlotFrame::Point q = frame.toPixel(series.x[i - 1], series.y[i - 1]);
      const int steps = static_cast<int>(std::min(500.0, std::hypot(p.x - q.x, p.y - q.y) / 4.0));
      for (int k = 1; k < steps; ++k) {
        const double t = static_cast<double>(k) / steps;
        samples.push_back({q.x + t * (p.x - q.x), q.y + t * (p.y - q.y)});
      }
    }
  }
  return samples;
}

std::optional<Rect> placeLegend(const PlotSpec& spec, const PlotFrame& frame, const Metrics& m) {
  int entries = 0, labelWidth = 0;
  for (const Series& series : spec.series) {
    if (series.label.empty()) continue;
    ++entries;
    labelWidth = std::max(labelWidth, Image::textWidth(series.label, m.s));
  }
  if (entries == 0) return std::nullopt;
  const int width = 3 * m.pad + m.legendSampleWidth() + labelWidth;
  const int height = 2 * m.pad + (entries - 1) * Image::lineHeight(m.s) + Metrics::glyphBox(m.s);
  const Rect& a = frame.area();
  const int left = a.x + m.pad, right = a.x + a.width - m.pad - width;
  const int top = a.y + m.pad, bottom = a.y + a.height - m.pad - height;
  // Preference order on ties: top-right, top-left, bottom-right, bottom-left (LegendCorner's order).
  const std::array<Rect, 4> candidates{Rect{right, top, width, height}, Rect{left, top, width, height},
                                       Rect{right, bottom, width, height}, Rect{left, bottom, width, height}};
  if (spec.legendCorner) return candidates[static_cast<std::size_t>(*spec.legendCorner)];
  const std::vector<PlotFrame::Point> samples = dataSamples(spec, frame);
  std::size_t best = 0, bestHidden = std::numeric_limits<std::size_t>::max();
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    const Rect& r = candidates[c];
    const auto hidden =
        static_cast<std::size_t>(std::count_if(samples.begin(), samples.end(), [&](const auto& p) {
          return p.x >= r.x - m.pad && p.x < r.x + r.width + m.pad && p.y >= r.y - m.pad &&
                 p.y < r.y + r.height + m.pad;
        }));
    if (hidden < bestHidden) {
      best = c;
      bestHidden = hidden;
    }
  }
  return candidates[best];
}

void drawSeries(Image& image, const PlotFrame& frame, const Series& series) {
  const bool line = series.style != Series::Style::Markers;
  const bool markers = series.style != Series::Style::Line;
  for (std::size_t i = 1; line && i < series.x.size(); ++i) {
    const PlotFrame::Point p = frame.toPixel(series.x[i - 1], series.y[i - 1]);
    const PlotFrame::Point q = frame.toPixel(series.x[i], series.y[i]);
    image.drawLine(p.x, p.y, q.x, q.y, series.colour, frame.lineThickness());
  }
  if (line && !markers && series.x.size() == 1) {  // a one-point line would be invisible
    const PlotFrame::Point p = frame.toPixel(series.x[0], series.y[0]);
    image.drawCircle(p.x, p.y, frame.lineThickness(), series.colour);
  }
  for (std::size_t i = 0; markers && i < series.x.size(); ++i) {
    const PlotFrame::Point p = frame.toPixel(series.x[i], series.y[i]);
    image.drawMarker(p.x, p.y, series.marker, frame.markerRadius(), series.colour);
  }
}

// Grid lines, axis frame, tick marks and tick labels.
void drawAxes(Image& image, const PlotFrame& frame, const Metrics& m) {
  const Rect& a = frame.area();
  const AxisTicks& xt = frame.xTicks();
  const AxisTicks& yt = frame.yTicks();
  for (std::size_t i = 0; i < xt.values.size(); ++i) {
    const int column = static_cast<int>(std::floor(frame.toPixel(xt.values[i], 0.0).x));
    if (column > a.x && column < a.x + a.width) image.fillRect({column, a.y, 1, a.height}, kGridColour);
    image.fillRect({column, a.y + a.height + m.frameWidth, m.frameWidth, m.tick}, kBlack);
    const int w = Image::textWidth(xt.labels[i], m.s);
    const int x = std::clamp(column - w / 2, 0, std::max(0, image.width() - w));
    image.drawText(x, a.y + a.height + m.frameWidth + m.tick + m.pad / 2, xt.labels[i], m.s, kBlack);
  }
  for (std::size_t i = 0; i < yt.values.size(); ++i) {
    const int row = static_cast<int>(std::floor(frame.toPixel(0.0, yt.values[i]).y));
    if (row > a.y && row < a.y + a.height) image.fillRect({a.x, row, a.width, 1}, kGridColour);
    image.fillRect({a.x - m.frameWidth - m.tick, row, m.tick, m.frameWidth}, kBlack);
    const int right = a.x - m.frameWidth - m.tick - m.pad / 2;
    image.drawText(right - Image::textWidth(yt.labels[i], m.s), row - m.cap() / 2, yt.labels[i], m.s, kBlack);
  }
  image.strokeRect(
      {a.x - m.frameWidth, a.y - m.frameWidth, a.width + 2 * m.frameWidth, a.height + 2 * m.frameWidth},
      kBlack, m.frameWidth);
}

void drawTitleAndLabels(Image& image, const PlotSpec& spec, const PlotFrame& frame, const Metrics& m) {
  const Rect& a = frame.area();
  const auto centredX = [&](const std::string& text, int scale) {
    return std::max(0, a.x + (a.width - Image::textWidth(text, scale)) / 2);
  };
  image.drawText(centredX(spec.title, m.titleScale), 2 * m.pad, spec.title, m.titleScale, kBlack);
  const int xLabelTop = a.y + a.height + m.frameWidth + m.tick + m.pad / 2 + m.cap() + 3 * m.pad / 2;
  image.drawText(centredX(spec.xLabel, m.s), xLabelTop, spec.xLabel, m.s, kBlack);
  if (!spec.yLabel.empty()) {
    // stb_easy_font only writes horizontally: draw the label into its own image and turn it.
    Image label(Image::textWidth(spec.yLabel, m.s), Metrics::glyphBox(m.s));
    label.drawText(0, 0, spec.yLabel, m.s, kBlack);
    const Image vertical = label.rotatedCounterClockwise();
    image.blit(vertical, m.pad, std::max(0, a.y + (a.height - vertical.height()) / 2));
  }
}

void drawLegend(Image& image, const PlotSpec& spec, const PlotFrame& frame, const Metrics& m) {
  const Rect box = *frame.legend();
  image.fillRect(box, kWhite);
  image.strokeRect(box, kLegendBorder);
  int row = 0;
  for (const Series& series : spec.series) {
    if (series.label.empty()) continue;
    const int top = box.y + m.pad + row++ * Image::lineHeight(m.s);
    const double centreY = top + m.cap() / 2.0;
    const double x0 = box.x + m.pad, x1 = x0 + m.legendSampleWidth();
    if (series.style != Series::Style::Markers) {
      image.drawLine(x0, centreY, x1, centreY, series.colour, frame.lineThickness());
    }
    if (series.style != Series::Style::Line) {
      image.drawMarker((x0 + x1) / 2.0, centreY, series.marker, frame.markerRadius(), series.colour);
    }
    image.drawText(static_cast<int>(x1) + m.pad, top, series.label, m.s, kBlack);
  }
}

}  // namespace

Rgb paletteColour(std::size_t index) {
  static constexpr std::array<Rgb, 7> kPalette{Rgb{0, 114, 178},   Rgb{213, 94, 0},  Rgb{0, 158, 115},
                                               Rgb{204, 121, 167}, Rgb{230, 159, 0}, Rgb{86, 180, 233},
                                               Rgb{0, 0, 0}};
  return kPalette[index % kPalette.size()];
}

void validatePlotSpec(const PlotSpec& spec) {
  if (spec.width < kMinSize || spec.height < kMinSize || spec.width > kMaxSize || spec.height > kMaxSize) {
    throw std::invalid_argument("PlotSpec: size " + std::to_string(spec.width) + "x" +
                                std::to_string(spec.height) + " must be between " + std::to_string(kMinSize) +
                                " and " + std::to_string(kMaxSize) + " pixels");
  }
  if (spec.textScale && (*spec.textScale < 1 || *spec.textScale > 8)) {
    throw std::invalid_argument("PlotSpec: textScale " + std::to_string(*spec.textScale) +
                                " must be between 1 and 8");
  }
  if (spec.minAreaLeft < 0) {
    throw std::invalid_argument("PlotSpec: minAreaLeft " + std::to_string(spec.minAreaLeft) +
                                " must not be negative");
  }
  validateRange(spec.xRange, "xRange");
  validateRange(spec.yRange, "yRange");
  for (std::size_t s = 0; s < spec.series.size(); ++s) {
    const Series& series = spec.series[s];
    if (series.x.size() != series.y.size()) {
      throw std::invalid_argument("series " + seriesName(series, s) + ": x has " +
                                  std::to_string(series.x.size()) + " values but y has " +
                                  std::to_string(series.y.size()));
    }
    for (std::size_t i = 0; i < series.x.size(); ++i) {
      if (!std::isfinite(series.x[i]) || !std::isfinite(series.y[i])) {
        throw std::invalid_argument("series " + seriesName(series, s) + ": point " + std::to_string(i) +
                                    " (" + std::to_string(series.x[i]) + ", " + std::to_string(series.y[i]) +
                                    ") is not finite");
      }
    }
  }
}

PlotFrame::PlotFrame(const PlotSpec& spec) {
  validatePlotSpec(spec);
  m_textScale = spec.textScale.value_or(textScaleFor(spec.width, spec.height));
  const Metrics m(m_textScale);
  std::tie(m_xMin, m_xMax) = spec.xRange ? *spec.xRange : autoRange(spec, false, std::nullopt);
  std::tie(m_yMin, m_yMax) = spec.yRange ? *spec.yRange : autoRange(spec, true, spec.xRange);

  // Vertical layout first: the y ticks depend on the area's height, the left margin on the
  // widest y tick label, and the x ticks on the resulting width.
  const int top = 2 * m.pad + (spec.title.empty() ? 0 : Metrics::glyphBox(m.titleScale) + 3 * m.pad / 2);
  const int bottom = m.frameWidth + m.tick + m.pad / 2 + m.cap() +
                     (spec.xLabel.empty() ? 0 : 3 * m.pad / 2 + Metrics::glyphBox(m.s)) + 3 * m.pad / 2;
  const int height = spec.height - top - bottom;
  m_yTicks = makeTicks(m_yMin, m_yMax, height / (5.0 * m.cap()), height, false, m.s, m.cap());
  int yTickWidth = 0;
  for (const std::string& label : m_yTicks.labels)
    yTickWidth = std::max(yTickWidth, Image::textWidth(label, m.s));
  const int left =
      std::max(spec.minAreaLeft, m.pad + (spec.yLabel.empty() ? 0 : Metrics::glyphBox(m.s) + 3 * m.pad / 2) +
                                     yTickWidth + m.pad / 2 + m.tick + m.frameWidth);
  const int right = 3 * m.pad;
  m_area = {left, top, spec.width - left - right, height};
  if (m_area.width < 16 || m_area.height < 16) {
    throw std::invalid_argument("PlotSpec: " + std::to_string(spec.width) + "x" +
                                std::to_string(spec.height) +
                                " pixels leave no room for the data next to the labels");
  }
  m_xTicks = makeTicks(m_xMin, m_xMax, m_area.width / (50.0 * m.s), m_area.width, true, m.s, 2 * m.pad);
  m_legend = placeLegend(spec, *this, m);
}

PlotFrame::Point PlotFrame::toPixel(double x, double y) const {
  return {m_area.x + (x - m_xMin) / (m_xMax - m_xMin) * m_area.width,
          m_area.y + m_area.height - (y - m_yMin) / (m_yMax - m_yMin) * m_area.height};
}

Image renderPlot(const PlotSpec& spec) {
  const PlotFrame frame(spec);
  const Metrics m(frame.textScale());
  Image image(spec.width, spec.height, kWhite);
  drawAxes(image, frame, m);
  image.setClip(frame.area());
  for (const Series& series : spec.series) drawSeries(image, frame, series);
  image.clearClip();
  drawTitleAndLabels(image, spec, frame, m);
  if (frame.legend()) drawLegend(image, spec, frame, m);
  return image;
}

void writePlotPng(const std::string& path, const PlotSpec& spec) { renderPlot(spec).savePng(path); }

}  // namespace hs::viz
