// The report's 16-bit logarithmic luminance codes (report_luminance.h); the page's
// script decodes them with the same formula (html_report.cpp).
#include "skylit/figures/report_luminance.h"

#include <algorithm>
#include <cmath>

namespace skylit {

uint16_t luminance_code(double luminance_cd_m2) {
  using S = LuminanceCodeScale;
  if (!(luminance_cd_m2 >= std::pow(10.0, S::kLowLog10 - S::kStepLog10 / 2))) return 0;  // also NaN
  const double steps = std::round((std::log10(luminance_cd_m2) - S::kLowLog10) / S::kStepLog10);
  return static_cast<uint16_t>(1 + std::clamp(steps, 0.0, 65534.0));
}

double luminance_from_code(uint16_t code) {
  using S = LuminanceCodeScale;
  return code == 0 ? 0.0 : std::pow(10.0, S::kLowLog10 + (code - 1) * S::kStepLog10);
}

std::vector<uint8_t> luminance_code_bytes(std::span<const float> luminance) {
  std::vector<uint8_t> bytes;
  bytes.reserve(2 * luminance.size());
  for (const float y : luminance) {
    const uint16_t code = luminance_code(y);
    bytes.push_back(static_cast<uint8_t>(code & 0xff));
    bytes.push_back(static_cast<uint8_t>(code >> 8));
  }
  return bytes;
}

}  // namespace skylit
