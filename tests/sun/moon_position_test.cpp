// The moon's position and light (sun/moon_position.h) against Meeus's worked examples
// and published photometry.
#include "skylit/sun/moon_position.h"

#include <gtest/gtest.h>

#include <cmath>

#include "skylit/core/angles.h"

namespace skylit {
namespace {

// J. Meeus, Astronomical Algorithms (2nd ed.), example 47.a: 1992 April 12, 0h TD.
constexpr double kExampleJde = 2448724.5;

TEST(MoonPosition, EclipticCoordinatesAreMeeusExample47a) {
  // λ = 133.162655°, β = −3.229126°, Δ = 368409.7 km from the same 60 + 60 terms, so
  // the only differences are rounding: 1e-5° (0.04″) and 0.1 km. (The brief's bound
  // for published positions is 0.1°.)
  const MoonEcliptic m = moon_ecliptic(kExampleJde);
  EXPECT_NEAR(m.longitude_deg, 133.162655, 1e-5);
  EXPECT_NEAR(m.latitude_deg, -3.229126, 1e-5);
  EXPECT_NEAR(m.distance_km, 368409.7, 0.1);
}

TEST(MoonPosition, ApparentPlaceAndPhaseAreMeeusExamples47aAnd48a) {
  // The same instant as UT with ΔT = 0: apparent α = 134.688470°, δ = 13.768368°
  // (47.a; nutation and obliquity here from SPA's IAU 1980 series, as Meeus's: within
  // 2e-4°); phase angle i = 69.0756°, k = 0.6786 (48.a, within 0.01° from the apparent
  // solar longitude of SPA rather than Meeus's chapter 25).
  SpaOptions options;
  options.delta_t_s = 0;
  const MoonPosition p = moon_position(SiteLocation{52.0, 4.36, 0}, kExampleJde, options);
  EXPECT_NEAR(p.right_ascension_deg, 134.688470, 2e-4);
  EXPECT_NEAR(p.declination_deg, 13.768368, 2e-4);
  EXPECT_NEAR(p.phase_angle_deg, 69.0756, 0.01);
  EXPECT_NEAR(p.illuminated_fraction, 0.6786, 1e-4);
  EXPECT_NEAR(p.angular_radius_deg, 0.2702, 1e-3);  // 1737.4 km at 368 410 km
}

TEST(MoonPosition, AltitudeAndAzimuthFollowTheSky) {
  // At the example's instant from Greenwich: hour angle H = θ0 − α with θ0 (mean
  // sidereal time, Meeus 12.4) 200.44°, so the moon (α 134.7°) stands 65.8° west of the
  // meridian: in the west (azimuth 259.5°), 25.8° up. Geocentric altitude from
  // sin h = sin φ sin δ + cos φ cos δ cos H; the topocentric one is lower by the
  // parallax (up to 0.99°) and raised by refraction; within 1.1° of the geocentric.
  SpaOptions options;
  options.delta_t_s = 0;
  const SiteLocation greenwich{51.4769, 0.0, 0};
  const MoonPosition p = moon_position(greenwich, kExampleJde, options);
  const double phi = 51.4769 * kPi / 180, dec = p.declination_deg * kPi / 180;
  const double theta0 = 280.46061837 + 360.98564736629 * (kExampleJde - 2451545.0);  // mean sidereal time
  const double h = std::fmod(theta0 - p.right_ascension_deg + 3600, 360.0) * kPi / 180;
  const double geocentric =
      std::asin(std::sin(phi) * std::sin(dec) + std::cos(phi) * std::cos(dec) * std::cos(h)) * 180 / kPi;
  EXPECT_NEAR(p.altitude_deg, geocentric, 1.1);
  EXPECT_LT(p.altitude_deg, geocentric + 0.6);  // parallax lowers more than refraction lifts above ~5°
  EXPECT_GT(p.azimuth_deg, 225);
  EXPECT_LT(p.azimuth_deg, 300);
}

TEST(MoonPosition, FullMoonIlluminanceIsThePublishedFraction) {
  // Outside the atmosphere at the mean distance: 0.267 lx (C. W. Allen, Astrophysical
  // Quantities, 3rd ed., §78) to 0.31 lx (Krisciunas & Schaefer's magnitude −12.73);
  // after a clear atmosphere at high altitude 0.1–0.3 lx.
  const double full = moon_illuminance_lx(0, 384400);
  EXPECT_GT(full, 0.25);
  EXPECT_LT(full, 0.34);
  // A quarter moon (i = 90°) gives about a tenth of the full moon's light (m −10.13).
  const double quarter = moon_illuminance_lx(90, 384400);
  EXPECT_GT(quarter / full, 0.07);
  EXPECT_LT(quarter / full, 0.12);
  // The inverse square of the distance: perigee (356 500 km) 16 % more than apogee.
  EXPECT_NEAR(moon_illuminance_lx(0, 356500) / moon_illuminance_lx(0, 406700), std::pow(406700.0 / 356500, 2), 1e-12);
}

}  // namespace
}  // namespace skylit
