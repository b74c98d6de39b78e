// The optical properties of the air (§3.1 of the paper, made right by today's physics):
// Rayleigh scattering by molecules, scattering and absorption by aerosols, absorption
// by ozone, each as a coefficient at a reference altitude times a relative density
// profile. Constants and their sources: docs/atmosphere.md.
#pragma once

#include <array>

#include "skylit/atmosphere/air_density_profile.h"
#include "skylit/atmosphere/atmosphere_settings.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

// The wavelength interval each entry of a Spectrum stands for. Rendering uses the bins
// of kGrid; `skylit spectrum` evaluates the model in 1 nm bands, kSpectralBins at a time.
struct SpectralBands {
  std::array<double, kSpectralBins> lo_nm{}, hi_nm{};
  double center_nm(int i) const { return 0.5 * (lo_nm[static_cast<size_t>(i)] + hi_nm[static_cast<size_t>(i)]); }

  static SpectralBands render_bins();
  // kSpectralBins bands of width `width_nm` centred on first_nm, first_nm + width_nm, ...
  static SpectralBands consecutive(double first_center_nm, double width_nm);
  bool operator==(const SpectralBands&) const = default;
};

// Rayleigh scattering after Bodhaine, Wood, Dutton & Slusser (1999), J. Atmos. Oceanic
// Technol. 16, 1854–1861: refractive index of air (Peck & Reeder 1972, 360 ppm CO₂),
// King factor (Bates 1984), cross section σ(λ) in m² per molecule.
double rayleigh_cross_section_m2(double wavelength_nm);
double king_factor_air(double wavelength_nm);
// The refractive index of dry air at 15 °C and 1013.25 hPa (the US Standard Atmosphere's
// sea level): Peck & Reeder (1972) with 360 ppm CO₂, as Bodhaine et al. use it.
double refractive_index_air(double wavelength_nm);
// Optical depth of the whole column at sea level, 1013.25 hPa, 45° latitude
// (Bodhaine's Eq. 30 with their g and mean molecular mass).
double rayleigh_optical_depth_sea_level(double wavelength_nm);

// Aerosol optical depth at 550 nm from a meteorological visibility (Koschmieder: the
// ground extinction is 3.912/V, less the Rayleigh part) with the aerosol scale height.
double aod_550_from_visibility(double visibility_km, double aerosol_scale_height_m);
// The farthest anything can be seen through air without aerosol at sea level
// (Koschmieder's 3.912 over the Rayleigh extinction at 550 nm): about 320 km. A reported
// visibility beyond it gives aod_550 = 0.
double clean_air_visibility_km();
// From a Linke turbidity at air mass 2 (Ineichen 2008, Solar Energy 82, 1095, with
// 1.5 cm of precipitable water and sea-level pressure).
double aod_550_from_linke_turbidity(double linke_turbidity);

// Dobson unit in molecules per m² (1 DU = 2.6867e20 m⁻²).
inline constexpr double kDobsonUnitPerM2 = 2.6867e20;

struct AtmosphereMedium {
  AtmosphereMedium(const AtmosphereSettings& settings, const SpectralBands& bands);

  // Coefficients (m⁻¹) where the relative density is 1.
  Spectrum rayleigh_scattering;  // at sea level
  Spectrum aerosol_scattering;   // at the site's ground
  Spectrum aerosol_extinction;   // at the site's ground
  Spectrum ozone_absorption;     // at the ozone layer's peak (25 km)
  double rayleigh_gamma;         // molecular anisotropy for the phase function, at 550 nm
  // n − 1 where the Rayleigh density is 1 (sea level), at 550 nm; n − 1 follows the
  // density (Gladstone–Dale). 0: the sunlight's rays are straight (refracted_ray.h).
  double refractivity = 0;

  double earth_radius_m, site_elevation_m;

  // Relative densities at an altitude above sea level.
  double rayleigh_density(double altitude_m) const;
  double aerosol_density(double altitude_m) const;
  double ozone_density(double altitude_m) const;

  // Extinction (m⁻¹) at an altitude from relative densities computed by the caller.
  Spectrum extinction(double rayleigh, double aerosol, double ozone) const;

 private:
  AirDensityProfile air_;
  double aerosol_scale_height_m_;
  bool ozone_;
};

// Extraterrestrial solar spectral irradiance in the bands (W m⁻² nm⁻¹), at the given
// Earth–Sun distance.
Spectrum extraterrestrial_irradiance(const SpectralBands& bands, double earth_sun_distance_au);

}  // namespace skylit
