// Decoding UTF-8 one character at a time, strictly after RFC 3629: no overlong forms, no
// surrogates, nothing past U+10FFFF; and text of unknown encoding made UTF-8.
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

// `text` unchanged if it is well-formed UTF-8, else read as Latin-1 (ISO 8859-1, whose
// bytes are the code points U+0000–U+00FF), as older files write names, and encoded.
std::string utf8_or_latin1(std::string_view text);

}  // namespace skylit
