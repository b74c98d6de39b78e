// Strict UTF-8 decoding, and text escaped for XML and HTML (utf8.h).
#include "skylit/figures/utf8.h"

#include <string>

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

std::string xml_text(std::string_view s) {
  std::string out;
  for (std::size_t at = 0; at < s.size();) {
    const unsigned char b = static_cast<unsigned char>(s[at]);
    if (b < 0x80) {
      switch (b) {
        case '&':
          out += "&amp;";
          break;
        case '<':
          out += "&lt;";
          break;
        case '>':
          out += "&gt;";
          break;
        case '"':
          out += "&quot;";
          break;
        case '\'':
          out += "&apos;";
          break;
        default:
          if (b >= 0x20 || b == '\t') out += static_cast<char>(b);
      }
      ++at;
      continue;
    }
    const std::size_t start = at;
    const char32_t c = decode_utf8(s, at);
    if (c == kMalformedUtf8 || c == 0xFFFE || c == 0xFFFF)  // the last two are not XML characters
      out += "\uFFFD";
    else
      out += s.substr(start, at - start);
  }
  return out;
}

}  // namespace skylit
