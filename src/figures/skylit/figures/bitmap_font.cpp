// The glyph sheet of the built-in font (bitmap_font.h), drawn here for this project,
// and the mapping from Unicode text onto it. The sheet is kept as pictures ('#' = ink)
// so that a glyph can be read and corrected by eye; it is turned into bit rows at
// compile time, and a malformed row stops the build.
#include "skylit/figures/bitmap_font.h"

#include <cstddef>

#include "skylit/figures/utf8.h"

namespace skylit {
namespace {

// Blocks of 8 glyphs side by side, kGlyphHeight rows each: ASCII 32–126 in order, then
// the characters of kExtraCharacters.
constexpr const char* kSheet[] = {
    // ' '   '!'   '"'   '#'   '$'   '%'   '&'   '\''
    "..... ..#.. .#.#. .#.#. ..#.. ##... .##.. ..#..",
    "..... ..#.. .#.#. .#.#. .#### ##..# #..#. ..#..",
    "..... ..#.. .#.#. ##### #.#.. ...#. #.#.. .#...",
    "..... ..#.. ..... .#.#. .###. ..#.. .#... .....",
    "..... ..#.. ..... ##### ..#.# .#... #.#.# .....",
    "..... ..... ..... .#.#. ####. #..## #..#. .....",
    "..... ..#.. ..... .#.#. ..#.. ...## .##.# .....",
    "..... ..... ..... ..... ..... ..... ..... .....",
    "..... ..... ..... ..... ..... ..... ..... .....",

    // '('   ')'   '*'   '+'   ','   '-'   '.'   '/'
    "...#. .#... ..... ..... ..... ..... ..... ....#",
    "..#.. ..#.. ..#.. ..#.. ..... ..... ..... ....#",
    ".#... ...#. #.#.# ..#.. ..... ..... ..... ...#.",
    ".#... ...#. .###. ##### ..... .###. ..... ..#..",
    ".#... ...#. #.#.# ..#.. ..... ..... ..... .#...",
    "..#.. ..#.. ..#.. ..#.. .##.. ..... .##.. #....",
    "...#. .#... ..... ..... .##.. ..... .##.. #....",
    "..... ..... ..... ..... ..#.. ..... ..... .....",
    "..... ..... ..... ..... .#... ..... ..... .....",

    // '0'   '1'   '2'   '3'   '4'   '5'   '6'   '7'
    ".###. ..#.. .###. ##### ...#. ##### ..##. #####",
    "#...# .##.. #...# ...#. ..##. #.... .#... ....#",
    "#..## ..#.. ....# ..#.. .#.#. ####. #.... ...#.",
    "#.#.# ..#.. ...#. ...#. #..#. ....# ####. ..#..",
    "##..# ..#.. ..#.. ....# ##### ....# #...# .#...",
    "#...# ..#.. .#... #...# ...#. #...# #...# .#...",
    ".###. .###. ##### .###. ...#. .###. .###. .#...",
    "..... ..... ..... ..... ..... ..... ..... .....",
    "..... ..... ..... ..... ..... ..... ..... .....",

    // '8'   '9'   ':'   ';'   '<'   '='   '>'   '?'
    ".###. .###. ..... ..... ...#. ..... .#... .###.",
    "#...# #...# .##.. .##.. ..#.. ..... ..#.. #...#",
    "#...# #...# .##.. .##.. .#... ##### ...#. ....#",
    ".###. .#### ..... ..... #.... ..... ....# ...#.",
    "#...# ....# .##.. .##.. .#... ##### ...#. ..#..",
    "#...# ...#. .##.. .##.. ..#.. ..... ..#.. .....",
    ".###. .##.. ..... ..#.. ...#. ..... .#... ..#..",
    "..... ..... ..... .#... ..... ..... ..... .....",
    "..... ..... ..... ..... ..... ..... ..... .....",

    // '@'   'A'   'B'   'C'   'D'   'E'   'F'   'G'
    ".###. .###. ####. .###. ####. ##### ##### .###.",
    "#...# #...# #...# #...# #...# #.... #.... #...#",
    "#.### #...# #...# #.... #...# #.... #.... #....",
    "#.#.# ##### ####. #.... #...# ####. ####. #.###",
    "#.### #...# #...# #.... #...# #.... #.... #...#",
    "#.... #...# #...# #...# #...# #.... #.... #...#",
    ".###. #...# ####. .###. ####. ##### #.... .####",
    "..... ..... ..... ..... ..... ..... ..... .....",
    "..... ..... ..... ..... ..... ..... ..... .....",

    // 'H'   'I'   'J'   'K'   'L'   'M'   'N'   'O'
    "#...# .###. ..### #...# #.... #...# #...# .###.",
    "#...# ..#.. ...#. #..#. #.... ##.## #...# #...#",
    "#...# ..#.. ...#. #.#.. #.... #.#.# ##..# #...#",
    "##### ..#.. ...#. ##... #.... #.#.# #.#.# #...#",
    "#...# ..#.. ...#. #.#.. #.... #...# #..## #...#",
    "#...# ..#.. #..#. #..#. #.... #...# #...# #...#",
    "#...# .###. .##.. #...# ##### #...# #...# .###.",
    "..... ..... ..... ..... ..... ..... ..... .....",
    "..... ..... ..... ..... ..... ..... ..... .....",

    // 'P'   'Q'   'R'   'S'   'T'   'U'   'V'   'W'
    "####. .###. ####. .#### ##### #...# #...# #...#",
    "#...# #...# #...# #.... ..#.. #...# #...# #...#",
    "#...# #...# #...# #.... ..#.. #...# #...# #...#",
    "####. #...# ####. .###. ..#.. #...# #...# #.#.#",
    "#.... #.#.# #.#.. ....# ..#.. #...# #...# #.#.#",
    "#.... #..#. #..#. ....# ..#.. #...# .#.#. #.#.#",
    "#.... .##.# #...# ####. ..#.. .###. ..#.. .#.#.",
    "..... ..... ..... ..... ..... ..... ..... .....",
    "..... ..... ..... ..... ..... ..... ..... .....",

    // 'X'   'Y'   'Z'   '['   '\\'  ']'   '^'   '_'
    "#...# #...# ##### .###. #.... .###. ..#.. .....",
    "#...# #...# ....# .#... #.... ...#. .#.#. .....",
    ".#.#. .#.#. ...#. .#... .#... ...#. #...# .....",
    "..#.. ..#.. ..#.. .#... ..#.. ...#. ..... .....",
    ".#.#. ..#.. .#... .#... ...#. ...#. ..... .....",
    "#...# ..#.. #.... .#... ....# ...#. ..... .....",
    "#...# ..#.. ##### .###. ....# .###. ..... .....",
    "..... ..... ..... ..... ..... ..... ..... #####",
    "..... ..... ..... ..... ..... ..... ..... .....",

    // '`'   'a'   'b'   'c'   'd'   'e'   'f'   'g'
    ".#... ..... #.... ..... ....# ..... ..##. .....",
    "..#.. ..... #.... ..... ....# ..... .#..# .....",
    "..... .###. ####. .###. .#### .###. .#... .####",
    "..... ....# #...# #.... #...# #...# ###.. #...#",
    "..... .#### #...# #.... #...# ##### .#... #...#",
    "..... #...# #...# #...# #...# #.... .#... #...#",
    "..... .#### ####. .###. .#### .###. .#... .####",
    "..... ..... ..... ..... ..... ..... ..... ....#",
    "..... ..... ..... ..... ..... ..... ..... .###.",

    // 'h'   'i'   'j'   'k'   'l'   'm'   'n'   'o'
    "#.... ..#.. ...#. #.... .##.. ..... ..... .....",
    "#.... ..... ..... #.... ..#.. ..... ..... .....",
    "#.##. .##.. ..##. #..#. ..#.. ##.#. #.##. .###.",
    "##..# ..#.. ...#. #.#.. ..#.. #.#.# ##..# #...#",
    "#...# ..#.. ...#. ##... ..#.. #.#.# #...# #...#",
    "#...# ..#.. ...#. #.#.. ..#.. #.#.# #...# #...#",
    "#...# .###. ...#. #..#. .###. #.#.# #...# .###.",
    "..... ..... #..#. ..... ..... ..... ..... .....",
    "..... ..... .##.. ..... ..... ..... ..... .....",

    // 'p'   'q'   'r'   's'   't'   'u'   'v'   'w'
    "..... ..... ..... ..... .#... ..... ..... .....",
    "..... ..... ..... ..... .#... ..... ..... .....",
    "####. .#### #.##. .#### ###.. #...# #...# #...#",
    "#...# #...# ##..# #.... .#... #...# #...# #...#",
    "#...# #...# #.... .###. .#... #...# #...# #.#.#",
    "#...# #...# #.... ....# .#..# #..## .#.#. #.#.#",
    "####. .#### #.... ####. ..##. .##.# ..#.. .#.#.",
    "#.... ....# ..... ..... ..... ..... ..... .....",
    "#.... ....# ..... ..... ..... ..... ..... .....",

    // 'x'   'y'   'z'   '{'   '|'   '}'   '~'   □
    "..... ..... ..... ...#. ..#.. .#... ..... #####",
    "..... ..... ..... ..#.. ..#.. ..#.. ..... #...#",
    "#...# #...# ##### ..#.. ..#.. ..#.. .#... #...#",
    ".#.#. #...# ...#. .#... ..#.. ...#. #.#.# #...#",
    "..#.. #...# ..#.. ..#.. ..#.. ..#.. ...#. #...#",
    ".#.#. #...# .#... ..#.. ..#.. ..#.. ..... #...#",
    "#...# .#### ##### ...#. ..#.. .#... ..... #####",
    "..... ....# ..... ..... ..#.. ..... ..... .....",
    "..... .###. ..... ..... ..... ..... ..... .....",

    // °     µ     λ     ·     ×     ±     Δ     ≈
    ".##.. ..... .#... ..... ..... ..#.. ..#.. .....",
    "#..#. ..... ..#.. ..... #...# ..#.. ..#.. .#...",
    "#..#. #...# ..#.. ..... .#.#. ##### .#.#. #.#.#",
    ".##.. #...# ..#.. .##.. ..#.. ..#.. .#.#. ...#.",
    "..... #...# .#.#. .##.. .#.#. ..#.. #...# .#...",
    "..... #..## #...# ..... #...# ..... #...# #.#.#",
    "..... ###.# #...# ..... ..... ##### ##### ...#.",
    "..... #.... ..... ..... ..... ..... ..... .....",
    "..... #.... ..... ..... ..... ..... ..... .....",
};

// The glyphs after ASCII, in sheet order; the first is the placeholder box.
constexpr char32_t kExtraCharacters[] = {U'\u25A1', U'\u00B0', U'\u00B5', U'\u03BB', U'\u00B7',
                                         U'\u00D7', U'\u00B1', U'\u0394', U'\u2248'};
constexpr char32_t kBox = U'\u25A1';

constexpr int kAsciiGlyphs = 126 - 32 + 1;
constexpr int kGlyphCount = kAsciiGlyphs + int(std::size(kExtraCharacters));
constexpr int kBlockGlyphs = 8;
constexpr std::size_t kSheetRowLength = kBlockGlyphs * (kGlyphWidth + 1) - 1;

// A throw in a constant expression does not compile: a bad sheet breaks the build.
constexpr std::array<GlyphRows, kGlyphCount> parse_sheet() {
  static_assert(std::size(kSheet) == (kGlyphCount + kBlockGlyphs - 1) / kBlockGlyphs * kGlyphHeight);
  std::array<GlyphRows, kGlyphCount> glyphs{};
  for (int g = 0; g < kGlyphCount; ++g) {
    const int block = g / kBlockGlyphs, column = g % kBlockGlyphs;
    for (int r = 0; r < kGlyphHeight; ++r) {
      const std::string_view row = kSheet[block * kGlyphHeight + r];
      if (row.size() != kSheetRowLength) throw "glyph sheet row of the wrong length";
      for (int gap = 1; gap < kBlockGlyphs; ++gap)
        if (row[gap * (kGlyphWidth + 1) - 1] != ' ') throw "glyphs in a sheet row not one space apart";
      uint8_t bits = 0;
      for (int c = 0; c < kGlyphWidth; ++c) {
        const char ink = row[column * (kGlyphWidth + 1) + c];
        if (ink != '#' && ink != '.') throw "glyph sheet holds a character other than # and .";
        bits = static_cast<uint8_t>(bits << 1 | (ink == '#'));
      }
      glyphs[g][r] = bits;
    }
  }
  return glyphs;
}

constexpr std::array<GlyphRows, kGlyphCount> kGlyphs = parse_sheet();

// Index into kGlyphs, or -1.
int glyph_index(char32_t c) {
  if (c >= 32 && c <= 126) return int(c - 32);
  for (std::size_t i = 0; i < std::size(kExtraCharacters); ++i)
    if (kExtraCharacters[i] == c) return kAsciiGlyphs + int(i);
  return -1;
}

// The plain character a superscript (Unicode's superscript digits and signs) stands for.
char32_t from_superscript(char32_t c) {
  switch (c) {
    case U'\u00B9':
      return U'1';
    case U'\u00B2':
      return U'2';
    case U'\u00B3':
      return U'3';
    case U'\u2070':
      return U'0';
    case U'\u2071':
      return U'i';
    case U'\u207A':
      return U'+';
    case U'\u207B':
      return U'-';
    case U'\u207C':
      return U'=';
    case U'\u207D':
      return U'(';
    case U'\u207E':
      return U')';
    case U'\u207F':
      return U'n';
    default:
      return (c >= U'\u2074' && c <= U'\u2079') ? U'4' + (c - U'\u2074') : 0;
  }
}

char32_t from_subscript(char32_t c) {
  if (c >= U'\u2080' && c <= U'\u2089') return U'0' + (c - U'\u2080');
  switch (c) {
    case U'\u208A':
      return U'+';
    case U'\u208B':
      return U'-';
    case U'\u208C':
      return U'=';
    case U'\u208D':
      return U'(';
    case U'\u208E':
      return U')';
    default:
      return 0;
  }
}

// ASCII (or in-font) stand-ins for typographic characters; 0 if none.
char32_t substitute(char32_t c) {
  switch (c) {
    case U'\t':
    case U'\u00A0':
    case U'\u2002':
    case U'\u2003':
    case U'\u2009':
    case U'\u202F':
      return U' ';
    case U'\u2010':
    case U'\u2011':
    case U'\u2012':
    case U'\u2013':
    case U'\u2014':
    case U'\u2212':
      return U'-';
    case U'\u2018':
    case U'\u2019':
    case U'\u2032':
      return U'\'';
    case U'\u201C':
    case U'\u201D':
    case U'\u2033':
      return U'"';
    case U'\u03BC':
      return U'\u00B5';  // Greek mu, as often typed for micro
    case U'\u22C5':
    case U'\u2219':
      return U'\u00B7';
    case U'\u2206':
      return U'\u0394';  // increment sign
    default:
      return 0;
  }
}

}  // namespace

bool font_has_glyph(char32_t c) { return glyph_index(c) >= 0; }

const GlyphRows& glyph_rows(char32_t c) {
  const int i = glyph_index(c);
  return kGlyphs[i >= 0 ? i : glyph_index(kBox)];
}

std::u32string font_characters(std::string_view utf8) {
  std::u32string out;
  enum class Run { none, superscript, subscript } run = Run::none;
  for (std::size_t at = 0; at < utf8.size();) {
    char32_t c = decode_utf8(utf8, at);
    if (c == kMalformedUtf8) c = kBox;
    if (const char32_t plain = from_superscript(c)) {
      if (run != Run::superscript) out.push_back(U'^');
      run = Run::superscript;
      out.push_back(plain);
      continue;
    }
    if (const char32_t plain = from_subscript(c)) {
      if (run != Run::subscript) out.push_back(U'_');
      run = Run::subscript;
      out.push_back(plain);
      continue;
    }
    run = Run::none;
    if (c == U'\u2026') {  // ellipsis
      out.append(U"...");
      continue;
    }
    if (const char32_t s = substitute(c)) c = s;
    out.push_back(font_has_glyph(c) ? c : kBox);
  }
  return out;
}

}  // namespace skylit
