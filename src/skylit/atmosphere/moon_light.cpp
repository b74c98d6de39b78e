#include "skylit/atmosphere/moon_light.h"

#include <algorithm>
#include <cmath>

#include "skylit/atmosphere/optical_properties.h"
#include "skylit/core/angles.h"
#include "skylit/spectrum/cie.h"
#include "skylit/sun/moon_position.h"

namespace skylit {

double moon_relative_reflectance(double wavelength_nm) {
  return std::clamp(1.0 + 0.0020 * (wavelength_nm - 550.0), 0.3, 1.6);
}

Spectrum moon_extraterrestrial_irradiance(const SpectralBands& bands, double earth_sun_distance_au,
                                          const MoonSettings& moon) {
  Spectrum reddened = extraterrestrial_irradiance(bands, earth_sun_distance_au);
  for (int i = 0; i < kSpectralBins; ++i)
    reddened[i] = static_cast<float>(reddened[i] * moon_relative_reflectance(bands.center_nm(i)));
  const double wanted_lx = moon_illuminance_lx(moon.phase_angle_deg, moon.distance_km);
  const double have_lx = luminance(reddened);
  return have_lx > 0 ? reddened * static_cast<float>(wanted_lx / have_lx) : Spectrum(0.0f);
}

bool moon_point_lit(double x, double y, double phase_angle_rad) {
  const double r2 = x * x + y * y;
  if (r2 >= 1) return false;
  return x * std::sin(phase_angle_rad) + std::sqrt(1 - r2) * std::cos(phase_angle_rad) > 0;
}

double moon_lit_fraction(double phase_angle_rad) { return (1 + std::cos(phase_angle_rad)) / 2; }

Spectrum moon_disc_radiance(const Spectrum& irradiance, const MoonSettings& moon, const Vec3& to_moon,
                            const Vec3& direction) {
  const double radius = radians(moon.angular_radius_deg);
  const Vec3 centre = normalize(to_moon), d = normalize(direction);
  const double cos_angle = dot(d, centre);
  if (cos_angle <= std::cos(radius)) return Spectrum(0.0f);
  // Across the sky toward the sun: the sun's direction without its part along the
  // line of sight; any perpendicular when the sun stands behind or in front of the moon.
  Vec3 toward_sun = moon.to_sun - centre * dot(moon.to_sun, centre);
  if (length(toward_sun) < 1e-9) toward_sun = cross(centre, std::abs(centre.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0});
  toward_sun = normalize(toward_sun);
  const Vec3 across = cross(centre, toward_sun);
  // The offset on the disc in radii (the gnomonic projection, exact enough at 0.26°).
  const Vec3 offset = d / cos_angle - centre;
  const double scale = std::tan(radius);
  const double x = dot(offset, toward_sun) / scale, y = dot(offset, across) / scale;
  const double phase = radians(moon.phase_angle_deg);
  if (!moon_point_lit(x, y, phase)) return Spectrum(0.0f);
  const double lit_solid_angle = 2 * kPi * (1 - std::cos(radius)) * moon_lit_fraction(phase);
  if (lit_solid_angle <= 0) return Spectrum(0.0f);
  return irradiance * static_cast<float>(1 / lit_solid_angle);
}

}  // namespace skylit
