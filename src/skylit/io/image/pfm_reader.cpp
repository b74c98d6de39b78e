// Portable Float Map input, the counterpart of pfm_writer.cpp: header "PF" (RGB) or
// "Pf" (grey), "<width> <height>", then the scale whose sign gives the byte order
// (negative: little-endian) and whose magnitude skylit ignores (it writes 1, and
// readers disagree on its meaning); rows from the bottom of the image up.
#include <bit>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>

#include "skylit/core/error.h"
#include "skylit/io/image/image_decoders.h"

namespace skylit {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& why) {
  throw InputError("cannot read \"" + path.string() + "\": " + why);
}

float float_at(const std::string& bytes, std::size_t offset, bool little_endian) {
  uint32_t bits = 0;
  for (int k = 0; k < 4; ++k) {
    const auto byte = static_cast<uint32_t>(static_cast<unsigned char>(bytes[offset + k]));
    bits |= little_endian ? byte << (8 * k) : byte << (8 * (3 - k));
  }
  return std::bit_cast<float>(bits);
}

}  // namespace

XyzImage decode_pfm(const std::string& bytes, const std::filesystem::path& path) {
  std::istringstream header(bytes);
  std::string magic;
  long long width = 0, height = 0;
  double scale = 0;
  header >> magic >> width >> height >> scale;
  if (!header || (magic != "PF" && magic != "Pf")) fail(path, "not a PFM file (no \"PF\" or \"Pf\" header)");
  if (width <= 0 || height <= 0 || width > 65536 || height > 65536 || scale == 0)
    fail(path, "bad PFM header (size " + std::to_string(width) + "x" + std::to_string(height) + ")");
  header.get();  // the single whitespace character that ends the header
  const std::size_t start = static_cast<std::size_t>(header.tellg());
  const int channels = magic == "PF" ? 3 : 1;
  const std::size_t needed = 4 * static_cast<std::size_t>(channels) * width * height;
  if (bytes.size() < start + needed)
    fail(path, "truncated PFM: " + std::to_string(bytes.size() - start) + " bytes of pixels, expected " +
                   std::to_string(needed));
  const bool little_endian = scale < 0;
  XyzImage image(static_cast<int>(width), static_cast<int>(height));
  std::size_t offset = start;
  for (int row = image.height - 1; row >= 0; --row)
    for (int x = 0; x < image.width; ++x) {
      Rgb rgb;
      for (int c = 0; c < 3; ++c) {
        rgb[c] = float_at(bytes, offset, little_endian);
        if (channels == 3) offset += 4;
      }
      if (channels == 1) offset += 4;
      image.set(x, row, xyz_from_linear_srgb(rgb));
    }
  return image;
}

}  // namespace skylit
