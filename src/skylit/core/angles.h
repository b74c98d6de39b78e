// π and conversions between degrees and radians, for every folder.
#pragma once

#include <numbers>

namespace skylit {

inline constexpr double kPi = std::numbers::pi;
constexpr double radians(double degrees) { return degrees * (kPi / 180.0); }
constexpr double degrees(double radians) { return radians * (180.0 / kPi); }

}  // namespace skylit
