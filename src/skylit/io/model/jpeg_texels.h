// JPEG textures decoded by libjpeg-turbo (Debian's libjpeg62-turbo), the decoder that
// browsers and image libraries use and OSS-Fuzz fuzzes. stb_image 2.27, which Debian 12
// ships, read out of bounds on JPEGs the texture fuzz target made (a scan using a
// Huffman table never defined, tables coding over 256 symbols) and overflowed signed
// integers on 16-bit quantisation tables; its fixes came in 2.28.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace skylit {

struct JpegTexels {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // 8-bit, top row first, alpha 255
};

// Decodes JPEG bytes (grey, YCbCr, RGB, or CMYK and YCCK converted without their colour
// profile; baseline or progressive) to RGBA. Throws
// InputError naming `where` when the bytes are not a JPEG libjpeg can decode or either
// side exceeds `max_side` texels (refused from the header, before texels are
// allocated). Damage libjpeg recovers from (a scan cut short) gives what it decoded.
JpegTexels decode_jpeg(const unsigned char* bytes, size_t size, int max_side, const std::string& where);

}  // namespace skylit
