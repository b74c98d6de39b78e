// stb_image's implementation is compiled here, for PNG and JPEG only.
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO
#define STBI_FAILURE_USERMSG
#define STBI_MAX_DIMENSIONS 16384  // kMaxTextureSide
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#endif
#include <stb/stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

#include "skylit/io/model/texture_file.h"

#include <climits>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

#include "skylit/core/error.h"
#include "skylit/io/model/mesh_io.h"

namespace skylit {

std::shared_ptr<const Texture> decode_texture(const unsigned char* bytes, size_t size, TextureEncoding encoding,
                                              const std::string& where) {
  if (size == 0 || size > static_cast<size_t>(INT_MAX)) throw InputError(where + ": not a PNG or JPEG image");
  int width = 0, height = 0, channels = 0;
  if (!stbi_info_from_memory(bytes, static_cast<int>(size), &width, &height, &channels))
    throw InputError(where + ": not a PNG or JPEG image (" + stbi_failure_reason() + ")");
  if (width <= 0 || height <= 0 || width > kMaxTextureSide || height > kMaxTextureSide)
    throw InputError(where + ": the image is " + std::to_string(width) + " × " + std::to_string(height) +
                     " texels; at most " + std::to_string(kMaxTextureSide) + " a side is read");
  unsigned char* texels = stbi_load_from_memory(bytes, static_cast<int>(size), &width, &height, &channels, 4);
  if (texels == nullptr) throw InputError(where + ": cannot decode the image (" + stbi_failure_reason() + ")");
  std::vector<uint8_t> rgba(texels, texels + static_cast<size_t>(width) * height * 4);
  stbi_image_free(texels);
  return std::make_shared<const Texture>(width, height, std::move(rgba), encoding);
}

std::shared_ptr<const Texture> read_texture_file(const std::filesystem::path& path, TextureEncoding encoding) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path.string() + ": texture file not found");
  if (std::filesystem::file_size(path, ec) > kMaxMeshFileBytes)
    throw InputError(path.string() + ": texture file larger than the limit of 1 GiB");
  std::ifstream in(path, std::ios::binary);
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof()) throw InputError(path.string() + ": cannot read the texture file");
  return decode_texture(bytes.data(), bytes.size(), encoding, path.string());
}

}  // namespace skylit
