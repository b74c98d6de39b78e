// Strict number parsing for the photometric readers (IES LM-63-02, EULUMDAT): a
// whole token must be a finite decimal number, so "12abc", "inf" or "1e999" are
// refused rather than half-read — the readers turn a refusal into file:line errors.
#pragma once

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

namespace skylit::lights_detail {

inline std::optional<double> parse_number(std::string_view token) {
  if (token.empty() || token.size() > 64) return std::nullopt;
  for (char ch : token) {
    // Only what a decimal number may contain (strtod would also take hex and "nan").
    if (!((ch >= '0' && ch <= '9') || ch == '.' || ch == '-' || ch == '+' || ch == 'e' || ch == 'E'))
      return std::nullopt;
  }
  const std::string text(token);
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace skylit::lights_detail
