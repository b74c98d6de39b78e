// The raster primitives and the built-in bitmap font (raster.h, bitmap_font.h): text
// changes pixels exactly inside its box (a space none), scaling and turning map glyph
// pixels as documented, every printable ASCII character has a glyph of its own,
// non-ASCII text is substituted rather than crashing, lines cover and anti-alias as
// documented, and write_png round-trips through libpng.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "../io/image_test_util.h"
#include "../io/png_read_util.h"
#include "skylit/core/error.h"
#include "skylit/figures/bitmap_font.h"
#include "skylit/figures/raster.h"

namespace skylit {
namespace {

constexpr Rgb8 kInk{200, 30, 40};

// Pixels that differ from white, as (x, y).
std::set<std::pair<int, int>> changed(const Raster& r) {
  std::set<std::pair<int, int>> out;
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x)
      if (r.at(x, y) != kWhite) out.insert({x, y});
  return out;
}

TEST(TextRaster, CharacterInksPixelsOnlyInsideItsCell) {
  Raster r(40, 30);
  draw_text(r, 10, 5, "A", kInk);
  const auto ink = changed(r);
  ASSERT_GT(ink.size(), 10u);  // an "A" has many pixels
  for (auto [x, y] : ink) {
    EXPECT_GE(x, 10);
    EXPECT_LT(x, 10 + kFontCellWidth);
    EXPECT_GE(y, 5);
    EXPECT_LT(y, 5 + kFontCellHeight);
    EXPECT_EQ(r.at(x, y), kInk);  // bitmap text is not blended
  }
  EXPECT_EQ(text_width("A"), kFontCellWidth);
  EXPECT_EQ(text_height(), kFontCellHeight);
}

TEST(TextRaster, GlyphsAreUprightAndNotMirrored) {
  Raster r(20, 20);
  draw_text(r, 2, 3, "L", kInk);
  // "L": a stem down the left of the glyph (cell rows 1–7) and a foot along its bottom.
  for (int row = 1; row <= 7; ++row) EXPECT_EQ(r.at(2, 3 + row), kInk) << row;
  for (int column = 0; column < kGlyphWidth; ++column) EXPECT_EQ(r.at(2 + column, 3 + 7), kInk) << column;
  EXPECT_EQ(r.at(2 + kGlyphWidth - 1, 3 + 1), kWhite);
  EXPECT_EQ(r.at(2, 3), kWhite);  // cell row 0 is blank: the glyph starts at kGlyphTopInCell
}

TEST(TextRaster, SpaceInksNothingButAdvances) {
  Raster r(40, 30);
  draw_text(r, 3, 3, "   ", kInk);
  EXPECT_TRUE(changed(r).empty());
  EXPECT_EQ(text_width("   "), 3 * kFontCellWidth);
  // Text after a space starts one cell later.
  Raster a(40, 30), b(40, 30);
  draw_text(a, 3, 3, " x", kInk);
  draw_text(b, 3 + kFontCellWidth, 3, "x", kInk);
  EXPECT_EQ(a.rgb, b.rgb);
}

TEST(TextRaster, ScaleMagnifiesEveryGlyphPixelIntoABlock) {
  Raster one(20, 20), three(60, 40);
  draw_text(one, 0, 0, "Hg", kInk);
  draw_text(three, 0, 0, "Hg", kInk, 3);
  EXPECT_EQ(text_width("Hg", 3), 3 * text_width("Hg"));
  EXPECT_EQ(text_height(3), 3 * kFontCellHeight);
  for (int y = 0; y < 3 * kFontCellHeight; ++y)
    for (int x = 0; x < 3 * 2 * kFontCellWidth; ++x) ASSERT_EQ(three.at(x, y), one.at(x / 3, y / 3)) << x << "," << y;
}

TEST(TextRaster, TurnedTextIsTheNormalTextRotatedCounterClockwise) {
  const std::string text = "Ab1";
  const int w = text_width(text), h = text_height();
  Raster normal(w, h), turned(h + 10, w + 10);
  draw_text(normal, 0, 0, text, kInk);
  draw_text(turned, 4, w + 6, text, kInk, 1, TextDirection::up);
  // Normal pixel (u, v) lands on (x + v, y − 1 − u); nothing lands elsewhere.
  std::size_t inked = 0;
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u) {
      ASSERT_EQ(turned.at(4 + v, w + 6 - 1 - u), normal.at(u, v));
      inked += normal.at(u, v) == kInk;
    }
  EXPECT_EQ(changed(turned).size(), inked);
}

TEST(TextRaster, EveryPrintableAsciiCharacterHasADistinctGlyph) {
  std::set<GlyphRows> seen;
  const GlyphRows blank{};
  for (char32_t c = 33; c <= 126; ++c) {
    EXPECT_TRUE(font_has_glyph(c));
    EXPECT_NE(glyph_rows(c), blank) << char(c);
    EXPECT_NE(glyph_rows(c), glyph_rows(U'\u25A1')) << char(c) << " looks like the placeholder box";
    EXPECT_TRUE(seen.insert(glyph_rows(c)).second) << char(c) << " has the same glyph as another character";
  }
  EXPECT_EQ(glyph_rows(U' '), blank);
  for (char32_t c = 33; c <= 126; ++c)
    for (uint8_t row : glyph_rows(c)) EXPECT_LT(row, 1u << kGlyphWidth);
}

