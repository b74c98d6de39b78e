// A false-colour image of a photometric quantity (luminance in cd/m², illuminance in lx):
// each pixel's value on a logarithmic or linear scale in viridis colours (viridis.h),
// optional contour lines where the value crosses a legend step, optionally over a faint
// copy of the display image, and a legend at the right that names the quantity, its
// unit and the scale, with a swatch for every step. docs/images.md, "False colour".
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "skylit/figures/raster.h"
#include "skylit/io/image/image.h"
#include "skylit/scene/output_settings.h"

namespace skylit {

struct FalseColourLegend {
  std::string quantity, unit;  // "luminance", "cd/m²"
  FalseColourScale scale = FalseColourScale::log;
  double low = 0, high = 1;   // the scale's ends; values beyond take the end colours
  std::vector<double> steps;  // the legend's values, ascending, low and high included
};

// The legend for `values` (row by row; non-finite ones ignored): `settings.max`, or
// else the 99th percentile of the values rounded up (log: to a power of ten; linear: to
// 1, 2 or 5 times one). Log steps are the ends and the 1-2-5 values between them;
// linear steps are 0 … high in tenths.
FalseColourLegend false_colour_legend(std::span<const float> values, const FalseColourSettings& settings);

// The colour of a value: viridis at its place on the scale (clamped; non-finite and,
// on a log scale, non-positive values take the low end's colour).
Rgb8 false_colour(double value, const FalseColourLegend& legend);

// A legend step's label: three significant digits, no trailing zeros ("0.5", "1e+04").
std::string false_colour_label(double value);

// Where the legend's swatches lie in the raster: swatch i (steps[i]) is the square
// [x, x + size) × [y[i], y[i] + size), highest value at the top.
struct FalseColourLayout {
  int swatch_x = 0, swatch_size = 0;
  std::vector<int> swatch_y;
};

// The image (`width` × `height` values; pixel (x, y) is raster pixel (x, y)) and the
// legend at its right. `underlay_srgb`: 3 bytes per pixel of the display image, or
// empty for none (it is required when settings.underlay is set).
Raster render_false_colour(std::span<const float> values, int width, int height, const FalseColourSettings& settings,
                           std::span<const uint8_t> underlay_srgb, FalseColourLayout* layout = nullptr);

// The false-colour PNG's bytes (see write_false_colour).
std::vector<uint8_t> encode_false_colour(const XyzImage& image, std::span<const float> values,
                                         const FalseColourSettings& settings, const DisplayOptions& display);

// The false-colour PNG of a render through a temporary file: `values` per pixel of
// `image` (its luminance, or the illuminance layer), the underlay (if asked) the
// display image of `image` under `display`. InputError naming the path for a name
// that does not end in .png or a missing folder; then no file is left.
void write_false_colour(const XyzImage& image, std::span<const float> values, const std::filesystem::path& path,
                        const FalseColourSettings& settings, const DisplayOptions& display);

// Whether a path asks for a false-colour image: its name ends in ".falsecolor.png" or
// ".falsecolour.png" (any case).
bool is_false_colour_path(const std::filesystem::path& path);

}  // namespace skylit
