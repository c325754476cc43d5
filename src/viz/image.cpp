#include "viz/image.h"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <numbers>
#include <stdexcept>

// Debian's libstb already contains the stb_image and stb_image_write implementations, so only the
// declarations are included here. stb_easy_font is header-only (all functions static); it is
// included in this one file only, and its C-style code is exempt from the project's warnings.
#include <stb_image.h>
#include <stb_image_write.h>
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wfloat-conversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wcast-align"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

namespace hs::viz {
namespace {

Rect intersect(const Rect& a, const Rect& b) {
  const int x0 = std::max(a.x, b.x), y0 = std::max(a.y, b.y);
  const int x1 = std::min(a.x + a.width, b.x + b.width), y1 = std::min(a.y + a.height, b.y + b.height);
  return {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
}

// Liang–Barsky: clips the segment to [lo, hi] in place; false if nothing remains. Done before
// rasterising so that points far outside the image (a plot with a fixed range) cost nothing and
// never overflow an int.
bool clipSegment(double& x0, double& y0, double& x1, double& y1, double loX, double loY, double hiX,
                 double hiY) {
  const double dx = x1 - x0, dy = y1 - y0;
  double t0 = 0.0, t1 = 1.0;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {x0 - loX, hiX - x0, y0 - loY, hiY - y0};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0.0) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
  }
  if (t0 > t1) return false;
  const double nx0 = x0 + t0 * dx, ny0 = y0 + t0 * dy;
  x1 = x0 + t1 * dx;
  y1 = y0 + t1 * dy;
  x0 = nx0;
  y0 = ny0;
  return true;
}

// Pixels [first, last] touched by the interval [lo, hi], limited to [clipLo, clipHi); empty when
// first > last. Clamping in double before converting keeps huge coordinates from overflowing.
struct PixelSpan {
  int first, last;
};
PixelSpan pixelSpan(double lo, double hi, int clipLo, int clipHi) {
  const double first = std::clamp(std::floor(lo), static_cast<double>(clipLo), static_cast<double>(clipHi));
  const double last =
      std::clamp(std::floor(hi), static_cast<double>(clipLo - 1), static_cast<double>(clipHi - 1));
  return {static_cast<int>(first), static_cast<int>(last)};
}

double distanceToSegment(double px, double py, double x0, double y0, double x1, double y1) {
  const double dx = x1 - x0, dy = y1 - y0;
  const double lengthSquared = dx * dx + dy * dy;
  double t = lengthSquared > 0.0 ? ((px - x0) * dx + (py - y0) * dy) / lengthSquared : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(px - (x0 + t * dx), py - (y0 + t * dy));
}

// stb_easy_font indexes a table with (char - 32), so anything outside printable ASCII must go.
std::string printableAscii(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    if (c != '\n' && (c < 32 || c > 126)) c = '?';
  }
  return out;
}

}  // namespace

Image::Image(int width, int height, Rgb background) : m_width(width), m_height(height) {
  if (width < 0 || height < 0) {
    throw std::invalid_argument("Image: negative size " + std::to_string(width) + "x" +
                                std::to_string(height));
  }
  m_pixels.resize(static_cast<std::size_t>(width) * height * 3);
  m_clip = {0, 0, width, height};
  fill(background);
}

Rgb Image::at(int x, int y) const {
  if (!contains(x, y)) {
    throw std::out_of_range("Image::at(" + std::to_string(x) + ", " + std::to_string(y) + ") outside " +
                            std::to_string(m_width) + "x" + std::to_string(m_height));
  }
  const std::size_t i = index(x, y);
  return {m_pixels[i], m_pixels[i + 1], m_pixels[i + 2]};
}

void Image::set(int x, int y, Rgb colour) {
  if (!m_clip.contains(x, y)) return;
  const std::size_t i = index(x, y);
  m_pixels[i] = colour.r;
  m_pixels[i + 1] = colour.g;
  m_pixels[i + 2] = colour.b;
}

