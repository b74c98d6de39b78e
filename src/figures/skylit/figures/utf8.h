// The text of figures (the bitmap font, SVG and HTML output), decoded strictly as UTF-8
// (core/utf8.h). Labels come from users, so malformed bytes must be caught, not trusted.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "skylit/core/utf8.h"

namespace skylit {

// Text as XML (SVG) or HTML character data or attribute value: the five special
// characters escaped, malformed UTF-8 replaced by U+FFFD and control characters (not
// allowed in XML 1.0) dropped, so any label gives a well-formed file.
std::string xml_text(std::string_view s);

}  // namespace skylit
