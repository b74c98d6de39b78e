// Text escaped for XML and HTML (utf8.h).
#include "skylit/figures/utf8.h"

#include <string>

namespace skylit {

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
