// Text on a Raster (raster.h) in the built-in bitmap font (bitmap_font.h): each glyph
// pixel becomes a scale × scale block, with no anti-aliasing, so text is crisp and the
// same bytes on every machine.
#include <algorithm>
#include <string>

#include "skylit/figures/bitmap_font.h"
#include "skylit/figures/raster.h"

namespace skylit {

int text_width(std::string_view utf8, int scale) {
  return static_cast<int>(font_characters(utf8).size()) * kFontCellWidth * std::max(scale, 1);
}

int text_height(int scale) { return kFontCellHeight * std::max(scale, 1); }

void draw_text(Raster& raster, int x, int y, std::string_view utf8, Rgb8 colour, int scale, TextDirection direction) {
  scale = std::max(scale, 1);
  const std::u32string text = font_characters(utf8);
  // (u, v): position in the unturned text's box, u along the line and v down the line.
  const auto plot = [&](int u, int v) {
    if (direction == TextDirection::right)
      fill_rect(raster, x + u, y + v, scale, scale, colour);
    else  // turned counter-clockwise: along the line is up, down the line is right
      fill_rect(raster, x + v, y - u - scale, scale, scale, colour);
  };
  for (std::size_t k = 0; k < text.size(); ++k) {
    const GlyphRows& glyph = glyph_rows(text[k]);
    const int u0 = static_cast<int>(k) * kFontCellWidth * scale;
    for (int r = 0; r < kGlyphHeight; ++r)
      for (int c = 0; c < kGlyphWidth; ++c)
        if (glyph[r] >> (kGlyphWidth - 1 - c) & 1) plot(u0 + c * scale, (kGlyphTopInCell + r) * scale);
  }
}

}  // namespace skylit
