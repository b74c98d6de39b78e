// The moon as the sky's light (atmosphere/moon_light.h): its illuminance through the air
// against Krisciunas & Schaefer and the published range, its disc's light and phase.
#include "skylit/atmosphere/moon_light.h"

#include <gtest/gtest.h>

#include <cmath>

#include "skylit/atmosphere/atmosphere.h"
#include "skylit/core/angles.h"
#include "skylit/spectrum/cie.h"
#include "skylit/sun/moon_position.h"

namespace skylit {
namespace {

AtmosphereSettings moonlit_air(double phase_angle_deg) {
  AtmosphereSettings air;
  MoonSettings moon;
  moon.phase_angle_deg = phase_angle_deg;
  air.moon = moon;
  air.night_sky.natural = false;  // the moon's light alone
  return air;
}

// Horizontal illuminance at the ground: the direct beam on the plane and the sky's.
double horizontal_lx(const Atmosphere& atmosphere, double altitude_deg) {
  const SkyModel sky(atmosphere, direction_from_altitude_azimuth(altitude_deg, 180), 1.0);
  return illuminance(sky.direct_sun(0.0)) * std::sin(radians(altitude_deg)) +
         illuminance(sky.sky_irradiance({0, 0, 1}));
}

TEST(MoonLight, FullMoonHighInTheSkyGivesThePublishedIlluminance) {
  // A full moon at 70° altitude through a clear average atmosphere: 0.1–0.3 lx on the
  // ground (Krisciunas & Schaefer 1991; Kyba et al., Sci. Rep. 7, 2017: 0.05–0.3 lx).
  const Atmosphere atmosphere(moonlit_air(0.0));
  const double e = horizontal_lx(atmosphere, 70);
  EXPECT_GT(e, 0.1);
  EXPECT_LT(e, 0.3);
}

TEST(MoonLight, ThroughAThinAtmosphereTheIlluminanceIsTheClosedForm) {
  // Air of a 1 m Rayleigh scale height, no aerosol or ozone: a vertical optical depth
  // near 1e-5, so the ground gets what arrives outside the atmosphere, E_KS(i, d) sin h.
  // 1 %: the transmittance and the sky are both far below it; what remains is the
  // spectrum's normalisation and the renderer's binned photopic weights.
  // One phase: the normalisation does not depend on it (moon_position_test checks the
  // phase law); two altitudes, 1.5 s each (the sky model's tables).
  const double phase = 75;
  AtmosphereSettings air = moonlit_air(phase);
  air.air_density = AirDensity::exponential;
  air.rayleigh_scale_height_m = 1.0;
  air.aerosol.aod_550 = 0;
  air.ozone_column_du = 0;
  const Atmosphere atmosphere(air);
  for (double altitude : {20.0, 85.0}) {
    const double closed = moon_illuminance_lx(phase, 384400) * std::sin(radians(altitude));
    EXPECT_NEAR(horizontal_lx(atmosphere, altitude), closed, 0.01 * closed) << altitude;
  }
}

TEST(MoonLight, TheSpectrumIsRedderThanSunlightByTheMoonsColourIndex) {
  // B−V of the moon 0.92 against the sun's 0.65: the ratio of reflectances at 440 and
  // 550 nm is 10^(−0.4·0.27) = 0.78; the linear law gives 0.78 exactly at 440 nm.
  EXPECT_NEAR(moon_relative_reflectance(440) / moon_relative_reflectance(550), std::pow(10, -0.4 * 0.27), 0.01);
}

// Quadrature of the disc's radiance over a square of directions around its centre.
struct DiscSums {
  double flux = 0;                    // ∫ L dω at 550 nm
  double toward_sun = 0, across = 0;  // ∫ L x dω, ∫ L y dω
};
DiscSums disc_sums(const MoonSettings& moon, const Vec3& to_moon, const Vec3& toward_sun, const Spectrum& e) {
  const Vec3 across = cross(to_moon, toward_sun);
  const double r = radians(moon.angular_radius_deg);
  const int n = 400;
  const double step = 2.2 * r / n;
  DiscSums s;
  const int bin = 17;  // any bin
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = -1.1 * r + (i + 0.5) * step, y = -1.1 * r + (j + 0.5) * step;
      const Vec3 d = normalize(to_moon + toward_sun * x + across * y);
      const double l = moon_disc_radiance(e, moon, to_moon, d)[bin];
      const double d_omega = step * step;  // a small patch at the centre of a 0.5° field
      s.flux += l * d_omega;
      s.toward_sun += l * x * d_omega;
      s.across += l * y * d_omega;
    }
  return s;
}

TEST(MoonLight, TheDiscCarriesTheIrradianceAndItsLitSideFacesTheSun) {
  // The moon due south at 30°, the sun below the horizon in the west-north-west.
  const Vec3 to_moon = direction_from_altitude_azimuth(30, 180);
  const Vec3 to_sun = direction_from_altitude_azimuth(-15, 290);
  const Vec3 toward_sun = normalize(to_sun - to_moon * dot(to_sun, to_moon));
  const Spectrum e(1.0f);
  for (double phase : {0.0, 60.0, 90.0, 150.0}) {
    MoonSettings moon;
    moon.phase_angle_deg = phase;
    moon.to_sun = to_sun;
    const DiscSums s = disc_sums(moon, to_moon, toward_sun, e);
    // The disc integrates to the irradiance; 2 % for the square grid's edge at 400² cells
    // (the thin crescent at 150° has the fewest).
    EXPECT_NEAR(s.flux, 1.0, 0.02) << phase;
    // The lit part's centroid lies toward the sun on the sky, and not sideways; a full
    // moon is centred.
    const double centroid = s.toward_sun / s.flux / radians(moon.angular_radius_deg);
    if (phase > 0) {
      EXPECT_GT(centroid, 0.1) << phase;
    } else {
      EXPECT_NEAR(centroid, 0.0, 0.01);
    }
    EXPECT_NEAR(s.across / s.flux / radians(moon.angular_radius_deg), 0.0, 0.01) << phase;
  }
}

TEST(MoonLight, LitFractionOfTheDiscFollowsThePhase) {
  // Counting lit points of a fine grid on the disc against (1 + cos i)/2, to 0.5 %.
  for (double phase : {30.0, 90.0, 140.0}) {
    const double i = radians(phase);
    int lit = 0, all = 0;
    for (int a = 0; a < 600; ++a)
      for (int b = 0; b < 600; ++b) {
        const double x = (a + 0.5) / 300 - 1, y = (b + 0.5) / 300 - 1;
        if (x * x + y * y >= 1) continue;
        ++all;
        lit += moon_point_lit(x, y, i);
      }
    EXPECT_NEAR(static_cast<double>(lit) / all, moon_lit_fraction(i), 0.005) << phase;
  }
}

}  // namespace
}  // namespace skylit
