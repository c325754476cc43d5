// Image: PNG round trip and clear I/O errors, text, lines, markers, clipping, composition.
#include <gtest/gtest.h>

#include "thrown_message.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "viz/image.h"

namespace hs::viz {
namespace {

constexpr Rgb kRed{200, 30, 40};

std::string tempPath(const std::string& name) {
  return (std::filesystem::path(::testing::TempDir()) / name).string();
}

// Bounding box of the pixels that differ from white; empty Rect if none.
Rect inkBox(const Image& image) {
  int x0 = image.width(), y0 = image.height(), x1 = -1, y1 = -1;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      if (image.at(x, y) == kWhite) continue;
      x0 = std::min(x0, x);
      y0 = std::min(y0, y);
      x1 = std::max(x1, x);
      y1 = std::max(y1, y);
    }
  }
  return x1 < 0 ? Rect{} : Rect{x0, y0, x1 - x0 + 1, y1 - y0 + 1};
}

TEST(Image, PngRoundTripKeepsEveryPixel) {
  Image image(37, 23);
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      image.set(x, y,
                {static_cast<std::uint8_t>(x * 7), static_cast<std::uint8_t>(y * 11),
                 static_cast<std::uint8_t>((x * y) % 256)});
    }
  }
  const std::string path = tempPath("viz-roundtrip.png");
  image.savePng(path);
  const Image loaded = Image::loadPng(path);
  EXPECT_EQ(loaded.width(), 37);
  EXPECT_EQ(loaded.height(), 23);
  EXPECT_EQ(loaded.pixels(), image.pixels());
}

TEST(Image, UnwritablePathThrowsNamingThePath) {
  const Image image(4, 4);
  const std::string message = hs::testing::thrownMessage<std::exception>([&] { image.savePng("/nonexistent-dir/x.png"); });
  EXPECT_NE(message.find("cannot write PNG '/nonexistent-dir/x.png'"), std::string::npos) << message;
  EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
}

TEST(Image, UnreadableOrInvalidPngThrowsNamingThePath) {
  EXPECT_NE(hs::testing::thrownMessage<std::exception>([] {
              Image::loadPng("/nonexistent-dir/x.png");
            }).find("cannot read PNG '/nonexistent-dir/x.png'"),
            std::string::npos);
  const std::string path = tempPath("viz-not-a-png.png");
  std::ofstream(path) << "this is text, not an image";
  EXPECT_NE(hs::testing::thrownMessage<std::exception>([&] { Image::loadPng(path); }).find("cannot read PNG '" + path + "'"), std::string::npos);
}

TEST(Image, AtOutsideThrowsAndSetOutsideIsIgnored) {
  Image image(3, 3);
  EXPECT_THROW((void)image.at(3, 0), std::out_of_range);
  EXPECT_THROW((void)image.at(0, -1), std::out_of_range);
  image.set(-1, 5, kRed);
  image.fillRect({-10, -10, 11, 11}, kRed);  // only (0, 0) is inside
  EXPECT_EQ(image.at(0, 0), kRed);
  EXPECT_EQ(image.at(1, 0), kWhite);
  EXPECT_EQ(image.at(0, 1), kWhite);
}

TEST(Image, TextChangesPixelsOnlyWithinItsWidthAndLine) {
  for (const int scale : {1, 2, 3}) {
    Image image(300, 60);
    const std::string text = "Hello 123";
    image.drawText(10, 5, text, scale, kBlack);
    const Rect ink = inkBox(image);
    ASSERT_FALSE(ink.empty()) << "scale " << scale;
    const int width = Image::textWidth(text, scale);
    EXPECT_EQ(ink.x, 10);
    EXPECT_EQ(ink.y, 5);
    // The advance includes the one-font-pixel gap after the last glyph.
    EXPECT_LE(ink.x + ink.width, 10 + width);
    EXPECT_GE(ink.x + ink.width, 10 + width - 2 * scale);
    // Capitals and digits, no descenders: exactly the cap height.
    EXPECT_EQ(ink.height, Image::capHeight(scale));
  }
}

TEST(Image, TextWidthIsAdditiveScalesAndUsesTheWidestLine) {
  EXPECT_EQ(Image::textWidth("", 2), 0);
  EXPECT_EQ(Image::textWidth("Pressure", 2) + Image::textWidth(" (mmHg)", 2),
            Image::textWidth("Pressure (mmHg)", 2));
  EXPECT_EQ(Image::textWidth("abc", 3) * 2, Image::textWidth("abc", 2) * 3);
  EXPECT_EQ(Image::textWidth("ab\nabcd\nc", 1), Image::textWidth("abcd", 1));
  // Bytes outside printable ASCII (here UTF-8 'é' and a control byte) print as '?'.
  EXPECT_EQ(Image::textWidth("\xc3\xa9\x01", 1), Image::textWidth("???", 1));
  Image image(100, 30);
  image.drawText(2, 2, "\xc3\xa9\x01~", 2, kBlack);
  EXPECT_FALSE(inkBox(image).empty());
}

