// Internal to io/: one encoder per file format, each turning an image into the file's
// bytes in memory. write_image (image.cpp) then writes the bytes through an AtomicFile,
// so every format shares one checked, temporary-then-rename path to disk.
#pragma once

#include <algorithm>
#include <cfloat>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "skylit/io/image/image.h"

namespace skylit {

using Bytes = std::vector<uint8_t>;

// OpenEXR, 32-bit float R, G, B (linear sRGB primaries, absolute) and Y (cd/m²), and
// options.exr_layers if given.
Bytes encode_exr(const XyzImage& image, const DisplayOptions& options);
// Portable Float Map, little-endian float R, G, B, rows bottom to top.
Bytes encode_pfm(const XyzImage& image);
// Radiance RGBE in Radiance's RGB, values in its units (luminance / 179), with
// options.radiance_view as the header's VIEW= line.
Bytes encode_rgbe(const XyzImage& image, const DisplayOptions& options);
// PNG of display_srgb8: 8-bit sRGB with an sRGB chunk.
Bytes encode_png(const XyzImage& image, const DisplayOptions& options);
// PNG of `width` × `height` 8-bit sRGB pixels (3 per pixel, rows top to bottom), with an
// sRGB chunk: encode_png's last step, shared with figures (raster.h).
Bytes encode_png_rgb8(int width, int height, std::span<const uint8_t> rgb);

// Pixel `index` (0 … width·height − 1) as doubles; a pixel with any non-finite
// component is black, so that no writer ever emits NaN or Inf.
Xyz finite_pixel_or_black(const XyzImage& image, std::size_t index);

// Finite double → finite float: an XYZ just below FLT_MAX can give RGB above it.
inline float to_finite_float(double v) { return static_cast<float>(std::clamp<double>(v, -FLT_MAX, FLT_MAX)); }

// Whether the pixel at `index` has three finite components.
bool pixel_is_finite(const XyzImage& image, std::size_t index);

// Throws std::invalid_argument unless width, height ≥ 0 and xyz holds exactly
// 3·width·height values: a renderer bug, not a user error.
void check_image_shape(const XyzImage& image);

}  // namespace skylit
