#include "render/vortex_cut.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hs::render {
namespace {

constexpr viz::Rgb kNoBlood{200, 200, 200};
constexpr viz::Rgb kInk{30, 30, 40};
constexpr viz::Rgb kArrow{20, 20, 20};
constexpr viz::Rgb kMitral{0, 140, 60};
constexpr viz::Rgb kAxis{120, 60, 160};
constexpr viz::Rgb kLeaflet{200, 160, 0};

std::string fixed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

void drawArrow(viz::Image& image, double x0, double y0, double x1, double y1, double thickness) {
  image.drawLine(x0, y0, x1, y1, kArrow, thickness);
  const double dx = x1 - x0, dy = y1 - y0, length = std::hypot(dx, dy);
  if (length < 2) return;
  const double head = std::min(0.35 * length, 6.0), ux = dx / length, uy = dy / length;
  // Two barbs at 30 degrees either side of the shaft.
  const double c = std::cos(0.52), s = std::sin(0.52);
  image.drawLine(x1, y1, x1 - head * (c * ux - s * uy), y1 - head * (s * ux + c * uy), kArrow, thickness);
  image.drawLine(x1, y1, x1 - head * (c * ux + s * uy), y1 - head * (-s * ux + c * uy), kArrow, thickness);
}

// A ring (drawCircle fills): 32 chords.
void drawRing(viz::Image& image, double cx, double cy, double radius, viz::Rgb colour, double thickness) {
  constexpr int kChords = 32;
  for (int k = 0; k < kChords; ++k) {
    const double a0 = 2 * 3.14159265358979 * k / kChords, a1 = 2 * 3.14159265358979 * (k + 1) / kChords;
    image.drawLine(cx + radius * std::cos(a0), cy + radius * std::sin(a0), cx + radius * std::cos(a1),
                   cy + radius * std::sin(a1), colour, thickness);
  }
}

}  // namespace

viz::Rgb vorticityColour(double omega, double scale) {
  const double t = scale > 0 ? std::clamp(omega / scale, -1.0, 1.0) : 0.0;
  // White to red (t > 0) or white to blue (t < 0), linear in each channel.
  const auto mix = [](double a, double b, double f) { return std::uint8_t(std::lround(a + (b - a) * f)); };
  if (t >= 0) return {mix(255, 200, t), mix(255, 20, t), mix(255, 20, t)};
  return {mix(255, 20, -t), mix(255, 60, -t), mix(255, 200, -t)};
}

