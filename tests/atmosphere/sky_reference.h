// Shared pieces of the atmosphere's validation tests: one default atmosphere built
// once for the whole test binary, directions relative to the sun, colour measures, and
// brute-force integrals over the sky that do not go through the tables under test.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>

#include "skylit/atmosphere/atmosphere.h"
#include "skylit/spectrum/cie.h"

namespace skylit::test_reference {

// Whether the tests should print their measured numbers (SKYLIT_REPORT set).
inline bool report() { return std::getenv("SKYLIT_REPORT") != nullptr; }

// The default atmosphere (aod_550 0.1, 300 DU, Hillaire's multiple scattering) in the
// rendering bins, built once (0.15 s) and shared by every test that reads it.
inline const Atmosphere& default_atmosphere() {
  static const Atmosphere atmosphere{AtmosphereSettings{}};
  return atmosphere;
}

// The sun's azimuth in the world frame for the shared sky models: not 0 or 180°, so
// that the conversion of world directions to the tables' sun-relative ones is
// exercised.
inline constexpr double kSunAzimuthDeg = 137.0;

// A view in the world frame given by its elevation and its azimuth from the sun's.
inline Vec3 world_direction(double elevation_deg, double azimuth_from_sun_deg) {
  return direction_from_altitude_azimuth(elevation_deg, kSunAzimuthDeg + azimuth_from_sun_deg);
}

// Sky models of the default atmosphere (0.1 s each to build), built on first use and
// shared by the tests, for a sun at an elevation (azimuth kSunAzimuthDeg) and an
// observer at a height.
inline const SkyModel& default_sky(double sun_elevation_deg, double observer_height_m = 0.0) {
  static std::mutex mutex;
  static std::map<std::pair<double, double>, std::unique_ptr<SkyModel>> models;
  const std::lock_guard<std::mutex> lock(mutex);
  std::unique_ptr<SkyModel>& model = models[{sun_elevation_deg, observer_height_m}];
  if (!model)
    model = std::make_unique<SkyModel>(
        default_atmosphere(), direction_from_altitude_azimuth(sun_elevation_deg, kSunAzimuthDeg), observer_height_m);
  return *model;
}

// The sun (or a view) at an elevation, with the sun's azimuth along +x and azimuths
// measured from it about the zenith: the frame of the sky-view tables.
inline Vec3 direction_from_sun_frame(double elevation_deg, double azimuth_from_sun_deg) {
  const double e = radians(elevation_deg), a = radians(azimuth_from_sun_deg);
  return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

struct Chromaticity {
  double x, y;
};

inline Chromaticity chromaticity(const Spectrum& spectrum) {
  const Xyz c = xyz_from_spectrum(spectrum);
  const double sum = c.x + c.y + c.z;
  return {c.x / sum, c.y / sum};
}
inline Chromaticity chromaticity(const Radiance& radiance) { return chromaticity(radiance.spectrum()); }
inline Chromaticity chromaticity(const Irradiance& irradiance) { return chromaticity(irradiance.spectrum()); }

// Correlated colour temperature (K) by McCamy (1992), Color Res. Appl. 17, 142: within
// a few K of Robertson's method from 2856 K to 6504 K, good enough to rank two colours.
inline double mccamy_cct(const Chromaticity& c) {
  const double n = (c.x - 0.3320) / (0.1858 - c.y);
  return 449.0 * n * n * n + 3525.0 * n * n + 6823.3 * n + 5520.33;
}

// The integrator's radiance (per unit solar irradiance) for a view at (elevation,
// azimuth from the sun) from radius r, with the sun at `sun_elevation_deg`.
inline Spectrum integrated_radiance(const ScatteringIntegrator& integrator, double r, double sun_elevation_deg,
                                    double elevation_deg, double azimuth_from_sun_deg, int segments) {
  const Vec3 view = direction_from_sun_frame(elevation_deg, azimuth_from_sun_deg);
  const Vec3 sun = direction_from_sun_frame(sun_elevation_deg, 0.0);
  return integrator.along_ray(r, view.z, sun.z, dot(view, sun), segments).radiance;
}

// ∫ L(ω) max(0, n·ω) dω over the whole sphere by brute force, L from the integrator
// along every ray (the ground seen through the air below the horizon), in the sun's
// frame. Midpoint rule in sin(elevation) (equal solid angles) and azimuth; azimuths
// cover the full circle, so nothing relies on the sky's symmetry.
inline Spectrum brute_force_irradiance(const ScatteringIntegrator& integrator, double r, double sun_elevation_deg,
                                       const Vec3& normal, int elevation_steps, int azimuth_steps, int segments) {
  const Vec3 sun = direction_from_sun_frame(sun_elevation_deg, 0.0);
  std::vector<Spectrum> bands(static_cast<size_t>(elevation_steps));
  tbb::parallel_for(0, elevation_steps, [&](int b) {
    const double z = -1.0 + 2.0 * (b + 0.5) / elevation_steps;
    const double c = std::sqrt(std::max(0.0, 1.0 - z * z));
    for (int a = 0; a < azimuth_steps; ++a) {
      const double phi = 2.0 * kPi * (a + 0.5) / azimuth_steps;
      const Vec3 view{c * std::cos(phi), c * std::sin(phi), z};
      const double cosine = dot(view, normal);
      if (cosine <= 0) continue;
      bands[static_cast<size_t>(b)] +=
          integrator.along_ray(r, z, sun.z, dot(view, sun), segments).radiance * static_cast<float>(cosine);
    }
  });
  Spectrum sum;
  for (const Spectrum& band : bands) sum += band;  // in order: deterministic
  return sum * static_cast<float>(4.0 * kPi / (elevation_steps * azimuth_steps));
}

}  // namespace skylit::test_reference
