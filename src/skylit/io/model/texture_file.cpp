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

// Whether stb takes the bytes for a JPEG: its start marker FF D8, after any fill bytes FF.
bool is_jpeg(const unsigned char* bytes, size_t size) {
  size_t at = 0;
  while (at < size && bytes[at] == 0xFF) ++at;
  return at > 0 && at < size && bytes[at] == 0xD8;
}

uint32_t big_endian_at(const unsigned char* bytes, size_t at) {
  return static_cast<uint32_t>(bytes[at]) << 24 | static_cast<uint32_t>(bytes[at + 1]) << 16 |
         static_cast<uint32_t>(bytes[at + 2]) << 8 | bytes[at + 3];
}

// Whether every JPEG Huffman table (DHT segment) codes at most 256 symbols. Debian
// 12's stb_image writes past its 257-entry table for one that codes more (found by
// the texture fuzz target), so such a file is refused before it reaches stb. In
// entropy-coded data 0xFF is stuffed as FF 00, so FF C4 is always a DHT marker.
bool jpeg_huffman_tables_fit(const unsigned char* bytes, size_t size) {
  if (!is_jpeg(bytes, size)) return true;  // a BMP's or TGA's texels may hold FF C4
  for (size_t p = 0; p + 4 <= size; ++p) {
    if (bytes[p] != 0xFF || bytes[p + 1] != 0xC4) continue;
    const size_t end = std::min(size, p + 2 + (size_t{bytes[p + 2]} << 8 | bytes[p + 3]));
    // As stb reads it: tables while the segment lasts, each table's 16 counts even
    // where they run past the segment's stated end.
    for (size_t q = p + 4; q < end;) {
      size_t symbols = 0;
      for (size_t i = 1; i <= 16 && q + i < size; ++i) symbols += bytes[q + i];
      if (symbols > 256) return false;
      q += 17 + symbols;
    }
  }
  return true;
}

// Whether a JPEG scan decodes with a Huffman table that no DHT segment before it
// defined. Debian 12's stb_image then reads its table from memory it never set (its
// decoder's state is malloc'd), so the same file read out of bounds at random (found by
// the texture fuzz target: a scan using AC table 1 of a file defining only AC table 0).
// Walked as stb walks it: segment by segment by their lengths, bytes between them
// skipped, and after a scan's header its entropy-coded data (where FF is stuffed as
// FF 00 and FF D0–D7 are restart markers) up to the next marker. A progressive scan
// decodes with the DC tables only when it is a first DC scan (Ss 0, Ah 0), with the AC
// tables only when Ss > 0; a baseline one with both. Table numbers above 3 stb refuses.
bool jpeg_scan_uses_undefined_table(const unsigned char* bytes, size_t size) {
  bool defined[2][4] = {};
  bool progressive = false;
  size_t p = 0;
  const auto length_at = [&](size_t at) { return at + 4 <= size ? size_t{bytes[at + 2]} << 8 | bytes[at + 3] : 0; };
  while (p + 1 < size) {
    const unsigned char marker = bytes[p + 1];
    if (bytes[p] != 0xFF || marker == 0xFF || marker == 0x00 || (marker >= 0xD0 && marker <= 0xD9) || marker == 0x01) {
      ++p;  // not a marker, fill, stuffing, or a marker without a segment
      continue;
    }
    const size_t end = std::min(size, p + 2 + length_at(p));
    if (marker == 0xC4) {
      for (size_t q = p + 4; q < end;) {
        const unsigned table_class = bytes[q] >> 4, id = bytes[q] & 15;
        if (table_class < 2 && id < 4) defined[table_class][id] = true;
        size_t symbols = 0;
        for (size_t i = 1; i <= 16 && q + i < size; ++i) symbols += bytes[q + i];
        q += 17 + symbols;
      }
    } else if (marker >= 0xC0 && marker <= 0xC2) {
      progressive = marker == 0xC2;
    } else if (marker == 0xDA && p + 5 <= size) {
      const size_t components = bytes[p + 4], spectral_at = p + 5 + 2 * components;
      if (spectral_at + 3 > size) return false;  // cut short: stb refuses it
      const bool first_dc = bytes[spectral_at] == 0 && (bytes[spectral_at + 2] >> 4) == 0;
      const bool uses_dc = !progressive || first_dc, uses_ac = !progressive || bytes[spectral_at] > 0;
      for (size_t k = 0; k < components; ++k) {
        const unsigned dc = bytes[p + 6 + 2 * k] >> 4, ac = bytes[p + 6 + 2 * k] & 15;
        if ((uses_dc && dc < 4 && !defined[0][dc]) || (uses_ac && ac < 4 && !defined[1][ac])) return true;
      }
    }
    p = std::max(end, p + 2);
  }
  return false;
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
  if (!jpeg_huffman_tables_fit(bytes, size))
    throw InputError(where + ": cannot decode the image (a JPEG Huffman table codes more than 256 symbols)");
  if (is_jpeg(bytes, size) && jpeg_scan_uses_undefined_table(bytes, size))
    throw InputError(where + ": cannot decode the image (a JPEG scan uses a Huffman table the file does not define)");
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
  if (width <= 0 || height <= 0 || width > kMaxTextureSide || height > kMaxTextureSide)
    throw InputError(where + ": the image is " + std::to_string(width) + " × " + std::to_string(height) +
                     " texels; at most " + std::to_string(kMaxTextureSide) + " a side is read");
  // stb reads a BMP or TGA shorter than its header claims as if zeros followed (a
  // 49-byte TGA from the fuzzer made 72 million texels); PNG and JPEG fail instead.
  // Their run-length codings hold fewer than 256 texels a byte, so more is not the file.
  if (!is_png(bytes, size) && !is_jpeg(bytes, size) &&
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
