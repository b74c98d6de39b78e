// stb_image's implementation is compiled in stb_image_implementation.cpp.
#define STBI_NO_STDIO
#include <stb/stb_image.h>

#include "skylit/io/model/texture_file.h"

#include <algorithm>
#include <climits>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "skylit/core/error.h"
#include "skylit/io/model/jpeg_texels.h"
#include "skylit/io/model/mesh_io.h"

namespace skylit {

namespace {

// Whether the bytes start as a PNG does (stb takes as JPEG what does not).
bool is_png(const unsigned char* bytes, size_t size) {
  return size >= 4 && bytes[0] == 0x89 && bytes[1] == 'P' && bytes[2] == 'N' && bytes[3] == 'G';
}

// BMP's RLE8 codes 255 texels in 2 bytes, TGA's run packets 128 in 2 (8-bit): 256 a
// byte is more than either can hold.
constexpr double kMostBmpOrTgaTexelsPerByte = 256;

// Whether the bytes start as a JPEG does: its start marker FF D8, after any fill bytes FF.
bool is_jpeg(const unsigned char* bytes, size_t size) {
  size_t at = 0;
  while (at < size && bytes[at] == 0xFF) ++at;
  return at > 0 && at < size && bytes[at] == 0xD8;
}

uint32_t big_endian_at(const unsigned char* bytes, size_t at) {
  return static_cast<uint32_t>(bytes[at]) << 24 | static_cast<uint32_t>(bytes[at + 1]) << 16 |
         static_cast<uint32_t>(bytes[at + 2]) << 8 | bytes[at + 3];
}

// The first PNG chunk, up to IEND, that claims more bytes than the file has left: none
// if every one fits. stb_image grows its buffer for the image data to what an IDAT
// chunk claims before reading it, doubling: an 89-byte file asked for 2 GiB (found by
// the texture fuzz target).
std::optional<std::string> png_chunk_past_the_end(const unsigned char* bytes, size_t size) {
  for (size_t at = 8; at + 8 <= size;) {
    const uint32_t length = big_endian_at(bytes, at);
    const std::string type(reinterpret_cast<const char*>(bytes + at + 4), 4);
    if (type == "IEND") return std::nullopt;
    // Its data and its 4-byte CRC after the 8-byte length and type.
    if (length > size - at - 8 || size - at - 8 - length < 4)
      return "a PNG chunk at byte " + std::to_string(at) + " claims " + std::to_string(length) +
             " bytes, more than the file has left";
    at += 12 + size_t{length};
  }
  return std::nullopt;
}

}  // namespace

std::shared_ptr<const Texture> decode_texture(const unsigned char* bytes, size_t size, TextureEncoding encoding,
                                              const std::string& where) {
  if (size == 0 || size > static_cast<size_t>(INT_MAX)) throw InputError(where + ": not a PNG, JPEG, BMP or TGA image");
  if (is_jpeg(bytes, size)) {
    JpegTexels jpeg = decode_jpeg(bytes, size, kMaxTextureSide, where);
    return std::make_shared<const Texture>(jpeg.width, jpeg.height, std::move(jpeg.rgba), encoding);
  }
  int width = 0, height = 0, channels = 0;
  if (is_png(bytes, size)) {
    if (const std::optional<std::string> why = png_chunk_past_the_end(bytes, size))
      throw InputError(where + ": not a PNG, JPEG, BMP or TGA image, or a damaged one (" + *why + ")");
    // A PNG's size is in its header (IHDR), which stb does not report when it refuses
    // one too large (it says "not of any known type").
    if (size >= 24) {
      const uint32_t w = big_endian_at(bytes, 16), h = big_endian_at(bytes, 20);
      if (w > static_cast<uint32_t>(kMaxTextureSide) || h > static_cast<uint32_t>(kMaxTextureSide))
        throw InputError(where + ": the image is " + std::to_string(w) + " × " + std::to_string(h) +
                         " texels; at most " + std::to_string(kMaxTextureSide) + " a side is read");
    }
  }
  if (!stbi_info_from_memory(bytes, static_cast<int>(size), &width, &height, &channels))
    throw InputError(where + ": not a PNG, JPEG, BMP or TGA image, or a damaged one (" + stbi_failure_reason() + ")");
  // A BMP stored top row first gives its height negative; stb_image 2.27's info passes
  // the sign on (its load turns the rows right).
  const bool bmp = size >= 2 && bytes[0] == 'B' && bytes[1] == 'M';
  if (bmp && height < 0 && height >= -kMaxTextureSide) height = -height;
  if (width <= 0 || height <= 0 || width > kMaxTextureSide || height > kMaxTextureSide)
    throw InputError(where + ": the image is " + std::to_string(width) + " × " + std::to_string(height) +
                     " texels; at most " + std::to_string(kMaxTextureSide) + " a side is read");
  // stb reads a BMP or TGA shorter than its header claims as if zeros followed (a
  // 49-byte TGA from the fuzzer made 72 million texels); a PNG fails instead.
  // Their run-length codings hold fewer than 256 texels a byte, so more is not the file.
  if (!is_png(bytes, size) &&
      static_cast<double>(width) * height > kMostBmpOrTgaTexelsPerByte * static_cast<double>(size))
    throw InputError(where + ": a BMP or TGA image of " + std::to_string(width) + " × " + std::to_string(height) +
                     " texels in " + std::to_string(size) + " bytes: cut short");
  unsigned char* texels = stbi_load_from_memory(bytes, static_cast<int>(size), &width, &height, &channels, 4);
  if (texels == nullptr) throw InputError(where + ": cannot decode the image (" + stbi_failure_reason() + ")");
  std::vector<uint8_t> rgba(texels, texels + static_cast<size_t>(width) * height * 4);
  stbi_image_free(texels);
  return std::make_shared<const Texture>(width, height, std::move(rgba), encoding);
}

std::shared_ptr<const Texture> read_texture_file(const std::filesystem::path& path, TextureEncoding encoding,
                                                 const std::string& named_by) {
  const std::string where = named_by.empty() ? path.string() : named_by + " (" + path.string() + ")";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(where + ": texture file not found");
  if (std::filesystem::file_size(path, ec) > kMaxMeshFileBytes)
    throw InputError(where + ": texture file larger than the limit of 1 GiB");
  std::ifstream in(path, std::ios::binary);
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof()) throw InputError(where + ": cannot read the texture file");
  return decode_texture(bytes.data(), bytes.size(), encoding, where);
}

}  // namespace skylit
