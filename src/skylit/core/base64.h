// Base64 (RFC 4648, the standard alphabet with '=' padding), for binary data carried in
// text: the images and the luminance layer of the HTML report.
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace skylit {

std::string base64_encode(std::span<const uint8_t> bytes);

}  // namespace skylit
