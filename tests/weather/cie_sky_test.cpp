// CIE standard general skies (atmosphere/cie_sky.h, cie_sky_view.h): each type's
// relative luminance against the standard's formula written independently, two
// published values of the overcast sky, and the scaled sky as the renderer reads it
// against the illuminance asked for.
#include "skylit/atmosphere/cie_sky.h"

#include <gtest/gtest.h>

#include <cmath>

#include "skylit/atmosphere/atmosphere.h"
#include "skylit/atmosphere/cie_sky_view.h"
#include "skylit/atmosphere/sky_irradiance_table.h"
#include "skylit/core/angles.h"
#include "skylit/spectrum/cie.h"

namespace skylit {
namespace {

// The standard's Table 1 as printed: type → a, b, c, d, e.
constexpr double kTable[kCieSkyTypes][5] = {
    {4.0, -0.70, 0, -1.0, 0},      {4.0, -0.70, 2, -1.5, 0.15},   {1.1, -0.8, 0, -1.0, 0},
    {1.1, -0.8, 2, -1.5, 0.15},    {0, -1.0, 0, -1.0, 0},         {0, -1.0, 2, -1.5, 0.15},
    {0, -1.0, 5, -2.5, 0.30},      {0, -1.0, 10, -3.0, 0.45},     {-1.0, -0.55, 2, -1.5, 0.15},
    {-1.0, -0.55, 5, -2.5, 0.30},  {-1.0, -0.55, 10, -3.0, 0.45}, {-1.0, -0.32, 10, -3.0, 0.45},
    {-1.0, -0.32, 16, -3.0, 0.30}, {-1.0, -0.15, 16, -3.0, 0.30}, {-1.0, -0.15, 24, -2.8, 0.15},
};

// The standard's Eqs. written in its own angles: zenith angles Z, Z_s and the azimuth
// difference, χ by the spherical law of cosines (the code uses a dot product).
double standard_relative_luminance(int type, double z_deg, double az_deg, double zs_deg) {
  const double* p = kTable[type - 1];
  const double z = radians(z_deg), zs = radians(zs_deg);
  const double chi = std::acos(std::cos(zs) * std::cos(z) + std::sin(zs) * std::sin(z) * std::cos(radians(az_deg)));
  const auto phi = [&](double zz) { return z_deg == 90 && zz == z ? 1.0 : 1 + p[0] * std::exp(p[1] / std::cos(zz)); };
  const auto f = [&](double x) {
    return 1 + p[2] * (std::exp(p[3] * x) - std::exp(p[3] * kPi / 2)) + p[4] * std::cos(x) * std::cos(x);
  };
  return f(chi) * phi(z) / (f(zs) * (1 + p[0] * std::exp(p[1])));
}

Vec3 direction(double zenith_deg, double azimuth_deg) {
  const double z = radians(zenith_deg), a = radians(azimuth_deg);
  return {std::sin(z) * std::sin(a), std::sin(z) * std::cos(a), std::cos(z)};
}

TEST(CieSky, EachTypeFollowsTheStandardsFormulaAtTestDirections) {
  const double sun_zenith = 50, sun_azimuth = 160;
  const Vec3 to_sun = direction(sun_zenith, sun_azimuth);
  for (int type = 1; type <= kCieSkyTypes; ++type) {
    const CieSkyParameters p = cie_sky_parameters(type);
    for (double z : {0.0, 30.0, 50.0, 75.0, 89.0})
      for (double az : {0.0, 45.0, 90.0, 160.0, 250.0}) {
        const double expected = standard_relative_luminance(type, z, az - sun_azimuth, sun_zenith);
        // The 1 %: both sides evaluate the same closed form, so they agree far
        // closer; the tolerance allows only rounding.
        EXPECT_NEAR(cie_relative_luminance(p, direction(z, az), to_sun), expected, 0.01 * expected)
            << "type " << type << " Z " << z << " az " << az;
      }
    EXPECT_DOUBLE_EQ(cie_relative_luminance(p, {0, 0, 1}, to_sun), 1.0);  // normalised at the zenith
    EXPECT_EQ(cie_relative_luminance(p, direction(95, 0), to_sun), 0.0);  // no sky below the horizon
  }
}

TEST(CieSky, OvercastMatchesMoonAndSpencersPublishedRatios) {
  // Type 1 is the standard's form of the CIE overcast sky of Moon & Spencer (1942),
  // L(h) = L_z (1 + 2 sin h)/3: a horizon a third of the zenith, and 2/3 at 30°.
  const CieSkyParameters p = cie_sky_parameters(1);
  const Vec3 sun = direction(40, 180);
  EXPECT_NEAR(1.0 / cie_relative_luminance(p, direction(89.999, 0), sun), 3.0, 0.01 * 3.0);
  for (double azimuth : {0.0, 90.0, 180.0})  // azimuthally uniform
    EXPECT_NEAR(cie_relative_luminance(p, direction(60, azimuth), sun), 2.0 / 3.0, 0.01 * 2.0 / 3.0);
}

TEST(CieSky, TheUniformSkyGivesPiTimesItsLuminance) {
  // Type 5 has φ ≡ 1 and f ≡ 1: a uniform sky, whose horizontal illuminance is π L
  // (closed form). The quadrature's midpoint rule is exact to about 1e-6 here.
  EXPECT_NEAR(cie_horizontal_illuminance_per_zenith_luminance(cie_sky_parameters(5), direction(30, 0)), kPi, 1e-4);
}

// ∫ L cos Z dω of the tabulated sky (what the renderer reads), by a midpoint rule in
// (Z, azimuth) unlike the one that scaled it.
double horizontal_illuminance_of_table(const SkyViewTable& table, const Vec3& to_sun) {
  constexpr int kZ = 180, kA = 240;
  double sum = 0;
  for (int i = 0; i < kZ; ++i) {
    const double z = (i + 0.5) * (kPi / 2) / kZ;
    for (int j = 0; j < kA; ++j) {
      const double a = (j + 0.5) * 2 * kPi / kA;
      const Vec3 d{std::sin(z) * std::sin(a), std::sin(z) * std::cos(a), std::cos(z)};
      sum += luminance(table.radiance(relative_direction(d, to_sun))) * std::cos(z) * std::sin(z);
    }
  }
  return sum * (kPi / 2 / kZ) * (2 * kPi / kA);
}

TEST(CieSky, TheTabulatedSkyGivesTheIlluminanceAskedFor) {
  const double ground = 6371e3;
  const Vec3 to_sun = direction(55, 200);
  for (int type = 1; type <= kCieSkyTypes; ++type) {
    const CieSkySettings settings{type, 12345.0, false};
    const auto table =
        cie_sky_view(settings, SpectralBands::render_bins(), to_sun, Irradiance(0.0f), 0.2, ground + 1.0, ground);
    // The 0.5 %: the table is bilinear over 96 × 128 nodes crowded toward the
    // horizon, the quadrature 180 × 240 midpoints; together they stay within 0.2 % here.
    EXPECT_NEAR(horizontal_illuminance_of_table(*table, to_sun), 12345.0, 0.005 * 12345.0) << "type " << type;
    // And the irradiance table the surfaces read (its own quadrature of the same table).
    const SkyIrradianceTable irradiance(*table, to_sun);
    EXPECT_NEAR(luminance(irradiance.at({0, 0, 1})), 12345.0, 0.005 * 12345.0) << "type " << type;
  }
}

TEST(CieSky, ReplacesTheModelsSkyAndHidesTheSunWhenOvercast) {
  AtmosphereSettings air;
  air.cie_sky = CieSkySettings{1, 8000.0, false};
  const Atmosphere atmosphere(air);
  const Vec3 to_sun = direction(50, 180);
  const SkyModel sky(atmosphere, to_sun, 1.5);
  EXPECT_EQ(illuminance(sky.direct_sun(0.0)), 0.0);
  EXPECT_EQ(luminance(sky.sun_radiance(to_sun)), 0.0);
  // The zenith: L_z = E_h / ∫ (L/L_z) cos Z dω.
  const double zenith = 8000.0 / cie_horizontal_illuminance_per_zenith_luminance(cie_sky_parameters(1), to_sun);
  EXPECT_NEAR(luminance(sky.sky_radiance_near_ground({0, 0, 1})), zenith, 0.005 * zenith);
  EXPECT_NEAR(illuminance(sky.sky_irradiance({0, 0, 1})), 8000.0, 0.005 * 8000.0);
}

}  // namespace
}  // namespace skylit
