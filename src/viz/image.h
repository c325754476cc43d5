#pragma once
// A small RGB8 raster image with the drawing operations that validation plots and contact sheets
// need: rectangles, anti-aliased thick lines, markers, a bitmap font (stb_easy_font), blitting,
// and PNG input/output (stb_image / stb_image_write from Debian's libstb).
//
// Coordinates are pixels, x to the right, y downwards, (0, 0) the top-left pixel. Floating-point
// coordinates address the continuous plane: pixel (i, j) covers [i, i+1) x [j, j+1), so its
// centre is (i + 0.5, j + 0.5).
//
// Every drawing operation (including set() and blit()) clips to the clip rectangle, which is the
// whole image unless setClip() narrowed it; reading (at()) is never clipped.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace hs::viz {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

inline constexpr Rgb kWhite{255, 255, 255};
inline constexpr Rgb kBlack{0, 0, 0};

// Pixel rectangle: columns [x, x + width), rows [y, y + height).
struct Rect {
  int x = 0, y = 0, width = 0, height = 0;
  bool contains(int px, int py) const { return px >= x && px < x + width && py >= y && py < y + height; }
  bool empty() const { return width <= 0 || height <= 0; }
  friend bool operator==(const Rect&, const Rect&) = default;
};

enum class MarkerShape { Circle, Square, Cross };

class Image {
 public:
  Image() = default;
  // Throws std::invalid_argument for negative sizes.
  Image(int width, int height, Rgb background = kWhite);

  int width() const { return m_width; }
  int height() const { return m_height; }
  bool contains(int x, int y) const { return x >= 0 && x < m_width && y >= 0 && y < m_height; }
  // Row-major RGB8, 3 bytes per pixel, no padding.
  const std::vector<std::uint8_t>& pixels() const { return m_pixels; }

  // Throws std::out_of_range outside the image.
  Rgb at(int x, int y) const;
  // Silently ignores pixels outside the clip rectangle, so drawing code need not check.
  void set(int x, int y, Rgb colour);
  // colour * coverage + old * (1 - coverage); coverage in [0, 1] (anti-aliasing).
  void blend(int x, int y, Rgb colour, double coverage);

  // Drawing is restricted to clip ∩ image until clearClip().
  void setClip(const Rect& clip);
  void clearClip();
  Rect clip() const { return m_clip; }

  void fill(Rgb colour);
  void fillRect(const Rect& rect, Rgb colour);
  // Outline lineWidth pixels wide, drawn inside rect.
  void strokeRect(const Rect& rect, Rgb colour, int lineWidth = 1);
  // Anti-aliased segment with round caps; thickness in pixels. Non-finite input draws nothing.
  void drawLine(double x0, double y0, double x1, double y1, Rgb colour, double thickness = 1.0);
  // Anti-aliased filled disc.
  void drawCircle(double cx, double cy, double radius, Rgb colour);
  // A marker centred on (cx, cy) fitting in a circle of the given radius.
  void drawMarker(double cx, double cy, MarkerShape shape, double radius, Rgb colour);

  // Bitmap text (stb_easy_font, ASCII; other bytes print as '?'; '\n' starts a new line).
  // (x, y) is the top-left corner; each font pixel becomes a pixelScale x pixelScale block.
  void drawText(int x, int y, std::string_view text, int pixelScale, Rgb colour);
  // Advance width of the widest line in image pixels (includes the one-font-pixel gap after the
  // last glyph), so drawText covers columns [x, x + textWidth).
  static int textWidth(std::string_view text, int pixelScale);
  // Height of capital letters and digits in image pixels (for centring text vertically).
  static int capHeight(int pixelScale);
  // Distance between baselines of consecutive lines in image pixels.
  static int lineHeight(int pixelScale);

  // Copies src with its top-left corner at (x, y), clipped.
  void blit(const Image& src, int x, int y);
  // The image turned a quarter turn counter-clockwise (for a vertical axis label).
  Image rotatedCounterClockwise() const;

  // Throws std::runtime_error("cannot write PNG '<path>': <reason>").
  void savePng(const std::string& path) const;
  // Any image stb_image reads, converted to RGB8. Throws std::runtime_error("cannot read PNG
  // '<path>': <reason>").
  static Image loadPng(const std::string& path);

 private:
  std::size_t index(int x, int y) const { return (static_cast<std::size_t>(y) * m_width + x) * 3; }

  int m_width = 0;
  int m_height = 0;
  std::vector<std::uint8_t> m_pixels;
  Rect m_clip;
};

}  // namespace hs::viz
