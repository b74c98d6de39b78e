// Portable Float Map, as Paul Debevec's page "PFM Portable Float Map" describes it
// (read by HDRShop, pfstools, ImageMagick, OpenImageIO):
// header "PF\n<width> <height>\n<scale>\n", a negative scale meaning little-endian
// floats, then R, G, B per pixel with rows from the BOTTOM of the image up. Values are
// linear sRGB primaries scaled so that 0.2126 R + 0.7152 G + 0.0722 B is cd/m², as EXR.
#include <bit>
#include <string>

#include "skylit/io/image/image_encoders.h"

namespace skylit {
namespace {

void put_little_endian(Bytes& out, float v) {
  const uint32_t bits = std::bit_cast<uint32_t>(v);
  for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<uint8_t>(bits >> shift));
}

}  // namespace

Bytes encode_pfm(const XyzImage& image) {
  const std::string header = "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
  Bytes out(header.begin(), header.end());
  out.reserve(header.size() + 12 * static_cast<std::size_t>(image.width) * image.height);
  for (int row = image.height - 1; row >= 0; --row) {
    for (int x = 0; x < image.width; ++x) {
      const Rgb rgb =
          linear_srgb_from_xyz(finite_pixel_or_black(image, static_cast<std::size_t>(row) * image.width + x));
      for (double c : rgb) put_little_endian(out, to_finite_float(c));
    }
  }
  return out;
}

}  // namespace skylit
