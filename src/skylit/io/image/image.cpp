// XyzImage, choosing a format from the file name, and write_image, which encodes in
// memory and writes through an AtomicFile (the encoders live in *_writer.cpp).
#include "skylit/io/image/image.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "skylit/core/error.h"
#include "skylit/core/file_names.h"
#include "skylit/io/atomic_file.h"
#include "skylit/io/image/image_encoders.h"

namespace skylit {

void check_image_shape(const XyzImage& image) {
  if (image.width < 0 || image.height < 0 ||
      image.xyz.size() != 3 * static_cast<std::size_t>(image.width) * image.height)
    throw std::invalid_argument("XyzImage: xyz holds " + std::to_string(image.xyz.size()) + " values, not 3 x " +
                                std::to_string(image.width) + " x " + std::to_string(image.height));
}

bool pixel_is_finite(const XyzImage& image, std::size_t index) {
  const float* p = &image.xyz[3 * index];
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

Xyz finite_pixel_or_black(const XyzImage& image, std::size_t index) {
  if (!pixel_is_finite(image, index)) return {0, 0, 0};
  const float* p = &image.xyz[3 * index];
  return {p[0], p[1], p[2]};
}

ImageFormat image_format_from_path(const std::filesystem::path& path) {
  const std::string ext = lower_case_extension(path);
  if (ext == ".png") return ImageFormat::png;
  if (ext == ".exr") return ImageFormat::exr;
  if (ext == ".pfm") return ImageFormat::pfm;
  if (ext == ".hdr") return ImageFormat::hdr;
  throw InputError("cannot write \"" + path.string() +
                   "\": " + (ext.empty() ? std::string("no file extension") : "unknown extension \"" + ext + "\"") +
                   "; use .png, .exr, .pfm or .hdr");
}

void check_pixels_finite(const XyzImage& image, const std::filesystem::path& path) {
  check_image_shape(image);
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  std::size_t bad = 0;
  for (std::size_t i = 0; i < pixels; ++i) bad += pixel_is_finite(image, i) ? 0 : 1;
  if (bad > 0)
    throw NonFinitePixels("\"" + path.string() + "\": " + std::to_string(bad) + " of " + std::to_string(pixels) +
                          " pixels are not finite numbers, so nothing was written (a bug in skylit: please report "
                          "it with the scene)");
}

namespace {

// Everything about one image that can be refused, before a temporary file exists.
void check_writable(const XyzImage& image, const std::filesystem::path& path, const DisplayOptions& options) {
  check_image_shape(image);
  if (image.width == 0 || image.height == 0)
    throw std::invalid_argument("write_image: empty image for \"" + path.string() + "\"");
  if (options.exposure_ev && !std::isfinite(*options.exposure_ev))
    throw InputError("cannot write \"" + path.string() + "\": exposure_ev is not finite");
  if (options.exr_layers)
    for (const auto& [name, values] : options.exr_layers->channels)
      if (values.size() != static_cast<std::size_t>(image.width) * image.height)
        throw std::invalid_argument("write_image: layer " + name + " does not match the image");
  check_pixels_finite(image, path);
}

Bytes encode(const XyzImage& image, ImageFormat format, const DisplayOptions& options) {
  Bytes bytes;
  switch (format) {
    case ImageFormat::exr:
      bytes = encode_exr(image, options);
      break;
    case ImageFormat::pfm:
      bytes = encode_pfm(image);
      break;
    case ImageFormat::hdr:
      bytes = encode_rgbe(image, options);
      break;
    case ImageFormat::png:
      bytes = encode_png(image, options);
      break;
  }
  return bytes;
}

}  // namespace

Bytes encode_image(const XyzImage& image, const std::filesystem::path& path, const DisplayOptions& options) {
  const ImageFormat format = image_format_from_path(path);
  check_writable(image, path, options);
  return encode(image, format, options);
}

void write_image(const XyzImage& image, const std::filesystem::path& path, const DisplayOptions& options) {
  image_format_from_path(path);
  AtomicFile file(path);  // checks the folder before the (possibly slow) encoding
  file.commit(encode_image(image, path, options));
}

}  // namespace skylit
