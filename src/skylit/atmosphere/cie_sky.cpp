#include "skylit/atmosphere/cie_sky.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "skylit/core/angles.h"

namespace skylit {

namespace {

// ISO 15469:2004 / CIE S 011/E:2003, Table 1: six gradation groups (a, b) and six
// indicatrix groups (c, d, e), and which of each the fifteen types combine.
constexpr std::array<std::array<double, 2>, 6> kGradation{{
    {4.0, -0.70},   // I
    {1.1, -0.80},   // II
    {0.0, -1.00},   // III
    {-1.0, -0.55},  // IV
    {-1.0, -0.32},  // V
    {-1.0, -0.15},  // VI
}};
constexpr std::array<std::array<double, 3>, 6> kIndicatrix{{
    {0, -1.0, 0.00},   // 1
    {2, -1.5, 0.15},   // 2
    {5, -2.5, 0.30},   // 3
    {10, -3.0, 0.45},  // 4
    {16, -3.0, 0.30},  // 5
    {24, -2.8, 0.15},  // 6
}};
// Type k (1-based) → {gradation group, indicatrix group}, both 1-based.
constexpr std::array<std::array<int, 2>, kCieSkyTypes> kTypeGroups{{
    {1, 1},
    {1, 2},
    {2, 1},
    {2, 2},
    {3, 1},
    {3, 2},
    {3, 3},
    {3, 4},
    {4, 2},
    {4, 3},
    {4, 4},
    {5, 4},
    {5, 5},
    {6, 5},
    {6, 6},
}};

double gradation(const CieSkyParameters& p, double cos_zenith) {
  // exp(b / cos Z) → 0 at the horizon (b < 0).
  return cos_zenith <= 0 ? 1.0 : 1.0 + p.a * std::exp(p.b / cos_zenith);
}

double indicatrix(const CieSkyParameters& p, double chi_rad) {
  const double c = std::cos(chi_rad);
  return 1.0 + p.c * (std::exp(p.d * chi_rad) - std::exp(p.d * kPi / 2)) + p.e * c * c;
}

}  // namespace

CieSkyParameters cie_sky_parameters(int type) {
  if (type < 1 || type > kCieSkyTypes) throw std::invalid_argument("CIE sky type must be 1 to 15");
  const auto [g, i] = kTypeGroups[static_cast<size_t>(type - 1)];
  const auto& ab = kGradation[static_cast<size_t>(g - 1)];
  const auto& cde = kIndicatrix[static_cast<size_t>(i - 1)];
  return {ab[0], ab[1], cde[0], cde[1], cde[2]};
}

double cie_relative_luminance(const CieSkyParameters& p, const Vec3& view, const Vec3& to_sun) {
  if (view.z < 0) return 0.0;
  const double chi = std::acos(std::clamp(dot(view, to_sun), -1.0, 1.0));
  const double sun_zenith = std::acos(std::clamp(to_sun.z, -1.0, 1.0));
  return indicatrix(p, chi) * gradation(p, view.z) / (indicatrix(p, sun_zenith) * gradation(p, 1.0));
}

double cie_horizontal_illuminance_per_zenith_luminance(const CieSkyParameters& p, const Vec3& to_sun) {
  // Midpoint rule in (cos Z, azimuth): dω cos Z = cos Z d(cos Z) dA.
  constexpr int kRings = 400, kSectors = 720;
  double sum = 0;
  for (int i = 0; i < kRings; ++i) {
    const double mu = (i + 0.5) / kRings, s = std::sqrt(1 - mu * mu);
    for (int j = 0; j < kSectors; ++j) {
      const double phi = 2 * kPi * (j + 0.5) / kSectors;
      sum += mu * cie_relative_luminance(p, {s * std::cos(phi), s * std::sin(phi), mu}, to_sun);
    }
  }
  return sum * (1.0 / kRings) * (2 * kPi / kSectors);
}

}  // namespace skylit
