// The aerosol types: their table, the defaults, the spectral extinction and the
// Cornette–Shanks parameter. The phase functions' normalisation and mean cosines are
// checked with every other phase function in phase_functions_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "skylit/atmosphere/aerosol_types.h"
#include "skylit/atmosphere/optical_properties.h"

namespace skylit {
namespace {

TEST(AerosolTypes, DefaultsAreContinentalAverage) {
  const AerosolSettings defaults;
  const AerosolSettings average = with_aerosol_type({}, AerosolType::continental_average);
  EXPECT_EQ(defaults.type, AerosolType::continental_average);
  EXPECT_DOUBLE_EQ(defaults.single_scattering_albedo, average.single_scattering_albedo);
  EXPECT_DOUBLE_EQ(defaults.asymmetry, average.asymmetry);
  EXPECT_DOUBLE_EQ(defaults.angstrom_exponent, average.angstrom_exponent);
  EXPECT_DOUBLE_EQ(defaults.angstrom_exponent_short, average.angstrom_exponent_short);
}

TEST(AerosolTypes, TableHoldsOpacValues) {
  // Hess, Koepke & Schult (1998), Table 4, 80 % relative humidity; an OPAC 3.1 run for
  // continental polluted gives ω = 0.8925, g = 0.6977 at 550 nm.
  const AerosolSettings polluted = with_aerosol_type({}, AerosolType::continental_polluted);
  EXPECT_NEAR(polluted.single_scattering_albedo, 0.8925, 0.001);
  EXPECT_NEAR(polluted.asymmetry, 0.6977, 0.001);
  // Physical ranking that a wrong row would break: soot makes urban air the most
  // absorbing, sea salt maritime air the least, and the coarse sea salt and dust have
  // the flattest spectra and the most forward-peaked phase functions.
  const AerosolSettings urban = with_aerosol_type({}, AerosolType::urban);
  const AerosolSettings maritime = with_aerosol_type({}, AerosolType::maritime_clean);
  const AerosolSettings desert = with_aerosol_type({}, AerosolType::desert);
  const AerosolSettings clean = with_aerosol_type({}, AerosolType::continental_clean);
  for (const AerosolSettings& a : {clean, polluted, maritime, desert}) {
    EXPECT_GT(a.single_scattering_albedo, urban.single_scattering_albedo);
    EXPECT_LT(a.single_scattering_albedo, 1.0);
  }
  EXPECT_GT(maritime.single_scattering_albedo, clean.single_scattering_albedo);
  EXPECT_LT(maritime.angstrom_exponent, 0.5);
  EXPECT_LT(desert.angstrom_exponent, 0.5);
  EXPECT_GT(clean.angstrom_exponent, 1.0);
  EXPECT_GT(maritime.asymmetry, clean.asymmetry);
  EXPECT_GT(desert.asymmetry, clean.asymmetry);
}

TEST(AerosolTypes, NamesRoundTrip) {
  for (size_t i = 0; i < aerosol_type_names().size(); ++i)
    EXPECT_EQ(aerosol_type_from_name(aerosol_type_names()[i]), static_cast<AerosolType>(i));
  EXPECT_FALSE(aerosol_type_from_name("volcanic").has_value());
}

TEST(AerosolTypes, SpectralExtinctionFollowsTheTwoPieceAngstromLaw) {
  AerosolSettings a;
  a.angstrom_exponent = 1.4;
  a.angstrom_exponent_short = 1.1;
  EXPECT_DOUBLE_EQ(aerosol_relative_optical_depth(a, 550.0), 1.0);
  EXPECT_NEAR(aerosol_relative_optical_depth(a, 800.0), std::pow(800.0 / 550.0, -1.4), 1e-12);
  // Continuous at 500 nm, then the short exponent: τ(400)/τ(500) = (0.8)^−1.1.
  EXPECT_NEAR(aerosol_relative_optical_depth(a, 499.999), aerosol_relative_optical_depth(a, 500.0), 1e-5);
  EXPECT_NEAR(aerosol_relative_optical_depth(a, 400.0) / aerosol_relative_optical_depth(a, 500.0), std::pow(0.8, -1.1),
              1e-12);
  // The medium takes its aerosol coefficients from the same law, in each bin.
  AtmosphereSettings settings;
  settings.aerosol = a;
  const SpectralBands bands = SpectralBands::consecutive(420.0, 10.0);
  const AtmosphereMedium medium(settings, bands);
  for (int i = 0; i < kSpectralBins; ++i) {
    const double expected = a.aod_550 * aerosol_relative_optical_depth(a, bands.center_nm(i)) / a.scale_height_m;
    EXPECT_NEAR(medium.aerosol_extinction[i], expected, 1e-6 * expected);
    EXPECT_NEAR(medium.aerosol_scattering[i], a.single_scattering_albedo * expected, 1e-6 * expected);
  }
}

TEST(AerosolTypes, CornetteShanksParameterGivesTheMeanCosine) {
  // The closed form of Cornette & Shanks (1992): g = 0.75 has mean cosine 0.8008, so a
  // mean cosine of 0.75 needs a smaller parameter.
  EXPECT_NEAR(cornette_shanks_parameter(3 * 0.75 * (4 + 0.5625) / (5 * 2.5625)), 0.75, 1e-12);
  EXPECT_LT(cornette_shanks_parameter(0.75), 0.75);
  EXPECT_NEAR(cornette_shanks_parameter(0.0), 0.0, 1e-12);
}

}  // namespace
}  // namespace skylit
