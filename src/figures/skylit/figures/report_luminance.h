// The compact luminance layer the HTML report carries for its read-out under the mouse
// (docs/report.md): each pixel's luminance as a 16-bit code, logarithmic from 10⁻⁶ to
// 10¹⁰ cd/m² (below a starlit night's ground to above the sun's disc, 1.6 × 10⁹).
// Sixteen decades in 65 534 steps make a step of 2.44 × 10⁻⁴ decade, so a decoded
// value is within 10^(step/2) − 1 = 0.028 % of the pixel's luminance. Code 0 stands
// for anything below 10⁻⁶ cd/m² (and zero or negative luminance); values above
// 10¹⁰ take the top code.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace skylit {

struct LuminanceCodeScale {
  static constexpr double kLowLog10 = -6;   // log₁₀ of the luminance of code 1, cd/m²
  static constexpr double kHighLog10 = 10;  // of code 65535
  static constexpr double kStepLog10 = (kHighLog10 - kLowLog10) / 65534;
  static constexpr double kRelativePrecision = 2.9e-4;  // > 10^(kStepLog10/2) − 1 = 2.81e-4
};

uint16_t luminance_code(double luminance_cd_m2);
double luminance_from_code(uint16_t code);  // 0 for code 0

// The codes of `luminance` (cd/m², row by row) as little-endian bytes, 2 per pixel.
std::vector<uint8_t> luminance_code_bytes(std::span<const float> luminance);

}  // namespace skylit
