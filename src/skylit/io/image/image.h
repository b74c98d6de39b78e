// Rendered images and how they leave the program: an image of absolute CIE XYZ, and
// writers for OpenEXR and PFM (linear, absolute, sRGB primaries), Radiance RGBE .hdr
// (Radiance's own RGB and luminance convention) and PNG (a tone-mapped display image).
// docs/images.md says what each file holds and defines the display transform exactly.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "skylit/spectrum/xyz_image.h"

namespace skylit {

// Extra EXR channels (docs/images.md, "Data layers"): each a name and one float per
// pixel, rows from the top; and the table that names the values of an "object" channel.
struct ExrLayers {
  std::vector<std::pair<std::string, std::vector<float>>> channels;
  std::vector<std::string> object_names;  // written as the string attribute "skylit:objects"
};

struct DisplayOptions {
  // Photographic exposure value at ISO 100 (EV100, stops); empty = automatic, chosen
  // by the meter of exposure_meter.h (see docs/images.md).
  std::optional<double> exposure_ev;
  // .hdr: Radiance's view options for the header's VIEW= line (radiance_view.h); empty
  // for none.
  std::optional<std::string> radiance_view{};
  // .png: the human-vision display (human_display.h) instead of the photographic one,
  // with foveal samples of about 1° at this many degrees per pixel.
  bool human = false;
  double degrees_per_pixel = 0.05;
  // .exr: extra layers, or null for none.
  const ExrLayers* exr_layers = nullptr;
};

enum class ImageFormat { png, exr, pfm, hdr };

// Format from the extension (.png .exr .pfm .hdr, case-insensitive); InputError naming
// the path otherwise.
ImageFormat image_format_from_path(const std::filesystem::path& path);

// Writes through a temporary file in the same folder, renamed into place, so that a
// failed or interrupted write leaves no partial file. InputError (naming the path) if
// the extension is unknown or the folder is missing or unwritable. An image with a
// non-finite pixel is not written: NonFinitePixels. The same image and options give
// the same bytes.
void write_image(const XyzImage& image, const std::filesystem::path& path, const DisplayOptions& options = {});

// A NaN or Inf in a rendered image is skylit's own bug (a user's input is checked before
// it can cause one), so it is an internal error, and nothing is written: written as
// black it would hide the fault (issue 19).
class NonFinitePixels : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

// Throws NonFinitePixels "<path>: N of M pixels are not finite ..." if any pixel has a
// non-finite component.
void check_pixels_finite(const XyzImage& image, const std::filesystem::path& path);

// The bytes write_image would write, with the same checks (NonFinitePixels, a layer of
// the wrong size, an unknown extension), for writers that gather a set of outputs and
// publish them all or nothing (io/output_files.h).
std::vector<uint8_t> encode_image(const XyzImage& image, const std::filesystem::path& path,
                                  const DisplayOptions& options);

// The display transform used for PNG, exposed for tests and contact sheets: returns
// 8-bit sRGB, 3 per pixel, rows top to bottom.
std::vector<uint8_t> display_srgb8(const XyzImage& image, const DisplayOptions& options);

}  // namespace skylit
