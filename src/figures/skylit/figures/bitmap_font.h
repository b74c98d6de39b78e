// The built-in bitmap font for labels in plots and contact sheets, so that drawing
// text needs no font library and gives the same pixels everywhere. Glyphs are 5×9
// pixels (capitals and digits 7 rows high, 2 rows of descenders) in a 6×11 cell. It
// covers printable ASCII and a few symbols that units and labels use (° µ λ · × ± Δ ≈);
// other text is mapped onto those (superscript ² → "^2", − → "-") or drawn as a box.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace skylit {

inline constexpr int kGlyphWidth = 5;       // pixels of a glyph's design
inline constexpr int kGlyphHeight = 9;      // rows 0–6 above the baseline, 7–8 below
inline constexpr int kFontCellWidth = 6;    // advance per character at scale 1
inline constexpr int kFontCellHeight = 11;  // line height at scale 1
inline constexpr int kGlyphTopInCell = 1;   // glyph row 0 is cell row 1

// One glyph, row 0 at the top; in each row bit (kGlyphWidth − 1 − c) is column c.
using GlyphRows = std::array<uint8_t, kGlyphHeight>;

// The glyph of `c`; characters the font lacks get the placeholder box (U+25A1).
const GlyphRows& glyph_rows(char32_t c);

// Whether the font has a glyph of its own for `c`.
bool font_has_glyph(char32_t c);

// UTF-8 text as the characters the font will draw: superscript runs become '^' and the
// plain characters ("m⁻²" → "m^-2"), subscript runs '_' likewise, typographic dashes,
// quotes and spaces their ASCII forms, Greek μ the micro sign, a tab a space; anything
// else the font lacks, and every byte of malformed UTF-8, becomes the box U+25A1.
std::u32string font_characters(std::string_view utf8);

}  // namespace skylit
