// A false-colour map of how much brighter or darker render B is than render A, pixel
// by pixel: the luminance ratio B/A on a log scale from 1/2 to 2 in Moreland's
// cool-warm colours (cool_warm.h: blue where B is darker, the neutral grey where they
// agree, red where B is brighter), with a legend below. Pixels dark in both renders
// (kDarkLuminance_cd_m2) or not finite are a darker, flat grey. docs/validation.md.
#pragma once

#include <filesystem>

#include "skylit/figures/raster.h"
#include "skylit/spectrum/xyz_image.h"

namespace skylit {

// The ends of the colour scale: ratios beyond them take the end colours.
inline constexpr double kRatioMapLowest = 0.5, kRatioMapHighest = 2.0;
// Pixels with no meaningful ratio; darker than the scale's neutral grey, so the two
// are not confused.
inline constexpr Rgb8 kNoRatioGrey{128, 128, 128};

// The colour of a ratio B/A: cool_warm at t = (log2(ratio) + 1) / 2, clamped.
Rgb8 ratio_colour(double ratio);

// Image pixel (x, y) is raster pixel (x, y); the legend lies below the image (the
// raster is widened, white, when the image is narrower than the legend). The legend
// is drawn larger for images wider than 512 pixels. std::invalid_argument if A and B
// differ in size (the caller checks and names the files).
Raster render_ratio_map(const XyzImage& a, const XyzImage& b);

// The map as PNG through a temporary file; InputError naming the path for another
// extension or a missing folder, and then no file is left.
void write_ratio_map(const XyzImage& a, const XyzImage& b, const std::filesystem::path& path);

}  // namespace skylit
