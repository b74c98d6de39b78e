// Optical depths and transmittance of the spherical shell against brute-force
// integration, and Rayleigh scattering against Bodhaine et al. (1999).
#include <gtest/gtest.h>

#include <cmath>

#include "skylit/atmosphere/optical_properties.h"
#include "skylit/atmosphere/shell_geometry.h"
#include "skylit/atmosphere/transmittance_table.h"

namespace skylit {
namespace {

constexpr double kEarth = 6371e3, kTop = 6471e3;

TEST(Rayleigh, OpticalDepthAt550nmIsBodhaines) {
  // Bodhaine et al. (1999): τ_R(550 nm) = 0.0973 at sea level; the issue allows 1 %.
  EXPECT_NEAR(rayleigh_optical_depth_sea_level(550.0), 0.0973, 0.000973);
  // Their cross section at 550 nm is 4.51e-27 cm² (Table 2 neighbourhood); λ^-4.08 law.
  EXPECT_NEAR(rayleigh_cross_section_m2(550.0) * 1e4, 4.51e-27, 0.03e-27);
  const double slope = std::log(rayleigh_optical_depth_sea_level(450.0) / rayleigh_optical_depth_sea_level(650.0)) /
                       std::log(650.0 / 450.0);
  EXPECT_NEAR(slope, 4.08, 0.05);
}

TEST(Rayleigh, ScaleHeightFixesTheSeaLevelCoefficient) {
  AtmosphereSettings settings;
  settings.model = AtmosphereModel::paper;
  const AtmosphereMedium medium(settings, SpectralBands::consecutive(550.0, 1.0));
  // The vertical column of the exponential profile is β₀·H: it must give τ(550).
  EXPECT_NEAR(medium.rayleigh_scattering[0] * 7994.0, rayleigh_optical_depth_sea_level(550.0), 1e-4);
}

// ∫ρ ds by the midpoint rule with 200,000 steps (5.6 m on the longest path), in double precision.
ColumnDensities brute_force_columns(const AtmosphereMedium& medium, double r, double mu, double length) {
  constexpr int kSteps = 200000;
  ColumnDensities sum;
  const double dt = length / kSteps;
  for (int i = 0; i < kSteps; ++i) {
    const double h = shell::radius_at(r, mu, (i + 0.5) * dt) - kEarth;
    sum.rayleigh += medium.rayleigh_density(h) * dt;
    sum.aerosol += medium.aerosol_density(h) * dt;
    sum.ozone += medium.ozone_density(h) * dt;
  }
  return sum;
}

TEST(Transmittance, ColumnDensitiesMatchBruteForceOnSlantPaths) {
  const AtmosphereMedium medium(AtmosphereSettings{}, SpectralBands::render_bins());
  // Vertical, slant, horizontal (the horizon: the longest path), and a ray from 10 km
  // going slightly down, past its lowest point, and up again.
  struct Case {
    double height, mu;
  };
  for (const Case c : {Case{0, 1.0}, Case{0, 0.5}, Case{0, 0.1}, Case{0, 0.0}, Case{1000, 0.0}, Case{10e3, -0.02}}) {
    const double r = kEarth + c.height;
    ASSERT_FALSE(shell::hits_ground(r, c.mu, kEarth));
    const double length = shell::distance_to_outer_sphere(r, c.mu, kTop);
    const ColumnDensities fast = column_densities(medium, r, c.mu, length);
    const ColumnDensities slow = brute_force_columns(medium, r, c.mu, length);
    // 2e-4 relative for the smooth exponential profiles: far below what the 40-bin
    // colours or any measurement resolve. The ozone tent has kinks at 10, 25 and 40 km
    // that Simpson's rule smooths over: 3e-3 of an optical depth of at most ~1 (the
    // horizon), i.e. under 0.3 % of the transmittance.
    EXPECT_NEAR(fast.rayleigh / slow.rayleigh, 1.0, 2e-4) << c.height << " " << c.mu;
    EXPECT_NEAR(fast.aerosol / slow.aerosol, 1.0, 2e-4) << c.height << " " << c.mu;
    EXPECT_NEAR(fast.ozone / slow.ozone, 1.0, 3e-3) << c.height << " " << c.mu;
  }
  // The vertical column from sea level: for the US Standard Atmosphere (default) its
  // equivalent height (the 100 km top leaves out 6e-7 of it); for the exponential the
  // closed form H(1 − e^(−100/H)).
  const ColumnDensities up = column_densities(medium, kEarth, 1.0, kTop - kEarth);
  EXPECT_NEAR(up.rayleigh / AirDensityProfile::us_standard_1976().equivalent_height_m(), 1.0, 2e-4);
  AtmosphereSettings exponential_air;
  exponential_air.air_density = AirDensity::exponential;
  const AtmosphereMedium exponential(exponential_air, SpectralBands::render_bins());
  const ColumnDensities up_exponential = column_densities(exponential, kEarth, 1.0, kTop - kEarth);
  EXPECT_NEAR(up_exponential.rayleigh / (7994.0 * (1 - std::exp(-100e3 / 7994.0))), 1.0, 2e-4);
  EXPECT_NEAR(up.aerosol / 1200.0, 1.0, 2e-4);
  EXPECT_NEAR(up.ozone / 15e3, 1.0, 3e-3);  // the tent profile's area
}

TEST(Transmittance, TableMatchesDirectComputationIncludingTheHorizon) {
  const AtmosphereMedium medium(AtmosphereSettings{}, SpectralBands::render_bins());
  const TransmittanceTable table(medium, kEarth, kTop);
  for (double height : {0.0, 2.0, 500.0, 3000.0, 10e3, 30e3}) {
    for (double mu : {1.0, 0.7, 0.3, 0.1, 0.03, 0.0, -0.01}) {
      const double r = kEarth + height;
      if (shell::hits_ground(r, mu, kEarth)) continue;
      const ColumnDensities c = brute_force_columns(medium, r, mu, shell::distance_to_outer_sphere(r, mu, kTop));
      const Spectrum tau = medium.extinction(c.rayleigh, c.aerosol, c.ozone);
      const Spectrum t = table.to_top(r, mu);
      for (int k = 0; k < kSpectralBins; k += 13) {
        const double expected = std::exp(-static_cast<double>(tau[k]));
        // Bilinear interpolation of the optical depth over 256 × 128 in Bruneton's
        // coordinates: within 0.3 % of the transmittance (the worst case: a grazing ray
        // 2 m above the ground, between the samples at 0 and 6 m), or 1e-5 absolute
        // where almost nothing gets through.
        EXPECT_NEAR(t[k], expected, std::max(3e-3 * expected, 1e-5)) << height << " " << mu << " bin " << k;
      }
    }
  }
  EXPECT_EQ(table.to_top(kEarth + 100, -0.5)[0], 0.0f);  // into the ground: the Earth's shadow
}

}  // namespace
}  // namespace skylit
