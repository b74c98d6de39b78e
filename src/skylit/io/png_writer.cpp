// PNG output: the display image of display_srgb8 (tone_map.h), 8-bit RGB, through
// libpng's simplified API, which writes an sRGB chunk for 8-bit data and no tIME
// chunk, so the bytes depend only on the pixels (and the zlib version).
#include <png.h>

#include <stdexcept>
#include <string>

#include "skylit/io/image_encoders.h"

namespace skylit {

Bytes encode_png(const XyzImage& image, const DisplayOptions& options) {
  const std::vector<uint8_t> pixels = display_srgb8(image, options);
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
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