void Image::blend(int x, int y, Rgb colour, double coverage) {
  if (!m_clip.contains(x, y) || !(coverage > 0.0)) return;
  if (coverage >= 1.0) {
    set(x, y, colour);
    return;
  }
  const std::size_t i = index(x, y);
  const auto mix = [coverage](std::uint8_t from, std::uint8_t to) {
    return static_cast<std::uint8_t>(std::lround(from + (to - from) * coverage));
  };
  m_pixels[i] = mix(m_pixels[i], colour.r);
  m_pixels[i + 1] = mix(m_pixels[i + 1], colour.g);
  m_pixels[i + 2] = mix(m_pixels[i + 2], colour.b);
}

void Image::setClip(const Rect& clip) { m_clip = intersect(clip, {0, 0, m_width, m_height}); }

void Image::clearClip() { m_clip = {0, 0, m_width, m_height}; }

void Image::fill(Rgb colour) { fillRect({0, 0, m_width, m_height}, colour); }

void Image::fillRect(const Rect& rect, Rgb colour) {
  const Rect r = intersect(rect, m_clip);
  for (int y = r.y; y < r.y + r.height; ++y) {
    for (int x = r.x; x < r.x + r.width; ++x) set(x, y, colour);
  }
}

void Image::strokeRect(const Rect& rect, Rgb colour, int lineWidth) {
  const int w = std::min({lineWidth, rect.width, rect.height});
  fillRect({rect.x, rect.y, rect.width, w}, colour);
  fillRect({rect.x, rect.y + rect.height - w, rect.width, w}, colour);
  fillRect({rect.x, rect.y, w, rect.height}, colour);
  fillRect({rect.x + rect.width - w, rect.y, w, rect.height}, colour);
}

void Image::drawLine(double x0, double y0, double x1, double y1, Rgb colour, double thickness) {
  if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1) ||
      !std::isfinite(thickness) || !(thickness > 0.0) || m_clip.empty()) {
    return;
  }
  const double r = thickness / 2.0;
  // Pixels with coverage lie within r + 0.5 of the segment; anything beyond r + 1 of the clip
  // rectangle can be cut off without changing a single pixel.
  if (!clipSegment(x0, y0, x1, y1, m_clip.x - r - 1.0, m_clip.y - r - 1.0, m_clip.x + m_clip.width + r + 1.0,
                   m_clip.y + m_clip.height + r + 1.0)) {
    return;
  }
  // Walk the major axis u; on each step only a band of the minor axis v can be covered: a point
  // within r of the segment is within 2r (|slope| <= 1) of the centre line's v at the same u.
  const bool steep = std::abs(y1 - y0) > std::abs(x1 - x0);
  const double u0 = steep ? y0 : x0, v0 = steep ? x0 : y0, u1 = steep ? y1 : x1, v1 = steep ? x1 : y1;
  const int uClipLo = steep ? m_clip.y : m_clip.x, uClipHi = uClipLo + (steep ? m_clip.height : m_clip.width);
  const int vClipLo = steep ? m_clip.x : m_clip.y, vClipHi = vClipLo + (steep ? m_clip.width : m_clip.height);
  const PixelSpan uSpan = pixelSpan(std::min(u0, u1) - r - 1.0, std::max(u0, u1) + r + 1.0, uClipLo, uClipHi);
  for (int iu = uSpan.first; iu <= uSpan.last; ++iu) {
    const double uc = iu + 0.5;
    const double t = u1 != u0 ? std::clamp((uc - u0) / (u1 - u0), 0.0, 1.0) : 0.0;
    const double vLine = v0 + t * (v1 - v0);
    const PixelSpan vSpan = pixelSpan(vLine - 2.0 * r - 2.0, vLine + 2.0 * r + 2.0, vClipLo, vClipHi);
    for (int iv = vSpan.first; iv <= vSpan.last; ++iv) {
      const double coverage = r + 0.5 - distanceToSegment(uc, iv + 0.5, u0, v0, u1, v1);
      if (steep) {
        blend(iv, iu, colour, coverage);
      } else {
        blend(iu, iv, colour, coverage);
      }
    }
  }
}

