// Aerial perspective (the air between the observer and a surface) against closed forms,
// limits and the integrator itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "sky_reference.h"
#include "skylit/atmosphere/atmosphere.h"

namespace skylit {
namespace {

using test_reference::default_atmosphere;
using test_reference::default_sky;
using test_reference::world_direction;

using test_reference::report;

// A pedestrian's eye, 2 m above the ground, with the sun at 30°.
constexpr double kEyeHeightM = 2.0, kSunDeg = 30.0;

TEST(AerialPerspective, ShortHorizontalPathTransmittanceIsBeerLambert) {
  // Over 500 m at 2 m the air is uniform: the ray rises d²/2R = 2 cm, so the
  // transmittance is exp(−σ_t d) with σ_t from the medium's coefficients at 2 m
  // (Rayleigh and aerosols; no ozone below 10 km). Tolerance 0.5 %: the table
  // interpolates linearly in √d between its slices at 312 and 703 m, where exp(−σ_t d)
  // bends by at most ~0.3 % (σ_t ≤ 1.7e-4 m⁻¹ in the violet). Measured: 0.29 %.
  const Atmosphere& atmosphere = default_atmosphere();
  const AtmosphereMedium& medium = atmosphere.medium();
  const SkyModel& sky = default_sky(kSunDeg, kEyeHeightM);
  const double d = 500.0;
  const Spectrum sigma_t =
      medium.extinction(medium.rayleigh_density(kEyeHeightM), medium.aerosol_density(kEyeHeightM), 0.0);
  double worst = 0;
  for (double azimuth : {0.0, 90.0, 180.0}) {
    const MediumStretch air = sky.aerial_perspective(world_direction(0.0, azimuth), d);
    for (int k = 0; k < kSpectralBins; ++k) {
      const double expected = std::exp(-static_cast<double>(sigma_t[k]) * d);
      worst = std::max(worst, std::abs(air.transmittance[k] / expected - 1.0));
      EXPECT_NEAR(air.transmittance[k], expected, 0.005 * expected) << "azimuth " << azimuth << ", bin " << k;
    }
  }
  if (report()) std::printf("500 m horizontal transmittance: worst %.3f %%\n", 100 * worst);
}

TEST(AerialPerspective, NothingAtZeroDistance) {
  // At the observer nothing is added and everything gets through, exactly (the table's
  // first slice), and both approach that limit continuously: at 1 cm the in-scatter is
  // under 2 % of that over 100 m and the transmittance within 1e-3 of 1. (The truth is
  // 0.01 % and 2e-6; the table's √d interpolation gives ~1 % and 1.6e-4 — see
  // DISABLED_InScatterNearTheObserver… below — so these bounds only check the limit.)
  const SkyModel& sky = default_sky(kSunDeg, kEyeHeightM);
  for (double elevation : {-1.0, 0.0, 5.0, 45.0})
    for (double azimuth : {0.0, 100.0, 180.0}) {
      const Vec3 view = world_direction(elevation, azimuth);
      const MediumStretch zero = sky.aerial_perspective(view, 0.0);
      const MediumStretch centimetre = sky.aerial_perspective(view, 0.01);
      const MediumStretch hundred = sky.aerial_perspective(view, 100.0);
      for (int k = 0; k < kSpectralBins; ++k) {
        EXPECT_EQ(zero.in_scattered[k], 0.0f);
        EXPECT_EQ(zero.transmittance[k], 1.0f);
        EXPECT_GT(centimetre.transmittance[k], 0.999f);
        EXPECT_LT(centimetre.in_scattered[k], 0.02f * hundred.in_scattered[k])
            << elevation << " " << azimuth << " bin " << k;
      }
    }
}

TEST(AerialPerspective, InScatterGrowsAndTransmittanceFallsWithDistance) {
  // Monotonic in every bin (to float rounding, 1e-6), from the observer to beyond the
  // table's 80 km; and it does grow: 10 km of air add more light than 1 km.
  const SkyModel& sky = default_sky(kSunDeg, kEyeHeightM);
  for (double elevation : {-1.0, 0.0, 3.0, 20.0, 60.0})
    for (double azimuth : {0.0, 60.0, 180.0}) {
      const Vec3 view = world_direction(elevation, azimuth);
      MediumStretch previous = sky.aerial_perspective(view, 0.0);
      for (int i = 1; i <= 300; ++i) {
        const double d = 100e3 * std::pow(i / 300.0, 2);
        const MediumStretch now = sky.aerial_perspective(view, d);
        for (int k = 0; k < kSpectralBins; ++k) {
          ASSERT_GE(now.in_scattered[k], previous.in_scattered[k] * (1 - 1e-6f))
              << elevation << " " << azimuth << " " << d << " bin " << k;
          ASSERT_LE(now.transmittance[k], previous.transmittance[k] * (1 + 1e-6f))
              << elevation << " " << azimuth << " " << d;
        }
        previous = now;
      }
      if (elevation >= 0) {
        EXPECT_GT(luminance(sky.aerial_perspective(view, 10e3).in_scattered),
                  1.5 * luminance(sky.aerial_perspective(view, 1e3).in_scattered));
      }
    }
}

TEST(AerialPerspective, LongNearlyHorizontalPathApproachesTheHorizonSky) {
  // 0.1° above the horizontal, 80 km of air near the ground (optical depth 3.6–12
  // across the bins) hide most of what lies beyond: the air's own light is the sky's
  // in that direction, less what the rest of the path adds — up to T(80 km) = 2.6 %
  // of it in the far red (3.0 % with continental average aerosol, α = 1.42), nothing in the violet — and less the
  // difference of two tables that sample the horizon differently (32 × 32 directions vs 96 × 128). Measured: the worst
  // bin (775 nm) −2.1 … −3.0 %, luminance within 0.2 %. Tolerance 4 %. (Exactly horizontal the table is wrong:
  // DISABLED_HorizontalViewsFarAway… below.)
  const SkyModel& sky = default_sky(kSunDeg, kEyeHeightM);
  for (double azimuth : {20.0, 90.0, 180.0}) {
    const Vec3 view = world_direction(0.1, azimuth);
    const MediumStretch air = sky.aerial_perspective(view, AerialPerspectiveTable::kMaxDistanceM);
    const Radiance horizon = sky.sky_radiance(view);
    double worst = 0;
    for (int k = 0; k < kSpectralBins; ++k) worst = std::max(worst, std::abs(air.in_scattered[k] / horizon[k] - 1.0));
    if (report())
      std::printf("80 km at 0.1 deg, %.0f deg from the sun: worst bin %.2f %%, luminance %.2f %%\n", azimuth,
                  100 * worst, 100 * (luminance(air.in_scattered) / luminance(horizon) - 1));
    EXPECT_LT(worst, 0.04) << azimuth;
    EXPECT_LT(air.transmittance[kSpectralBins - 1], 0.035f);
  }
}

// The table against ScatteringIntegrator::up_to with 400 stops (800 segments) up to
// the same distance, per bin: the worst relative error of in-scatter and transmittance.
struct TableError {
  double radiance = 0, transmittance = 0;
};
TableError table_error(double elevation, double azimuth, double d) {
  const Atmosphere& atmosphere = default_atmosphere();
  const SkyModel& sky = default_sky(kSunDeg, kEyeHeightM);
  const double r = atmosphere.ground_radius() + kEyeHeightM;
  const Vec3 sun = test_reference::direction_from_sun_frame(kSunDeg, 0.0);
  const Vec3 view = test_reference::direction_from_sun_frame(elevation, azimuth);
  std::vector<double> stops;
  for (int i = 1; i <= 400; ++i) stops.push_back(d * i / 400.0);
  const ScatteredLight direct = atmosphere.integrator().up_to(r, view.z, sun.z, dot(view, sun), stops).back();
  const MediumStretch table = sky.aerial_perspective(world_direction(elevation, azimuth), d);
  const Radiance radiance(direct.radiance * atmosphere.extraterrestrial_irradiance().spectrum());
  TableError e;
  for (int k = 0; k < kSpectralBins; ++k) {
    e.radiance = std::max(e.radiance, std::abs(static_cast<double>(table.in_scattered[k]) / radiance[k] - 1.0));
    e.transmittance = std::max(e.transmittance,
                               std::abs(static_cast<double>(table.transmittance[k]) / direct.transmittance[k] - 1.0));
  }
  return e;
}

TEST(AerialPerspective, TableMatchesTheIntegrator) {
  // Where the table is meant to be used at its accuracy: surfaces 1–20 km away, views
  // 0.5–45° up and at least 60° in azimuth from the sun. Measured worst bin: in-scatter
  // 2.1 % (1 km, between slices at 0.70 and 1.25 km), transmittance 3.3 % (20 km at
  // 0.5°, where T is ~0.03 and interpolated linearly between elevation rows 0.05° and
  // 0.8° whose optical depths differ by ×2). Tolerances 2.5 % and 4 %.
  TableError worst;
  for (double elevation : {0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 45.0})
    for (double azimuth : {60.0, 90.0, 180.0})
      for (double d : {1e3, 2e3, 5e3, 10e3, 20e3}) {
        const TableError e = table_error(elevation, azimuth, d);
        worst.radiance = std::max(worst.radiance, e.radiance);
        worst.transmittance = std::max(worst.transmittance, e.transmittance);
        EXPECT_LT(e.radiance, 0.025) << elevation << " " << azimuth << " " << d;
        EXPECT_LT(e.transmittance, 0.04) << elevation << " " << azimuth << " " << d;
      }
  if (report())
    std::printf("aerial perspective table vs up_to: in-scatter %.2f %%, transmittance %.2f %%\n", 100 * worst.radiance,
                100 * worst.transmittance);
}

// Near the observer: in-scatter and optical depth grow in proportion to distance, and
// the table interpolates linearly in distance between its slices (0, 78, 312 m, …), so
// the first metres are as accurate as the slices themselves. (Interpolating in the
// slices' own √d spacing made the in-scatter 1,200 % too high at 1 m; the segment
// weight (1 − e^(−σΔt))/σ also needed its series for thin segments in single precision.)
TEST(AerialPerspective, InScatterNearTheObserverMatchesTheIntegrator) {
  for (double elevation : {0.5, 10.0})
    for (double azimuth : {90.0, 180.0})
      for (double d : {1.0, 10.0, 30.0, 100.0, 200.0, 500.0})
        EXPECT_LT(table_error(elevation, azimuth, d).radiance, 0.02) << elevation << " " << azimuth << " " << d;
}

// Exactly horizontal from 2 m: a table row lies at the horizon's dip (an odd row count)
// and rays below it go on through the ground, so there is no jump at the horizon.
// Within 5 km (a city's views): 2 %. Farther, the optical depth differs a lot between the
// dip's row (−0.045°) and the next (+0.31°), whose ray has climbed 325 m at 60 km: the
// transmittance is then off by 3.2 % at 20 km (where it is 0.16) and 27 % at 60 km —
// where it is below 0.05, so the surface's share of the pixel is wrong by less than
// 1.5 % of its own radiance.
TEST(AerialPerspective, HorizontalViewsFarAwayMatchTheIntegrator) {
  for (double azimuth : {20.0, 90.0, 180.0}) {
    for (double d : {1e3, 2e3, 5e3}) {
      const TableError e = table_error(0.0, azimuth, d);
      EXPECT_LT(e.radiance, 0.02) << azimuth << " " << d;
      EXPECT_LT(e.transmittance, 0.02) << azimuth << " " << d;
    }
    for (double d : {20e3, 60e3}) EXPECT_LT(table_error(0.0, azimuth, d).radiance, 0.03) << azimuth << " " << d;
    const SkyModel& sky = default_sky(kSunDeg, kEyeHeightM);
    const Vec3 view = world_direction(0.0, azimuth);
    EXPECT_LT(table_error(0.0, azimuth, 20e3).transmittance, 0.04) << azimuth;
    const double t60 =
        luminance(sky.aerial_perspective(view, 60e3).transmittance.spectrum()) / luminance(Spectrum(1.0f));
    EXPECT_LT(t60, 0.05) << azimuth;
    EXPECT_NEAR(luminance(sky.aerial_perspective(view, AerialPerspectiveTable::kMaxDistanceM).in_scattered),
                luminance(sky.sky_radiance(view)), 0.04 * luminance(sky.sky_radiance(view)));
  }
}

}  // namespace
}  // namespace skylit