TEST(Image, LineColoursItsEndpointsAndNothingFarAway) {
  Image image(64, 48);
  image.drawLine(10.5, 10.5, 50.5, 30.5, kRed, 3.0);
  EXPECT_EQ(image.at(10, 10), kRed);
  EXPECT_EQ(image.at(50, 30), kRed);
  EXPECT_EQ(image.at(30, 20), kRed);  // midpoint
  EXPECT_EQ(image.at(10, 30), kWhite);
  EXPECT_EQ(image.at(50, 10), kWhite);
  const Rect ink = inkBox(image);
  EXPECT_GE(ink.x, 8);
  EXPECT_LE(ink.x + ink.width, 53);
}

TEST(Image, ThinHorizontalAndSteepLinesAreOnePixelWide) {
  Image image(40, 40);
  image.drawLine(5.5, 20.5, 30.5, 20.5, kRed, 1.0);
  for (int x = 5; x <= 30; ++x) EXPECT_EQ(image.at(x, 20), kRed) << x;
  EXPECT_EQ(image.at(15, 19), kWhite);
  EXPECT_EQ(image.at(15, 21), kWhite);
  image.drawLine(35.5, 2.5, 35.5, 38.5, kBlack, 1.0);
  for (int y = 2; y <= 38; ++y) EXPECT_EQ(image.at(35, y), kBlack) << y;
  EXPECT_EQ(image.at(34, 20), kWhite);
}

TEST(Image, LinesClipAndSurviveHugeOrNonFiniteCoordinates) {
  Image image(20, 20);
  image.setClip({5, 5, 10, 10});
  image.drawLine(-1e12, 10.5, 1e12, 10.5, kRed, 2.0);
  image.drawLine(0.0, 0.0, std::numeric_limits<double>::quiet_NaN(), 5.0, kRed, 2.0);
  image.clearClip();
  // Thickness 2 centred on row 10 covers it fully and rows 9 and 11 by half.
  EXPECT_EQ(inkBox(image), (Rect{5, 9, 10, 3}));
  EXPECT_EQ(image.at(7, 10), kRed);
}

TEST(Image, MarkersCoverTheirCentreAndStayInsideTheirRadius) {
  for (const MarkerShape shape : {MarkerShape::Circle, MarkerShape::Square, MarkerShape::Cross}) {
    Image image(40, 40);
    image.drawMarker(20.5, 20.5, shape, 5.0, kRed);
    EXPECT_EQ(image.at(20, 20), kRed);
    const Rect ink = inkBox(image);
    EXPECT_GE(ink.x, 20 - 6);
    EXPECT_GE(ink.y, 20 - 6);
    EXPECT_LE(ink.x + ink.width, 21 + 6);
    EXPECT_LE(ink.y + ink.height, 21 + 6);
  }
  Image image(40, 40);
  image.drawMarker(20.5, 20.5, MarkerShape::Cross, 5.0, kRed);
  EXPECT_EQ(image.at(20, 16), kWhite);  // a cross (x) leaves the space above its centre empty
}

TEST(Image, BlitComposesAndClips) {
  Image tile(4, 3, kRed);
  tile.set(0, 0, kBlack);
  Image sheet(10, 10);
  sheet.blit(tile, 2, 5);
  sheet.blit(tile, 8, -1);  // partly outside: top row and right columns dropped
  EXPECT_EQ(sheet.at(2, 5), kBlack);
  EXPECT_EQ(sheet.at(5, 7), kRed);
  EXPECT_EQ(sheet.at(6, 7), kWhite);
  EXPECT_EQ(sheet.at(2, 8), kWhite);
  EXPECT_EQ(sheet.at(8, 0), kRed);
  EXPECT_EQ(sheet.at(9, 1), kRed);
  EXPECT_EQ(sheet.at(8, 2), kWhite);
}

TEST(Image, RotationCounterClockwiseMovesTopRightToTopLeft) {
  Image image(3, 2);
  image.set(2, 0, kRed);
  image.set(0, 1, kBlack);
  const Image rotated = image.rotatedCounterClockwise();
  EXPECT_EQ(rotated.width(), 2);
  EXPECT_EQ(rotated.height(), 3);
  EXPECT_EQ(rotated.at(0, 0), kRed);
  EXPECT_EQ(rotated.at(1, 2), kBlack);
}

}  // namespace
}  // namespace hs::viz
