// Shards' exact XYZ images (xyz_file.h).
#include "skylit/io/image/xyz_file.h"

#include <bit>
#include <cmath>
#include <sstream>

#include "skylit/core/error.h"
#include "skylit/core/text_file.h"

namespace skylit {

namespace {

constexpr const char* kMagic = "skylit-xyz";
constexpr long long kMaxSide = 65536;

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& why) {
  throw InputError("cannot read \"" + path.string() + "\": " + why);
}

}  // namespace

std::vector<uint8_t> encode_xyz_file(const XyzImage& image) {
  const std::string header =
      std::string(kMagic) + " 1\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n";
  std::vector<uint8_t> out(header.begin(), header.end());
  out.reserve(header.size() + 4 * image.xyz.size());
  for (const float v : image.xyz) {
    const auto bits = std::bit_cast<uint32_t>(v);
    for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<uint8_t>(bits >> shift));
  }
  return out;
}

XyzImage decode_xyz_file(const std::string& bytes, const std::filesystem::path& path) {
  const std::size_t first_line = bytes.find('\n');
  if (first_line == std::string::npos || bytes.compare(0, first_line, std::string(kMagic) + " 1") != 0)
    fail(path, "not a skylit-xyz shard image (no \"skylit-xyz 1\" line)");
  const std::size_t second_line = bytes.find('\n', first_line + 1);
  if (second_line == std::string::npos) fail(path, "no size line");
  std::istringstream size(bytes.substr(first_line + 1, second_line - first_line - 1));
  long long width = 0, height = 0;
  std::string rest;
  size >> width >> height;
  if (!size || (size >> rest) || width < 1 || height < 1 || width > kMaxSide || height > kMaxSide)
    fail(path, "bad size line (expected \"<width> <height>\", each 1 to 65536)");
  const std::size_t start = second_line + 1;
  const std::size_t needed = 12 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (bytes.size() - start != needed)
    fail(path, std::to_string(bytes.size() - start) + " bytes of pixels, expected " + std::to_string(needed));
  XyzImage image(static_cast<int>(width), static_cast<int>(height));
  for (std::size_t i = 0; i < image.xyz.size(); ++i) {
    uint32_t bits = 0;
    for (int k = 0; k < 4; ++k) bits |= uint32_t{static_cast<unsigned char>(bytes[start + 4 * i + k])} << (8 * k);
    image.xyz[i] = std::bit_cast<float>(bits);
    if (!std::isfinite(image.xyz[i])) fail(path, "pixel value " + std::to_string(i / 3) + " is not finite");
  }
  return image;
}

XyzImage read_xyz_file(const std::filesystem::path& path) {
  // A 16384 × 16384 frame is 3 GiB: the cap only keeps a mistaken device file out.
  return decode_xyz_file(read_text_file(path, "shard image", std::uintmax_t{1} << 34), path);
}

}  // namespace skylit