void Image::drawCircle(double cx, double cy, double radius, Rgb colour) {
  if (!std::isfinite(cx) || !std::isfinite(cy) || !std::isfinite(radius) || !(radius > 0.0)) return;
  const PixelSpan xs = pixelSpan(cx - radius - 1.0, cx + radius + 1.0, m_clip.x, m_clip.x + m_clip.width);
  const PixelSpan ys = pixelSpan(cy - radius - 1.0, cy + radius + 1.0, m_clip.y, m_clip.y + m_clip.height);
  for (int y = ys.first; y <= ys.last; ++y) {
    for (int x = xs.first; x <= xs.last; ++x)
      blend(x, y, colour, radius + 0.5 - std::hypot(x + 0.5 - cx, y + 0.5 - cy));
  }
}

void Image::drawMarker(double cx, double cy, MarkerShape shape, double radius, Rgb colour) {
  if (!std::isfinite(cx) || !std::isfinite(cy) || !std::isfinite(radius) || !(radius > 0.0)) return;
  switch (shape) {
    case MarkerShape::Circle:
      drawCircle(cx, cy, radius, colour);
      break;
    case MarkerShape::Square: {
      // A square of the same area as the circle looks the same size; coverage is the exact
      // overlap of each pixel with the square, so the edges are anti-aliased too.
      const double half = radius * std::sqrt(std::numbers::pi) / 2.0;
      const auto overlap = [half](int pixel, double centre) {
        return std::clamp(std::min(pixel + 1.0, centre + half) - std::max(pixel * 1.0, centre - half), 0.0,
                          1.0);
      };
      const PixelSpan xs = pixelSpan(cx - half, cx + half, m_clip.x, m_clip.x + m_clip.width);
      const PixelSpan ys = pixelSpan(cy - half, cy + half, m_clip.y, m_clip.y + m_clip.height);
      for (int y = ys.first; y <= ys.last; ++y) {
        for (int x = xs.first; x <= xs.last; ++x) blend(x, y, colour, overlap(x, cx) * overlap(y, cy));
      }
      break;
    }
    case MarkerShape::Cross: {
      const double arm = radius * 0.8;
      const double thickness = std::max(1.5, radius / 2.5);
      drawLine(cx - arm, cy - arm, cx + arm, cy + arm, colour, thickness);
      drawLine(cx - arm, cy + arm, cx + arm, cy - arm, colour, thickness);
      break;
    }
  }
}

void Image::drawText(int x, int y, std::string_view text, int pixelScale, Rgb colour) {
  if (text.empty() || pixelScale <= 0) return;
  std::string ascii = printableAscii(text);
  // stb_easy_font writes 4 vertices of 16 bytes (x, y, z floats + RGBA) per quad and silently
  // truncates when the buffer is full, so grow it until the output fits with room to spare.
  constexpr int kVertexBytes = 16, kQuadBytes = 4 * kVertexBytes;
  std::vector<unsigned char> buffer(ascii.size() * 8 * kQuadBytes + kQuadBytes);
  int quads = 0;
  for (;;) {
    quads = stb_easy_font_print(0.0f, 0.0f, ascii.data(), nullptr, buffer.data(),
                                static_cast<int>(buffer.size()));
    if (static_cast<std::size_t>(quads + 1) * kQuadBytes <= buffer.size()) break;
    buffer.resize(buffer.size() * 2);
  }
  for (int q = 0; q < quads; ++q) {
    float minX = 1e9f, minY = 1e9f, maxX = -1e9f, maxY = -1e9f;
    for (int v = 0; v < 4; ++v) {
      float xy[2];
      std::memcpy(xy, buffer.data() + q * kQuadBytes + v * kVertexBytes, sizeof xy);
      minX = std::min(minX, xy[0]);
      maxX = std::max(maxX, xy[0]);
      minY = std::min(minY, xy[1]);
      maxY = std::max(maxY, xy[1]);
    }
    // Glyph quads lie on the font's integer grid, so scaling by an integer keeps text crisp.
    fillRect({x + static_cast<int>(minX) * pixelScale, y + static_cast<int>(minY) * pixelScale,
              static_cast<int>(maxX - minX) * pixelScale, static_cast<int>(maxY - minY) * pixelScale},
             colour);
  }
}

