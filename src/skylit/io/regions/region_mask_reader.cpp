// read_region_mask (regions_reader.h) through libpng's simplified API, which reads any
// PNG (grey, palette, 16-bit, with alpha) as 8-bit RGBA. Alpha is read rather than
// composited so that a transparent pixel is "no region" whatever colour it hides.
#include <png.h>

#include <cstdio>
#include <map>
#include <string>
#include <system_error>
#include <vector>

#include "skylit/core/error.h"
#include "skylit/io/regions/regions_reader.h"

namespace skylit {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& why) {
  throw InputError("cannot read the mask \"" + path.string() + "\": " + why);
}

struct Rgba8Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;
};

Rgba8Image read_rgba8(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) fail(path, "no such file");
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str()))
    fail(path, std::string("not a readable PNG (") + png.message + ")");
  png.format = PNG_FORMAT_RGBA;
  Rgba8Image out;
  out.width = static_cast<int>(png.width);
  out.height = static_cast<int>(png.height);
  out.rgba.resize(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, out.rgba.data(), 0, nullptr)) {
    const std::string message = png.message;
    png_image_free(&png);
    fail(path, "not a readable PNG (" + message + ")");
  }
  return out;
}

std::string hex_colour(uint32_t rgb) {
  char text[8];
  std::snprintf(text, sizeof text, "#%06x", rgb);
  return text;
}

}  // namespace

std::vector<ImageRegion> read_region_mask(const std::filesystem::path& path, int width, int height) {
  const Rgba8Image mask = read_rgba8(path);
  if (mask.width != width || mask.height != height)
    fail(path, "it is " + std::to_string(mask.width) + "x" + std::to_string(mask.height) + ", the images are " +
                   std::to_string(width) + "x" + std::to_string(height));
  std::map<uint32_t, std::vector<uint32_t>> pixels_by_colour;  // ordered, so regions come sorted by name
  for (uint32_t i = 0; i < static_cast<uint32_t>(width) * static_cast<uint32_t>(height); ++i) {
    const uint8_t* p = &mask.rgba[4 * static_cast<std::size_t>(i)];
    const uint32_t rgb = (uint32_t(p[0]) << 16) | (uint32_t(p[1]) << 8) | p[2];
    if (p[3] == 0 || rgb == 0) continue;
    pixels_by_colour[rgb].push_back(i);
    if (pixels_by_colour.size() > static_cast<std::size_t>(kMaxMaskColours))
      fail(path, "more than " + std::to_string(kMaxMaskColours) +
                     " colours; draw the mask with flat colours and no anti-aliasing");
  }
  if (pixels_by_colour.empty()) fail(path, "every pixel is black or transparent: no region");
  std::vector<ImageRegion> regions;
  regions.reserve(pixels_by_colour.size());
  for (auto& [rgb, pixels] : pixels_by_colour) regions.push_back({hex_colour(rgb), std::move(pixels)});
  return regions;
}

}  // namespace skylit
