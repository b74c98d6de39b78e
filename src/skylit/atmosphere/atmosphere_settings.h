// What a user sets about the air: the scene file's `atmosphere` part and the options of
// `skylit sky` and `skylit spectrum`. Defaults, sources and the differences from the
// paper are in docs/atmosphere.md.
#pragma once

#include <optional>

#include "skylit/atmosphere/cie_sky.h"
#include "skylit/atmosphere/moon_settings.h"
#include "skylit/atmosphere/night_sky_settings.h"

namespace skylit {

enum class AtmosphereModel {
  full,   // single and multiple scattering, ozone absorption (today's physics)
  paper,  // the paper's §3.1: single scattering only, no ozone
};

// How the full model computes multiple scattering (docs/atmosphere.md).
enum class MultipleScatteringMethod {
  scattering_orders,  // iterated scattering orders (Bruneton & Neyret 2008; Bruneton 2017)
  hillaire,           // Hillaire (2020): isotropic after the first event, geometric series
};

// The air's density against altitude (air_density_profile.h). The paper's model is
// always exponential.
enum class AirDensity {
  us_standard_1976,  // the US Standard Atmosphere 1976: right at 20–60 km, where twilight is lit
  exponential,       // the paper's Eq. (1) with rayleigh_scale_height_m
};

enum class AerosolPhase { cornette_shanks, henyey_greenstein };

// The aerosol types of OPAC (Hess, Koepke & Schult 1998), data/aerosol_types.csv.
enum class AerosolType {
  continental_clean,
  continental_average,
  continental_polluted,
  urban,
  maritime_clean,
  maritime_polluted,
  desert,
};

// The defaults are OPAC's continental average at 80 % relative humidity (its Table 4;
// a test checks them against data/aerosol_types.csv); `aerosol_settings(type)` gives
// the others. The amount, aod_550, is set apart from the type.
struct AerosolSettings {
  AerosolType type = AerosolType::continental_average;
  double aod_550 = 0.1;  // optical depth at 550 nm of the column above the site
  // Ångström's law in two pieces, as OPAC tabulates it: τ(λ) = τ(550)·(λ/550 nm)^−α
  // from 500 nm up, and τ(500)·(λ/500 nm)^−α_short below 500 nm.
  double angstrom_exponent = 1.42;          // 500–800 nm
  double angstrom_exponent_short = 1.11;    // 350–500 nm
  double single_scattering_albedo = 0.925;  // scattering / extinction at 550 nm
  double asymmetry = 0.703;                 // the phase function's mean cosine ⟨cos θ⟩ at 550 nm
  AerosolPhase phase = AerosolPhase::cornette_shanks;
  double scale_height_m = 1200.0;  // the paper's §3.1 after Sekine (1987)
  bool operator==(const AerosolSettings&) const = default;
};

// A new field that changes the air (not the sun's side: moon, CIE sky, night sky) must
// join the key of the shared tables in atmosphere_tables.cpp.
struct AtmosphereSettings {
  AtmosphereModel model = AtmosphereModel::full;
  MultipleScatteringMethod multiple_scattering = MultipleScatteringMethod::scattering_orders;
  AerosolSettings aerosol;
  double ozone_column_du = 300.0;  // total ozone in Dobson units
  double ground_albedo = 0.15;     // Lambertian, grey, for the ground seen through the air and multiple scattering
  AirDensity air_density = AirDensity::us_standard_1976;
  double rayleigh_scale_height_m = 7994;  // the paper's Eq. (1), for AirDensity::exponential
  // Sunlight bent by the air on its way to each scattering point and the sunlit ground
  // (refracted_ray.h), which lifts the Earth's shadow at twilight; false: straight rays.
  // The paper's model is always straight. The scene's sun altitude stays the geometric one.
  bool refraction = true;
  double earth_radius_m = 6371e3;
  double top_altitude_m = 100e3;       // above sea level
  double site_elevation_m = 0.0;       // the scene's ground (z = 0) above sea level
  double earth_sun_distance_au = 1.0;  // scales the extraterrestrial spectrum by 1/d²
  // A CIE standard general sky in place of the model's own sky (scene `sky`,
  // docs/weather.md); the air between the camera and the scene stays the model's.
  std::optional<CieSkySettings> cie_sky;
  // Set: the light in the sky is the moon's, not the sun's (scene `moon`, docs/night-sky.md):
  // the direction the sky model is given is the moon's, its irradiance the moon's.
  std::optional<MoonSettings> moon;
  // Airglow, zodiacal light, starlight and a city's glow, added to the sky (night_sky.h).
  NightSkySettings night_sky;
};

}  // namespace skylit
