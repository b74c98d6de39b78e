// Shapes and lights shared by the cloud tests (tests/clouds/*_test.cpp).
#pragma once

#include <cmath>
#include <limits>

#include "skylit/clouds/cloud.h"

namespace skylit {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

inline CloudShape wavy_cloud() {
  CloudShape s;
  s.center_x = 300;
  s.center_y = -200;
  s.altitude = 1500;
  s.semi_axis_a = 1200;
  s.semi_axis_b = 700;
  s.rotation = 0.6;
  s.max_thickness = 400;
  s.waves_u = {{0.3, 2 * kPi / 1000, 0.4}, {0.21, 4 * kPi / 1000, 2.0}, {0.15, 8 * kPi / 1000, 5.1}};
  s.waves_v = {{0.3, 2 * kPi / 600, 1.3}, {0.21, 4 * kPi / 600, 0.2}};
  return s;
}

// World position of local (u, v) on a cloud.
inline Vec3 local_point(const CloudShape& s, double u, double v, double z) {
  const double c = std::cos(s.rotation), sn = std::sin(s.rotation);
  return {s.center_x + u * c - v * sn, s.center_y + u * sn + v * c, z};
}

inline float total(const Spectrum& s) {
  float sum = 0;
  for (int i = 0; i < Spectrum::size(); ++i) sum += s[i];
  return sum;
}

inline CloudLighting flat_light(const Vec3& to_sun) {
  CloudLighting l;
  l.to_sun = normalize(to_sun);
  l.sun = Spectrum(1.5f);
  l.sky_from_above = Spectrum(0.3f);
  l.sky_from_below = Spectrum(0.1f);
  return l;
}

}  // namespace skylit
