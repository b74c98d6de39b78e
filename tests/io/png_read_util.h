// Reading a PNG back with libpng's simplified API, for the figure tests (plots,
// contact sheets, rasters): the pixels as 8-bit RGB, rows top to bottom.
#pragma once

#include <gtest/gtest.h>
#include <png.h>

#include <cstdint>
#include <filesystem>
#include <vector>

#include "skylit/figures/raster.h"

namespace skylit::test {

inline Raster read_png_raster(const std::filesystem::path& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  Raster out;
  if (!png_image_begin_read_from_file(&image, path.c_str())) {
    ADD_FAILURE() << "libpng: " << image.message;
    return out;
  }
  image.format = PNG_FORMAT_RGB;
  out.width = int(image.width);
  out.height = int(image.height);
  out.rgb.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, out.rgb.data(), 0, nullptr)) ADD_FAILURE() << "libpng: " << image.message;
  return out;
}

}  // namespace skylit::test
