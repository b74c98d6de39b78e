// Strict UTF-8 decoding (utf8.h).
#include "skylit/core/utf8.h"

namespace skylit {

char32_t decode_utf8(std::string_view s, std::size_t& at) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(s[i]); };
  const unsigned char lead = byte(at);
  std::size_t length = 0;
  char32_t c = 0, minimum = 0;
  if (lead < 0x80) {
    ++at;
    return lead;
  }
  if ((lead & 0xE0) == 0xC0) {
    length = 2, c = lead & 0x1F, minimum = 0x80;
  } else if ((lead & 0xF0) == 0xE0) {
    length = 3, c = lead & 0x0F, minimum = 0x800;
  } else if ((lead & 0xF8) == 0xF0) {
    length = 4, c = lead & 0x07, minimum = 0x10000;
  } else {  // a continuation byte or 0xF8–0xFF where a character should start
    ++at;
    return kMalformedUtf8;
  }
  if (at + length > s.size()) {
    ++at;
    return kMalformedUtf8;
  }
  for (std::size_t i = 1; i < length; ++i) {
    if ((byte(at + i) & 0xC0) != 0x80) {
      ++at;
      return kMalformedUtf8;
    }
    c = c << 6 | (byte(at + i) & 0x3F);
  }
  if (c < minimum || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) {
    ++at;
    return kMalformedUtf8;
  }
  at += length;
  return c;
}

std::string utf8_or_latin1(std::string_view text) {
  bool well_formed = true;
  for (std::size_t at = 0; at < text.size() && well_formed;) well_formed = decode_utf8(text, at) != kMalformedUtf8;
  if (well_formed) return std::string(text);
  std::string out;
  for (const char c : text) {
    const auto code = static_cast<unsigned char>(c);
    if (code < 0x80) {
      out += c;
    } else {
      out += static_cast<char>(0xC0 | (code >> 6));
      out += static_cast<char>(0x80 | (code & 0x3F));
    }
  }
  return out;
}

}  // namespace skylit
