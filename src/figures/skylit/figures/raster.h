// A small 8-bit sRGB raster for figures (plots, contact sheets): filling, anti-aliased
// lines, blitting display images, text in the built-in bitmap font (bitmap_font.h),
// and writing it as PNG through a temporary file. Coordinates are pixels from the
// top-left corner; pixel (i, j) covers [i, i+1) × [j, j+1), so its centre is at
// (i + 0.5, j + 0.5) and a 1-pixel line along y = j + 0.5 is crisp. Everything clips
// at the edges: drawing outside the raster is not an error.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

namespace skylit {

struct Rgb8 {
  uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb8&) const = default;
};

inline constexpr Rgb8 kWhite{255, 255, 255};
inline constexpr Rgb8 kBlack{0, 0, 0};

struct Raster {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // 3 per pixel, sRGB-encoded, rows top to bottom

  Raster() = default;
  // std::invalid_argument if a size is negative.
  Raster(int width, int height, Rgb8 background = kWhite);

  Rgb8 at(int x, int y) const;  // std::out_of_range outside
};

struct PointF {
  double x = 0, y = 0;
};

void fill(Raster& raster, Rgb8 colour);
void set_pixel(Raster& raster, int x, int y, Rgb8 colour);
// Mixes `colour` over the pixel with weight `coverage` (clamped to [0, 1]), in sRGB
// code values as display software does for anti-aliased edges.
void blend_pixel(Raster& raster, int x, int y, Rgb8 colour, double coverage);
void fill_rect(Raster& raster, int x, int y, int width, int height, Rgb8 colour);

// An anti-aliased polyline `width_px` wide: each pixel is covered by how far its centre
// lies inside the stroke (a one-pixel ramp at the edge), taking the largest coverage over
// all segments so that joints are not painted twice. Non-finite points are skipped.
void draw_polyline(Raster& raster, std::span<const PointF> points, Rgb8 colour, double width_px);
void draw_line(Raster& raster, PointF from, PointF to, Rgb8 colour, double width_px);

// Copies a `width` × `height` 8-bit RGB image (e.g. display_srgb8) with its top-left
// corner at (x, y). std::invalid_argument if `rgb` does not hold 3·width·height bytes.
void blit_rgb8(Raster& raster, int x, int y, int width, int height, std::span<const uint8_t> rgb);

// Text in the built-in font, one line, `scale` ≥ 1 an integer magnification.
enum class TextDirection {
  right,  // normal reading
  up,     // turned 90° counter-clockwise, read from the bottom up (a y-axis label)
};
int text_width(std::string_view utf8, int scale = 1);  // advance along the line, pixels
int text_height(int scale = 1);                        // line height, pixels
// For `right` the text occupies x ≤ column < x + text_width, y ≤ row < y + text_height;
// for `up` it occupies x ≤ column < x + text_height, y − text_width ≤ row < y, starting
// at the bottom with the tops of the letters to the left.
void draw_text(Raster& raster, int x, int y, std::string_view utf8, Rgb8 colour, int scale = 1,
               TextDirection direction = TextDirection::right);

// PNG (8-bit RGB with an sRGB chunk) through a temporary file renamed into place.
// InputError naming the path if the extension is not .png (any case) or the folder is
// missing or not writable; nothing is left behind on failure.
void write_png(const Raster& raster, const std::filesystem::path& path);

}  // namespace skylit