viz::Image drawEVortexCut(const cardiac::EVortexView& view, int height, const std::string& title) {
  const pbd::PlaneGrid& g = view.field.grid;
  const int px = std::max(1, height / std::max(1, g.rows));  // pixels per node
  const int textScale = std::max(1, height / 400);
  const int top = 3 * viz::Image::lineHeight(textScale), keyHeight = 4 * viz::Image::lineHeight(textScale);
  const int margin = 8 * textScale;
  const cardiac::EVortexSample& s = view.sample;
  const std::string figures =
      s.found ? "ring's cores at " + fixed(100 * s.position, 1) + "% of the long axis (" + fixed(s.depth * 1e3, 1) +
                    " of " + fixed(s.longAxis * 1e3, 1) + " mm) from the mitral plane; circulation " +
                    fixed(s.circulation, 4) + " m^2/s"
              : "no vortex core below the mitral plane";
  // The vorticity scale: the largest |omega| in the cut; the arrows' stride, about 12 pixels.
  double scale = 0;
  for (const double w : view.omega)
    if (!std::isnan(w)) scale = std::max(scale, std::abs(w));
  const int stride = std::max(2, int(std::lround(12.0 / px)));
  double fastest = 0;
  for (int j = 0; j < g.rows; j += stride)
    for (int i = 0; i < g.columns; i += stride)
      if (view.field.filled[g.index(i, j)])
        fastest = std::max(fastest, std::hypot(view.field.vu[g.index(i, j)], view.field.vv[g.index(i, j)]));
  const std::string key[3] = {
      "colour: vorticity out of the cut, red clockwise / blue anticlockwise as drawn, +-" + fixed(scale, 0) +
          " 1/s; grey: no blood (wall, outside)",
      "arrows: in-plane velocity (SPH average), longest " + fixed(fastest, 2) +
          " m/s; rings: vortex cores (half-peak |vorticity|), crossed: the ring's two cores",
      "cut: the plane of the long axis and the mitral orifice's centre (three-chamber view), " +
          fixed(g.spacing * 1e3, 1) + " mm grid" +
          (view.cut.leafletLength > 0 ? "; yellow: the open mitral leaflets" : "")};
  int textWidth = 0;
  for (const std::string& line : {title, figures, key[0], key[1], key[2]})
    textWidth = std::max(textWidth, viz::Image::textWidth(line, textScale));
  const int width = std::max(g.columns * px, textWidth) + 2 * margin;
  viz::Image image(width, top + g.rows * px + keyHeight + margin, viz::kWhite);
  const int left = (width - g.columns * px) / 2;
  for (int j = 0; j < g.rows; ++j)
    for (int i = 0; i < g.columns; ++i) {
      const std::size_t k = g.index(i, j);
      const double w = view.omega[k];
      const viz::Rgb colour = !std::isnan(w) ? vorticityColour(w, scale) : view.field.filled[k] ? viz::kWhite : kNoBlood;
      image.fillRect({left + i * px, top + j * px, px, px}, colour);
    }
  auto at = [&](double i, double j) { return std::pair{left + (i + 0.5) * px, top + (j + 0.5) * px}; };
  // Arrows every stride nodes (about two blood spacings), the fastest 1.8 strides long.
  const double perSpeed = fastest > 0 ? 1.8 * stride * px / fastest : 0;
  for (int j = 0; j < g.rows; j += stride)
    for (int i = 0; i < g.columns; i += stride) {
      const std::size_t k = g.index(i, j);
      if (!view.field.filled[k]) continue;
      const auto [x, y] = at(i, j);
      drawArrow(image, x, y, x + view.field.vu[k] * perSpeed, y + view.field.vv[k] * perSpeed, std::max(1.0, px / 6.0));
    }
  // The mitral plane (depth 0) and the long axis, from the mitral plane to the apex.
  const cardiac::LongAxisCut& cut = view.cut;
  const double jMitral = -cut.depth(g.origin) / g.spacing;
  const double iAxis = g.u.dot(cut.axisAtMitralPlane - g.origin) / g.spacing;
  {
    const auto [x0, y] = at(-0.5, jMitral);
    const auto [x1, y1] = at(g.columns - 0.5, jMitral);
    image.drawLine(x0, y, x1, y1, kMitral, 2.0 * textScale);
    image.drawText(int(x0) + 2, int(y) - viz::Image::lineHeight(textScale), "mitral plane", textScale, kMitral);
  }
  {
    const auto [x, y0] = at(iAxis, jMitral);
    const auto [x1, y1] = at(iAxis, jMitral + cut.longAxis / g.spacing);
    image.drawLine(x, y0, x1, y1, kAxis, 2.0 * textScale);
    image.drawMarker(x1, y1, viz::MarkerShape::Square, 3.0 * textScale, kAxis);
    image.drawText(int(x1) + 6, int(y1) - viz::Image::lineHeight(textScale), "apex (long axis)", textScale, kAxis);
  }
  // The open mitral leaflets where the cut crosses them: two lines down from the orifice's rim.
  if (cut.leafletLength > 0) {
    for (const double side : {-1.0, 1.0}) {
      const pbd::Vec3d rim = cut.mitralCentre + side * cut.mitralRadius * cut.across;
      const double i = g.u.dot(rim - g.origin) / g.spacing;
      const auto [x, y0] = at(i, jMitral);
      const auto [x1, y1] = at(i, jMitral + cut.leafletLength / g.spacing);
      image.drawLine(x, y0, x1, y1, kLeaflet, 3.0 * textScale);
    }
  }
  // Every core thin, the ring's two thick and named with their depth.
  for (std::size_t c = 0; c < view.cores.size(); ++c) {
    const pbd::VortexCore& core = view.cores[c];
    const auto [x, y] = at(core.i, core.j);
    const bool ring = int(c) == view.ring[0] || int(c) == view.ring[1];
    const double radius = std::max(4.0, std::sqrt(double(core.nodes) / 3.14159) * px);
    drawRing(image, x, y, radius, ring ? viz::kBlack : kInk, ring ? 2.5 : 1.0);
    if (!ring) continue;
    image.drawMarker(x, y, viz::MarkerShape::Cross, 3.0 * textScale, viz::kBlack);
    const double share = cut.longAxis > 0 ? cut.depth(core.position) / cut.longAxis : 0;
    image.drawText(int(x + radius) + 3, int(y) - 3 * textScale, fixed(100 * share, 0) + "%", textScale, viz::kBlack);
  }
  image.drawText(margin, margin / 2, title, textScale, kInk);
  image.drawText(margin, margin / 2 + viz::Image::lineHeight(textScale), figures, textScale, kInk);
  const int keyTop = top + g.rows * px + margin / 2;
  for (int k = 0; k < 3; ++k) image.drawText(margin, keyTop + k * viz::Image::lineHeight(textScale), key[k], textScale, kInk);
  return image;
}

}  // namespace hs::render
