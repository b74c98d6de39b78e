// Decoding UTF-8 one character at a time, for the text of figures (the bitmap font,
// SVG and HTML output), strictly after RFC 3629: no overlong forms, no surrogates, nothing past
// U+10FFFF. Labels come from users, so malformed bytes must be caught, not trusted.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace skylit {

// What decode_utf8 returns for a malformed sequence (not a Unicode character).
inline constexpr char32_t kMalformedUtf8 = 0xFFFFFFFF;

// The character starting at byte `at`, advancing `at` past it; for a malformed
// sequence kMalformedUtf8, advancing by one byte. `at` must be < text.size().
char32_t decode_utf8(std::string_view text, std::size_t& at);

// Text as XML (SVG) or HTML character data or attribute value: the five special
// characters escaped, malformed UTF-8 replaced by U+FFFD and control characters (not
// allowed in XML 1.0) dropped, so any label gives a well-formed file.
std::string xml_text(std::string_view s);

}  // namespace skylit
