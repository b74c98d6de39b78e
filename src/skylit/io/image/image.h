// Rendered images and how they leave the program: an image of absolute CIE XYZ, and
// writers for OpenEXR and PFM (linear, absolute, sRGB primaries), Radiance RGBE .hdr
// (Radiance's own RGB and luminance convention) and PNG (a tone-mapped display image).
// docs/images.md says what each file holds and defines the display transform exactly.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "skylit/spectrum/xyz_image.h"

namespace skylit {

struct DisplayOptions {
  // Photographic exposure value at ISO 100 (EV100, stops); empty = automatic, chosen
  // from the image's log-average luminance (see docs/images.md).
  std::optional<double> exposure_ev;
};

enum class ImageFormat { png, exr, pfm, hdr };

// Format from the extension (.png .exr .pfm .hdr, case-insensitive); InputError naming
// the path otherwise.
ImageFormat image_format_from_path(const std::filesystem::path& path);

// Writes through a temporary file in the same folder, renamed into place, so that a
// failed or interrupted write leaves no partial file. InputError (naming the path) if
// the extension is unknown or the folder is missing or unwritable. Non-finite pixels
// are written as black. The same image and options give the same bytes.
void write_image(const XyzImage& image, const std::filesystem::path& path, const DisplayOptions& options = {});

// The display transform used for PNG, exposed for tests and contact sheets: returns
// 8-bit sRGB, 3 per pixel, rows top to bottom.
std::vector<uint8_t> display_srgb8(const XyzImage& image, const DisplayOptions& options);

// exp(mean(log(δ + Y))) over the finite pixels, δ = kLogAverageDelta cd/m² (Reinhard et
// al. 2002, Eq. 1); negative Y counts as 0. An image with no finite pixel gives δ.
double log_average_luminance(const XyzImage& image);

// δ of log_average_luminance, cd/m²: small next to any lit surface (a lamp-lit street
// is 0.3–2 cd/m²), so it only keeps black pixels from sending the average to zero.
inline constexpr double kLogAverageDelta = 1e-4;

}  // namespace skylit