int Image::textWidth(std::string_view text, int pixelScale) {
  std::string ascii = printableAscii(text);
  return stb_easy_font_width(ascii.data()) * pixelScale;
}

// stb_easy_font's capitals and digits span font rows 0..6 (lowercase descenders reach row 9);
// lines are 12 font pixels apart.
int Image::capHeight(int pixelScale) { return 7 * pixelScale; }

int Image::lineHeight(int pixelScale) { return 12 * pixelScale; }

void Image::blit(const Image& src, int x, int y) {
  const Rect target = intersect({x, y, src.width(), src.height()}, m_clip);
  for (int ty = target.y; ty < target.y + target.height; ++ty) {
    const std::size_t from = src.index(target.x - x, ty - y);
    std::copy_n(src.m_pixels.begin() + static_cast<std::ptrdiff_t>(from), target.width * 3,
                m_pixels.begin() + static_cast<std::ptrdiff_t>(index(target.x, ty)));
  }
}

Image Image::rotatedCounterClockwise() const {
  Image out(m_height, m_width);
  // Source column x becomes row (width - 1 - x): the top-right corner moves to the top-left.
  for (int y = 0; y < m_height; ++y) {
    for (int x = 0; x < m_width; ++x) out.set(y, m_width - 1 - x, at(x, y));
  }
  return out;
}

void Image::savePng(const std::string& path) const {
  const auto fail = [&path](const std::string& reason) {
    throw std::runtime_error("cannot write PNG '" + path + "': " + reason);
  };
  if (m_width == 0 || m_height == 0) fail("the image is empty");
  // Encode to memory first: stbi_write_png only returns 0 on failure, while fopen/fwrite give
  // the reason (no such directory, permission denied, disk full) through errno.
  struct Sink {
    std::vector<unsigned char> bytes;
    bool failed = false;
  } sink;
  const auto append = [](void* context, void* data, int size) {
    auto* s = static_cast<Sink*>(context);
    try {  // no exception may unwind through stb's C code
      const auto* begin = static_cast<const unsigned char*>(data);
      s->bytes.insert(s->bytes.end(), begin, begin + size);
    } catch (...) {
      s->failed = true;
    }
  };
  if (!stbi_write_png_to_func(append, &sink, m_width, m_height, 3, m_pixels.data(), m_width * 3) ||
      sink.failed) {
    fail("PNG encoding failed");
  }
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "wb"), &std::fclose);
  if (!file) fail(std::strerror(errno));
  const bool written = std::fwrite(sink.bytes.data(), 1, sink.bytes.size(), file.get()) == sink.bytes.size();
  const int writeError = errno;
  if (!written || std::fclose(file.release()) != 0) {
    const int error = written ? errno : writeError;
    std::remove(path.c_str());  // do not leave a truncated PNG behind
    fail(std::strerror(error));
  }
}

Image Image::loadPng(const std::string& path) {
  const auto fail = [&path](const std::string& reason) {
    throw std::runtime_error("cannot read PNG '" + path + "': " + reason);
  };
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) fail(std::strerror(errno));
  std::vector<unsigned char> bytes;
  unsigned char chunk[65536];
  while (const std::size_t n = std::fread(chunk, 1, sizeof chunk, file.get()))
    bytes.insert(bytes.end(), chunk, chunk + n);
  if (std::ferror(file.get())) fail(std::strerror(errno));
  if (bytes.size() > static_cast<std::size_t>(INT_MAX)) fail("file too large");
  int width = 0, height = 0, channels = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> data(
      stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width, &height, &channels, 3),
      &stbi_image_free);
  if (!data) fail(stbi_failure_reason() ? stbi_failure_reason() : "unknown stb_image error");
  Image image(width, height);
  std::copy_n(data.get(), image.m_pixels.size(), image.m_pixels.begin());
  return image;
}

}  // namespace hs::viz
