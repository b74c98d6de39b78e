// perez_daylight_efficacy (luminous_efficacy.h).
#include "skylit/io/weather/luminous_efficacy.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "skylit/core/angles.h"

namespace skylit {

namespace {

// The lower bounds of Perez's eight clearness ranges (the last is open).
constexpr std::array<double, 8> kClearnessFrom{1.000, 1.065, 1.230, 1.500, 1.950, 2.800, 4.500, 6.200};

// Table 4 of Perez et al. (1990): a, b, c, d per clearness range.
struct Coefficients {
  std::array<double, 8> a, b, c, d;
};
// Global horizontal: a + b·W + c·cos Z + d·ln Δ.
constexpr Coefficients kGlobal{{96.63, 107.54, 98.73, 92.72, 86.73, 88.34, 78.63, 99.65},
                               {-0.47, 0.79, 0.70, 0.56, 0.98, 1.39, 1.47, 1.86},
                               {11.50, 1.79, 4.40, 8.36, 7.10, 6.06, 4.93, -4.46},
                               {-9.16, -1.19, -6.95, -8.31, -10.94, -7.60, -11.37, -3.15}};
// Direct normal: a + b·W + c·exp(5.73·Z − 5) + d·Δ (Z in radians), not below 0.
constexpr Coefficients kDirect{{57.20, 98.99, 109.83, 110.34, 106.36, 107.19, 105.75, 101.18},
                               {-4.55, -3.46, -4.90, -5.84, -3.97, -1.25, 0.77, 1.58},
                               {-2.98, -1.21, -1.71, -1.99, -1.75, -1.51, -1.26, -1.10},
                               {117.12, 12.38, -8.81, -4.56, -6.16, -26.73, -34.44, -8.29}};
// Diffuse horizontal: a + b·W + c·cos Z + d·ln Δ.
constexpr Coefficients kDiffuse{{97.24, 107.22, 104.97, 102.39, 100.71, 106.42, 141.88, 152.23},
                                {-0.46, 1.15, 2.96, 5.59, 5.94, 3.83, 1.90, 0.35},
                                {12.00, 0.59, -5.53, -13.95, -22.75, -36.15, -53.24, -45.27},
                                {-8.91, -3.95, -8.77, -13.90, -23.74, -28.83, -14.03, -7.98}};

// Kasten and Young (1989): the relative optical air mass at zenith angle Z (degrees).
double air_mass(double zenith_deg) {
  return 1.0 / (std::cos(radians(zenith_deg)) + 0.50572 * std::pow(96.07995 - zenith_deg, -1.6364));
}

}  // namespace

std::optional<DaylightEfficacy> perez_daylight_efficacy(double direct_normal_w_m2, double diffuse_horizontal_w_m2,
                                                        double sun_zenith_deg, double precipitable_water_cm,
                                                        double extraterrestrial_normal_w_m2) {
  if (!(sun_zenith_deg >= 0 && sun_zenith_deg < 90) || !(diffuse_horizontal_w_m2 > 0) || !(direct_normal_w_m2 >= 0) ||
      !(extraterrestrial_normal_w_m2 > 0) || !std::isfinite(direct_normal_w_m2) ||
      !std::isfinite(diffuse_horizontal_w_m2) || !std::isfinite(precipitable_water_cm))
    return std::nullopt;
  const double z = radians(sun_zenith_deg);
  const double kz3 = 1.041 * z * z * z;
  DaylightEfficacy out;
  out.clearness = ((diffuse_horizontal_w_m2 + direct_normal_w_m2) / diffuse_horizontal_w_m2 + kz3) / (1 + kz3);
  out.brightness = diffuse_horizontal_w_m2 * air_mass(sun_zenith_deg) / extraterrestrial_normal_w_m2;
  const auto range = static_cast<size_t>(std::upper_bound(kClearnessFrom.begin(), kClearnessFrom.end(), out.clearness) -
                                         kClearnessFrom.begin() - 1);
  // W beyond 7 cm (more than the wettest air holds) and Δ below 0.01 (a sky far darker
  // than daylight's) lie outside the laws' ground; there ln Δ would run away.
  const double w = std::clamp(precipitable_water_cm, 0.0, 7.0);
  const double log_delta = std::log(std::max(out.brightness, 0.01));
  auto linear = [&](const Coefficients& k, double zenith_term, double delta_term) {
    return k.a[range] + k.b[range] * w + k.c[range] * zenith_term + k.d[range] * delta_term;
  };
  // Not below 0 either (the laws stay positive over the skies they were fitted to; a
  // file's extreme values may lie outside them).
  out.global_lm_w = std::max(0.0, linear(kGlobal, std::cos(z), log_delta));
  out.diffuse_lm_w = std::max(0.0, linear(kDiffuse, std::cos(z), log_delta));
  out.direct_lm_w = std::max(0.0, linear(kDirect, std::exp(5.73 * z - 5), out.brightness));
  return out;
}

double precipitable_water_cm_from_dew_point(double dew_point_c) { return std::exp(0.07 * dew_point_c - 0.075); }

}  // namespace skylit
