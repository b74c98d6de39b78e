// The US Standard Atmosphere 1976 density profile against values printed in the
// standard and against the hydrostatic column mass.
#include "skylit/atmosphere/air_density_profile.h"

#include <gtest/gtest.h>

#include <cmath>

namespace skylit {
namespace {

TEST(AirDensityProfile, MatchesTheStandardsTable) {
  // ρ in kg/m³ of the US Standard Atmosphere 1976 (NOAA-S/T 76-1562) over its sea-level
  // 1.2250 kg/m³: at whole kilometres its Table I; at 11.5, 47.5 and 70.5 km (between the
  // data file's rows, where the temperature gradient bends) its hydrostatic equations
  // (33a/33b) with its layer temperatures, evaluated apart. 0.3 %: the log-linear
  // interpolation of 1 km rows (measured worst 0.2 %, at the bends) and 5 printed digits.
  const AirDensityProfile air = AirDensityProfile::us_standard_1976();
  const struct {
    double km, kg_m3;
  } rows[] = {{0, 1.2250},     {5, 0.73643},      {11.5, 0.33743},   {30, 1.8410e-2}, {40, 3.9957e-3},
              {50, 1.0269e-3}, {47.5, 1.4012e-3}, {70.5, 7.7223e-5}, {86, 6.958e-6}};
  for (const auto& r : rows) {
    const double expected = r.kg_m3 / 1.2250;
    EXPECT_NEAR(air.relative_density(r.km * 1e3), expected, 0.003 * expected) << r.km;
  }
  // Above the table, the density keeps falling, by less than 1 % of 86 km's per 10 km beyond 100 km.
  EXPECT_LT(air.relative_density(100e3), 0.2 * air.relative_density(86e3));
  EXPECT_GT(air.relative_density(100e3), 0.0);
}

TEST(AirDensityProfile, EquivalentHeightIsTheHydrostaticColumn) {
  // The whole column's mass is p₀/g: p₀/(g₀ρ₀) = 101325 / (9.80665 · 1.2250) = 8434.6 m of
  // sea-level air, and g falls by 0.2 % at the column's mass-weighted height (~5.5 km),
  // which adds 0.2 %. 0.5 %: that correction's uncertainty and the log-linear rows.
  const double equivalent = AirDensityProfile::us_standard_1976().equivalent_height_m();
  EXPECT_NEAR(equivalent, 8434.6 * 1.002, 0.005 * 8434.6);
  // The exponential's equivalent height is its scale height, in closed form.
  EXPECT_DOUBLE_EQ(AirDensityProfile::exponential(7994).equivalent_height_m(), 7994);
  EXPECT_DOUBLE_EQ(AirDensityProfile::exponential(7994).relative_density(7994), std::exp(-1.0));
}

}  // namespace
}  // namespace skylit
