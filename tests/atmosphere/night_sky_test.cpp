// The night sky's own light (atmosphere/night_sky.h): its zenith luminance against the
// published dark-site range, van Rhijn's law for the airglow, and the sky model's
// horizontal illuminance from it against a quadrature of the model's radiance.
#include "skylit/atmosphere/night_sky.h"

#include <gtest/gtest.h>

#include <cmath>

#include "skylit/atmosphere/atmosphere.h"
#include "skylit/core/angles.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

// The default clear air, built once for the tests that only read its transmittance.
const Atmosphere& clear_air() {
  static const Atmosphere air{AtmosphereSettings{}};
  return air;
}

TEST(NightSky, ZenithLuminanceOfADarkSiteIsInThePublishedRange) {
  // Duriscoe (PASP 125, 2013): natural zenith brightness 21.6–22.0 mag/arcsec² in V at
  // the darkest US parks, 1.7e-4 to 2.5e-4 cd/m² (10.8e4 cd/m² × 10^(−0.4 m)).
  const Atmosphere& air = clear_air();
  const NightSky night(NightSkySettings{}, air.bands(), air.transmittance(), 6371e3);
  const double zenith = luminance(night.radiance(1.0));
  EXPECT_GT(zenith, 1.08e5 * std::pow(10, -0.4 * 22.0));
  EXPECT_LT(zenith, 1.08e5 * std::pow(10, -0.4 * 21.6));
  // Brighter toward the horizon, as measured (Duriscoe's 60°–80° zenith-angle ring is
  // about twice the zenith), but not without bound (extinction).
  const double at_75 = luminance(night.radiance(std::cos(radians(75))));
  EXPECT_GT(at_75, 1.3 * zenith);
  EXPECT_LT(at_75, 4.0 * zenith);
}

TEST(NightSky, AirglowRisesTowardTheHorizonByVanRhijnsFactor) {
  // Airglow alone, without the air: the ratio to the zenith is van Rhijn's factor for a
  // layer at 90 km, 1/√(1 − (R/(R+h))² sin² z), written out here: 6.01 at the horizon.
  NightSkySettings only_airglow;
  only_airglow.zodiacal_cd_m2 = only_airglow.starlight_cd_m2 = 0;
  const Atmosphere& air = clear_air();
  const NightSky night(only_airglow, air.bands(), air.transmittance(), 6371e3);
  const double zenith = luminance(night.radiance_without_air(1.0));
  const double k = 6371.0 / 6461.0;
  for (double z : {30.0, 60.0, 80.0, 89.9}) {
    const double s = std::sin(radians(z));
    const double expected = 1 / std::sqrt(1 - k * k * s * s);
    EXPECT_NEAR(luminance(night.radiance_without_air(std::cos(radians(z)))) / zenith, expected, 1e-4 * expected) << z;
  }
  EXPECT_NEAR(1 / std::sqrt(1 - k * k), 6.01, 0.01);
}

TEST(NightSky, ArtificialGlowRisesTowardTheHorizonAsTheSlabLawSays) {
  NightSkySettings city;
  city.natural = false;
  city.artificial_zenith_cd_m2 = 0.01;
  const Atmosphere& air = clear_air();
  const NightSky night(city, air.bands(), air.transmittance(), 6371e3);
  EXPECT_NEAR(luminance(night.radiance(1.0)), 0.01, 1e-6);
  const double low = luminance(night.radiance(std::cos(radians(85))));
  // (1 − e^{−τX})/(1 − e^{−τ}) with τ ≈ 0.3 at 550 nm and X ≈ 10: about 3 to 4.
  EXPECT_GT(low, 2.0 * 0.01);
  EXPECT_LT(low, 6.0 * 0.01);
}

TEST(NightSky, SkyModelsHorizontalIlluminanceMatchesAQuadratureOfTheNightSky) {
  // The sun far below (no scattered sunlight left), the ground black: the sky model's
  // horizontal illuminance comes from its sky-view and irradiance tables; here it is a
  // brute-force quadrature of the night sky's radiance over the hemisphere (2000 rings
  // in zenith angle, fine enough near the horizon where the radiance changes fastest).
  // 1 %: the tables' interpolation, the tolerance.
  AtmosphereSettings settings;
  settings.ground_albedo = 0;
  settings.night_sky.artificial_zenith_cd_m2 = 1e-3;
  settings.night_sky.artificial_spectrum = Spectrum(1.0f);
  const Atmosphere air(settings);
  const SkyModel sky(air, direction_from_altitude_azimuth(-60, 0), 1.0);
  const NightSky night(settings.night_sky, air.bands(), air.transmittance(), settings.earth_radius_m);
  const int rings = 2000;
  double quadrature = 0;
  for (int k = 0; k < rings; ++k) {
    const double z = (k + 0.5) * (kPi / 2) / rings;
    quadrature += luminance(night.radiance(std::cos(z))) * std::cos(z) * std::sin(z) * 2 * kPi * (kPi / 2) / rings;
  }
  const double model = illuminance(sky.sky_irradiance({0, 0, 1}));
  EXPECT_NEAR(model, quadrature, 0.01 * quadrature);
  EXPECT_NEAR(luminance(night.horizontal_irradiance()), quadrature, 0.002 * quadrature);
  // Only the night sky: the twilight of a sun 60° down is negligible beside it.
  EXPECT_GT(quadrature, 1e-3);
}

}  // namespace
}  // namespace skylit
