// PNG output: the display image of display_srgb8 (tone_map.h), and any other 8-bit RGB
// picture (figures: raster.h), through libpng's simplified API, which writes an sRGB
// chunk for 8-bit data and no tIME chunk, so the bytes depend only on the pixels (and
// the zlib version).
#include <png.h>

#include <stdexcept>
#include <string>

#include "skylit/io/image/human_display.h"
#include "skylit/io/image/image_encoders.h"

namespace skylit {

Bytes encode_png(const XyzImage& image, const DisplayOptions& options) {
  if (options.human)
    return encode_png_rgb8(image.width, image.height, human_display_srgb8(image, options.degrees_per_pixel));
  return encode_png_rgb8(image.width, image.height, display_srgb8(image, options));
}

Bytes encode_png_rgb8(int width, int height, std::span<const uint8_t> pixels) {
  if (width <= 0 || height <= 0 || pixels.size() != 3 * static_cast<std::size_t>(width) * height)
    throw std::invalid_argument("encode_png_rgb8: " + std::to_string(pixels.size()) + " bytes for " +
                                std::to_string(width) + "x" + std::to_string(height) + " pixels");
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(width);
  png.height = static_cast<png_uint_32>(height);
  png.format = PNG_FORMAT_RGB;
  // First call sizes the output, second fills it (libpng 1.6 png_image_write_to_memory).
  png_alloc_size_t size = 0;
  if (png_image_write_to_memory(&png, nullptr, &size, 0, pixels.data(), 0, nullptr)) {
    Bytes out(size);
    if (png_image_write_to_memory(&png, out.data(), &size, 0, pixels.data(), 0, nullptr)) {
      out.resize(size);
      return out;
    }
  }
  const std::string message = png.message;
  png_image_free(&png);
  throw std::runtime_error("libpng: " + message);
}

}  // namespace skylit
