#include "skylit/atmosphere/optical_properties.h"

#include <algorithm>
#include <cmath>

#include "skylit/atmosphere/aerosol_types.h"
#include "skylit/core/angles.h"
#include "skylit/spectrum/illuminants.h"
#include "skylit/spectrum/tabulated.h"

namespace skylit {

namespace {

constexpr double kCo2PartsPerVolume = 360e-6;     // Bodhaine et al.'s reference air
constexpr double kLoschmidtPerCm3 = 2.546899e19;  // N_s at 288.15 K, 1013.25 hPa (Bodhaine Eq. 2)
constexpr double kAvogadro = 6.0221367e23;
constexpr double kSeaLevelPressureDynPerCm2 = 1013.25e3;

// Gravity at 45° latitude at the mass-weighted column height above sea level (Bodhaine Eqs. 10–11), cm s⁻².
double bodhaine_gravity_cm_s2() {
  const double zc = 5517.56;  // m, 0.73737·z + 5517.56 at z = 0
  return 980.6160 - 3.085462e-4 * zc + 7.254e-11 * zc * zc - 1.517e-17 * zc * zc * zc;
}

double mean_molecular_mass_g_per_mol() { return 15.0556 * kCo2PartsPerVolume + 28.9595; }

// The tent profile of Bruneton (2017): zero below 10 km, rising to 1 at 25 km, back to
// zero at 40 km; its integral over altitude is 15 km.
constexpr double kOzoneBottomM = 10e3, kOzonePeakM = 25e3, kOzoneTopM = 40e3;
constexpr double kOzoneProfileIntegralM = 15e3;

// σ_O₃ at 223 K, a typical stratospheric temperature (data/ozone_cross_section.csv).
const Tabulated& ozone_cross_section_cm2() {
  static const Tabulated table = embedded_table("ozone_cross_section.csv", 2);
  return table;
}

}  // namespace

// Peck & Reeder (1972) for 300 ppm CO₂, scaled to 360 ppm (Bodhaine Eqs. 18–19).
double refractive_index_air(double wavelength_nm) {
  const double inv_um2 = 1.0 / std::pow(wavelength_nm * 1e-3, 2);
  const double n300_minus_1 = (8060.51 + 2480990.0 / (132.274 - inv_um2) + 17455.7 / (39.32957 - inv_um2)) * 1e-8;
  return 1.0 + n300_minus_1 * (1.0 + 0.54 * (kCo2PartsPerVolume - 0.0003));
}

SpectralBands SpectralBands::render_bins() {
  SpectralBands bands;
  for (int i = 0; i < kSpectralBins; ++i) {
    bands.lo_nm[static_cast<size_t>(i)] = kGrid.lower_nm(i);
    bands.hi_nm[static_cast<size_t>(i)] = kGrid.lower_nm(i + 1);
  }
  return bands;
}

SpectralBands SpectralBands::consecutive(double first_center_nm, double width_nm) {
  SpectralBands bands;
  for (int i = 0; i < kSpectralBins; ++i) {
    const double center = first_center_nm + i * width_nm;
    bands.lo_nm[static_cast<size_t>(i)] = center - 0.5 * width_nm;
    bands.hi_nm[static_cast<size_t>(i)] = center + 0.5 * width_nm;
  }
  return bands;
}

double king_factor_air(double wavelength_nm) {
  const double inv_um2 = 1.0 / std::pow(wavelength_nm * 1e-3, 2);
  const double f_n2 = 1.034 + 3.17e-4 * inv_um2;                                  // Bates 1984
  const double f_o2 = 1.096 + 1.385e-3 * inv_um2 + 1.448e-4 * inv_um2 * inv_um2;  // Bates 1984
  const double f_ar = 1.00, f_co2 = 1.15;
  const double co2_percent = kCo2PartsPerVolume * 100.0;
  return (78.084 * f_n2 + 20.946 * f_o2 + 0.934 * f_ar + co2_percent * f_co2) /
         (78.084 + 20.946 + 0.934 + co2_percent);  // Bodhaine Eq. 23
}

double rayleigh_cross_section_m2(double wavelength_nm) {
  const double n = refractive_index_air(wavelength_nm);
  const double lambda_cm = wavelength_nm * 1e-7;
  const double ratio = (n * n - 1.0) / (n * n + 2.0);
  const double sigma_cm2 = 24.0 * std::pow(kPi, 3) * ratio * ratio /
                           (std::pow(lambda_cm, 4) * kLoschmidtPerCm3 * kLoschmidtPerCm3) *
                           king_factor_air(wavelength_nm);
  return sigma_cm2 * 1e-4;
}

double rayleigh_optical_depth_sea_level(double wavelength_nm) {
  const double column_per_cm2 =
      kSeaLevelPressureDynPerCm2 * kAvogadro / (mean_molecular_mass_g_per_mol() * bodhaine_gravity_cm_s2());
  return rayleigh_cross_section_m2(wavelength_nm) * 1e4 * column_per_cm2;
}

namespace {
// Koschmieder's constant: −ln 0.02, the 2 % contrast threshold.
constexpr double kKoschmieder = 3.912;
double rayleigh_extinction_550_per_m() { return rayleigh_optical_depth_sea_level(550.0) / 7994.0; }
}  // namespace

double aod_550_from_visibility(double visibility_km, double aerosol_scale_height_m) {
  const double ground_extinction = kKoschmieder / (visibility_km * 1e3);
  return std::max(0.0, ground_extinction - rayleigh_extinction_550_per_m()) * aerosol_scale_height_m;
}

double clean_air_visibility_km() { return kKoschmieder / rayleigh_extinction_550_per_m() / 1e3; }

double aod_550_from_linke_turbidity(double linke_turbidity) {
  // Ineichen (2008), Eq. 5 at p = p0 and w = 1.5 cm:
  // T_L = 3.91·e^0.689·τ_550 + 0.376·ln w + 2 + 0.54 − 0.5 + 0.16.
  const double offset = 0.376 * std::log(1.5) + 2.0 + 0.54 - 0.5 + 0.16;
  return std::max(0.0, (linke_turbidity - offset) / (3.91 * std::exp(0.689)));
}

AtmosphereMedium::AtmosphereMedium(const AtmosphereSettings& settings, const SpectralBands& bands)
    : earth_radius_m(settings.earth_radius_m),
      site_elevation_m(settings.site_elevation_m),
      air_(settings.model == AtmosphereModel::full && settings.air_density == AirDensity::us_standard_1976
               ? AirDensityProfile::us_standard_1976()
               : AirDensityProfile::exponential(settings.rayleigh_scale_height_m)),
      aerosol_scale_height_m_(settings.aerosol.scale_height_m),
      ozone_(settings.model == AtmosphereModel::full && settings.ozone_column_du > 0) {
  const AerosolSettings& aerosol = settings.aerosol;
  const double ozone_peak_per_m3 = settings.ozone_column_du * kDobsonUnitPerM2 / kOzoneProfileIntegralM;
  for (int i = 0; i < kSpectralBins; ++i) {
    const double lo = bands.lo_nm[static_cast<size_t>(i)], hi = bands.hi_nm[static_cast<size_t>(i)];
    // Band means: of the Rayleigh optical depth by Simpson's rule (smooth), of ozone's
    // finely structured cross section exactly from its table.
    const double tau_r =
        (rayleigh_optical_depth_sea_level(lo) + 4.0 * rayleigh_optical_depth_sea_level(0.5 * (lo + hi)) +
         rayleigh_optical_depth_sea_level(hi)) /
        6.0;
    // The profile's equivalent height fixes the sea-level coefficient: τ = β₀·∫ρ/ρ₀ dh
    // (H for the exponential; issue 3; docs/atmosphere.md).
    rayleigh_scattering[i] = static_cast<float>(tau_r / air_.equivalent_height_m());
    const double lambda = 0.5 * (lo + hi);
    const double aerosol_tau = aerosol.aod_550 * aerosol_relative_optical_depth(aerosol, lambda);
    aerosol_extinction[i] = static_cast<float>(aerosol_tau / aerosol_scale_height_m_);
    aerosol_scattering[i] =
        static_cast<float>(aerosol.single_scattering_albedo * aerosol_tau / aerosol_scale_height_m_);
    ozone_absorption[i] =
        static_cast<float>(ozone_ ? ozone_peak_per_m3 * ozone_cross_section_cm2().average(lo, hi) * 1e-4 : 0.0);
  }
  const double f = king_factor_air(550.0);
  const double depolarisation = (6.0 * f - 6.0) / (3.0 + 7.0 * f);  // F = (6 + 3ρ)/(6 − 7ρ)
  rayleigh_gamma = depolarisation / (2.0 - depolarisation);
  // One index for every wavelength: across 400–700 nm n − 1 changes by ±1.5 %, and the
  // bending with it (docs/atmosphere.md, "Twilight").
  // Air thin enough that r·|dn/dr| nears 1 (an exponential of scale height under ~4 km,
  // as tests use) would trap grazing rays, where Bouguer's rays have no lowest point:
  // its rays stay straight.
  const bool ducts = settings.air_density == AirDensity::exponential &&
                     settings.earth_radius_m * 2.8e-4 / settings.rayleigh_scale_height_m > 0.5;
  if (settings.model == AtmosphereModel::full && settings.refraction && !ducts)
    refractivity = refractive_index_air(550.0) - 1.0;
}

double AtmosphereMedium::rayleigh_density(double altitude_m) const { return air_.relative_density(altitude_m); }

double AtmosphereMedium::aerosol_density(double altitude_m) const {
  // Relative to the site's ground, so that aod_550 is the column above the site.
  return std::exp(-(altitude_m - site_elevation_m) / aerosol_scale_height_m_);
}

double AtmosphereMedium::ozone_density(double altitude_m) const {
  if (!ozone_ || altitude_m <= kOzoneBottomM || altitude_m >= kOzoneTopM) return 0.0;
  return altitude_m < kOzonePeakM ? (altitude_m - kOzoneBottomM) / (kOzonePeakM - kOzoneBottomM)
                                  : (kOzoneTopM - altitude_m) / (kOzoneTopM - kOzonePeakM);
}

Spectrum AtmosphereMedium::extinction(double rayleigh, double aerosol, double ozone) const {
  Spectrum out;
  const float r = static_cast<float>(rayleigh), a = static_cast<float>(aerosol), o = static_cast<float>(ozone);
  for (int i = 0; i < kSpectralBins; ++i)
    out[i] = rayleigh_scattering[i] * r + aerosol_extinction[i] * a + ozone_absorption[i] * o;
  return out;
}

Spectrum extraterrestrial_irradiance(const SpectralBands& bands, double earth_sun_distance_au) {
  const Tabulated& sun = solar_extraterrestrial_table();
  Spectrum out;
  for (int i = 0; i < kSpectralBins; ++i)
    out[i] = static_cast<float>(sun.average(bands.lo_nm[static_cast<size_t>(i)], bands.hi_nm[static_cast<size_t>(i)]) /
                                (earth_sun_distance_au * earth_sun_distance_au));
  return out;
}

}  // namespace skylit
