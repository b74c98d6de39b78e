// Numbers in text, printf-style, for the reports the program writes (`skylit info`, the
// weather's summary).
#pragma once

#include <cstdio>
#include <string>

namespace skylit {

// `pattern` with up to three numbers, e.g. formatted("%.1f m, %.0f %%", 2.5, 40).
// Cut at 255 characters, far beyond any line of a report.
inline std::string formatted(const char* pattern, double a, double b = 0, double c = 0) {
  char text[256];
  std::snprintf(text, sizeof text, pattern, a, b, c);
  return text;
}

}  // namespace skylit
