#include "contact_sheet.h"

#include <algorithm>

namespace hs::app {
namespace {

const char* viewCaption(render::View view) {
  switch (view) {
    case render::View::Front: return "front (three-chamber plane)";
    case render::View::Left: return "left (from -x, lateral side)";
    case render::View::Right: return "right (from +x, septal side)";
    case render::View::Top: return "top (onto the base)";
  }
  return "";
}

std::string fitText(std::string text, int width, int scale) {
  while (text.size() > 3 && viz::Image::textWidth(text, scale) > width) text = text.substr(0, text.size() - 4) + "...";
  return text;
}

}  // namespace

viz::Image shrink(const viz::Image& image, int factor) {
  if (factor <= 1) return image;
  viz::Image small(image.width() / factor, image.height() / factor);
  for (int y = 0; y < small.height(); ++y)
    for (int x = 0; x < small.width(); ++x) {
      int r = 0, g = 0, b = 0;
      for (int dy = 0; dy < factor; ++dy)
        for (int dx = 0; dx < factor; ++dx) {
          const viz::Rgb c = image.at(x * factor + dx, y * factor + dy);
          r += c.r, g += c.g, b += c.b;
        }
      const int n = factor * factor;
      small.set(x, y, {std::uint8_t(r / n), std::uint8_t(g / n), std::uint8_t(b / n)});
    }
  return small;
}

viz::Image contactSheet(const std::string& title, const std::vector<std::string>& rowLabels,
                        const std::vector<render::View>& views, const std::vector<std::vector<viz::Image>>& cells,
                        const std::string& footer) {
  const int cellW = cells[0][0].width(), cellH = cells[0][0].height();
  const int scale = 2, gap = 8, margin = 16;
  const int labelW = viz::Image::textWidth("t = 00.000 s", scale) + gap;
  const int titleH = viz::Image::lineHeight(3) + gap, headerH = viz::Image::lineHeight(scale) + gap;
  const int footerH = viz::Image::lineHeight(scale) + gap;
  const int cols = int(views.size()), rows = int(rowLabels.size());
  const int width = std::max(2 * margin + labelW + cols * cellW + (cols - 1) * gap, 480);
  const int height = 2 * margin + titleH + headerH + rows * cellH + (rows - 1) * gap + footerH;
  viz::Image sheet(width, height, {255, 255, 255});
  const viz::Rgb ink{30, 30, 40};
  sheet.drawText(margin, margin, fitText(title, width - 2 * margin, 3), 3, ink);
  const int top = margin + titleH + headerH, left = margin + labelW;
  for (int c = 0; c < cols; ++c) {
    const std::string caption = fitText(viewCaption(views[c]), cellW, scale);
    const int x = left + c * (cellW + gap) + (cellW - viz::Image::textWidth(caption, scale)) / 2;
    sheet.drawText(x, margin + titleH, caption, scale, ink);
  }
  for (int r = 0; r < rows; ++r) {
    const int y = top + r * (cellH + gap);
    sheet.drawText(margin, y + cellH / 2 - viz::Image::capHeight(scale) / 2, rowLabels[r], scale, ink);
    for (int c = 0; c < cols; ++c) {
      sheet.blit(cells[r][c], left + c * (cellW + gap), y);
      sheet.strokeRect({left + c * (cellW + gap) - 1, y - 1, cellW + 2, cellH + 2}, {170, 175, 185});
    }
  }
  sheet.drawText(margin, height - margin - viz::Image::lineHeight(scale) + gap, fitText(footer, width - 2 * margin, scale),
                 scale, {80, 80, 90});
  return sheet;
}

}  // namespace hs::app
