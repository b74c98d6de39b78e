#include "skylit/atmosphere/sky_irradiance_table.h"

#include <cmath>

namespace skylit {

namespace {

constexpr int kElevationBands = 32, kAzimuthSteps = 64;

// Unit vector of a relative direction in a frame where the sun's azimuth is +x.
Vec3 unit_vector(const RelativeDirection& d) {
  const double c = std::cos(d.elevation_rad);
  return {c * std::cos(d.azimuth_from_sun_rad), c * std::sin(d.azimuth_from_sun_rad), std::sin(d.elevation_rad)};
}

}  // namespace

SkyIrradianceTable::SampledSphere SkyIrradianceTable::sample(const SkyViewTable& sky) {
  // Bands of equal solid angle (equal steps in sin e), azimuth over the full circle.
  SampledSphere sphere;
  sphere.solid_angle_each = static_cast<float>(4.0 * kPi / (kElevationBands * kAzimuthSteps));
  for (int b = 0; b < kElevationBands; ++b) {
    const double e = std::asin(-1.0 + 2.0 * (b + 0.5) / kElevationBands);
    for (int a = 0; a < kAzimuthSteps; ++a) {
      const double phi = 2.0 * kPi * (a + 0.5) / kAzimuthSteps - kPi;  // −π..π from the sun
      sphere.directions.push_back(unit_vector({e, phi}));
      sphere.radiance.push_back(sky.radiance({e, std::abs(phi)}));
    }
  }
  return sphere;
}

Spectrum SkyIrradianceTable::integrate(const SampledSphere& sphere, const Vec3& normal) {
  Spectrum sum;
  for (size_t i = 0; i < sphere.directions.size(); ++i) {
    const float cosine = static_cast<float>(dot(normal, sphere.directions[i]));
    if (cosine > 0) sum += sphere.radiance[i] * cosine;
  }
  return sum * sphere.solid_angle_each;
}

Spectrum SkyIrradianceTable::integrate(const SkyViewTable& sky, const RelativeDirection& normal) {
  return integrate(sample(sky), unit_vector(normal));
}

SkyIrradianceTable::SkyIrradianceTable(const SkyViewTable& sky, const Vec3& to_sun)
    : to_sun_(to_sun), table_(kNormalAzimuthSize, kNormalElevationSize) {
  const SampledSphere sphere = sample(sky);
  for (int j = 0; j < kNormalElevationSize; ++j) {
    const double elevation = -kPi / 2 + kPi * j / (kNormalElevationSize - 1);
    for (int i = 0; i < kNormalAzimuthSize; ++i)
      table_.at(i, j) = integrate(sphere, unit_vector({elevation, kPi * i / (kNormalAzimuthSize - 1)}));
  }
}

Spectrum SkyIrradianceTable::at(const Vec3& normal) const {
  const RelativeDirection d = relative_direction(normal, to_sun_);
  return table_.interpolate(d.azimuth_from_sun_rad / kPi * (kNormalAzimuthSize - 1),
                            (d.elevation_rad + kPi / 2) / kPi * (kNormalElevationSize - 1));
}

}  // namespace skylit