TEST(TextRaster, NonAsciiTextIsSubstitutedNotACrash) {
  EXPECT_EQ(font_characters("µm²"), U"\u00B5m^2");
  EXPECT_EQ(font_characters("μm"), U"\u00B5m");  // Greek mu drawn as the micro sign
  EXPECT_EQ(font_characters("W·m⁻²·sr⁻¹·nm⁻¹"), U"W\u00B7m^-2\u00B7sr^-1\u00B7nm^-1");
  EXPECT_EQ(font_characters("λ 380–780 nm, 17°"), U"\u03BB 380-780 nm, 17\u00B0");
  EXPECT_EQ(font_characters("aod₅₅₀"), U"aod_550");
  EXPECT_EQ(font_characters("é"), U"\u25A1");  // not in the font: the box
  EXPECT_EQ(font_characters("漢"), U"\u25A1");
  // Malformed UTF-8: each bad byte a box, and the text after it intact.
  EXPECT_EQ(font_characters("\xFF"
                            "a"),
            U"\u25A1a");
  EXPECT_EQ(font_characters("\xC3"), U"\u25A1");                      // truncated
  EXPECT_EQ(font_characters("\xC0\xAF"), U"\u25A1\u25A1");            // overlong '/'
  EXPECT_EQ(font_characters("\xED\xA0\x80"), U"\u25A1\u25A1\u25A1");  // a surrogate
  Raster r(200, 20);
  EXPECT_NO_THROW(draw_text(r, 0, 0, "µ² λ é \xFF\xFE 漢", kInk));
  EXPECT_FALSE(changed(r).empty());
  EXPECT_EQ(text_width("λ"), kFontCellWidth);
}

TEST(TextRaster, DrawingOutsideTheRasterClips) {
  Raster r(10, 10);
  EXPECT_NO_THROW(draw_text(r, -7, -3, "Wide text", kInk, 2));
  EXPECT_NO_THROW(draw_text(r, 5, 2, "up", kInk, 1, TextDirection::up));
  EXPECT_NO_THROW(draw_line(r, {-50, -50}, {60, 70}, kInk, 3));
  EXPECT_NO_THROW(fill_rect(r, -5, -5, 100, 100, kInk));
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x) EXPECT_EQ(r.at(x, y), kInk);
  EXPECT_THROW(r.at(10, 0), std::out_of_range);
}

TEST(TextRaster, LinesCoverTheirWidthAndBlendTheirEdges) {
  Raster r(40, 30);
  // Along the pixel boundary y = 10, 2 px wide: rows 9 and 10 fully, nothing else.
  draw_line(r, {2, 10}, {30, 10}, kInk, 2);
  EXPECT_EQ(r.at(15, 9), kInk);
  EXPECT_EQ(r.at(15, 10), kInk);
  EXPECT_EQ(r.at(15, 8), kWhite);
  EXPECT_EQ(r.at(15, 11), kWhite);
  // Centred on a pixel row, 2 px wide: the row fully, half of each neighbour.
  Raster s(40, 30);
  draw_line(s, {2, 10.5}, {30, 10.5}, kBlack, 2);
  EXPECT_EQ(s.at(15, 10), kBlack);
  EXPECT_NEAR(s.at(15, 9).r, 128, 1);
  EXPECT_NEAR(s.at(15, 11).r, 128, 1);
  // A diagonal is anti-aliased: some pixels lie strictly between ink and paper.
  Raster d(40, 30);
  draw_line(d, {1, 2}, {37, 25}, kBlack, 1.5);
  int partial = 0;
  for (int y = 0; y < d.height; ++y)
    for (int x = 0; x < d.width; ++x) partial += d.at(x, y).r > 0 && d.at(x, y).r < 255;
  EXPECT_GT(partial, 20);
}

TEST(TextRaster, PolylineBreaksAtNonFinitePoints) {
  Raster r(60, 20);
  const double nan = std::nan("");
  const PointF points[] = {{2, 10}, {20, 10}, {nan, 10}, {40, 10}, {58, 10}};
  draw_polyline(r, points, kInk, 2);
  EXPECT_EQ(r.at(10, 10), kInk);
  EXPECT_EQ(r.at(30, 10), kWhite);  // the gap where the NaN is
  EXPECT_EQ(r.at(50, 10), kInk);
}

TEST(TextRaster, BlitCopiesAnImageAndClipsIt) {
  Raster r(3, 3);
  const std::vector<uint8_t> image{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};  // 2×2
  blit_rgb8(r, -1, 2, 2, 2, image);
  EXPECT_EQ(r.at(0, 2), (Rgb8{4, 5, 6}));  // the top-right pixel of the image
  EXPECT_EQ(r.at(1, 2), kWhite);
  EXPECT_EQ(changed(r).size(), 1u);
  EXPECT_THROW(blit_rgb8(r, 0, 0, 2, 3, image), std::invalid_argument);
}

TEST(TextRaster, WritePngRoundTripsAndRefusesOtherExtensions) {
  test::ScratchFolder dir("raster-png");
  Raster r(17, 9, {10, 20, 30});
  draw_text(r, 1, 0, "ok", kInk);
  write_png(r, dir / "figure.PNG");
  const Raster back = test::read_png_raster(dir / "figure.PNG");
  EXPECT_EQ(back.width, 17);
  EXPECT_EQ(back.height, 9);
  EXPECT_EQ(back.rgb, r.rgb);
  EXPECT_THROW(write_png(r, dir / "figure.jpg"), InputError);
  EXPECT_THROW(write_png(r, dir / "missing" / "figure.png"), InputError);
  EXPECT_EQ(test::listing(dir.path()), std::vector<std::string>{"figure.PNG"});
}

}  // namespace
}  // namespace skylit
