// What a user sets about the air: the scene file's `atmosphere` part and the options of
// `skylit sky` and `skylit spectrum`. Defaults, sources and the differences from the
// paper are in docs/atmosphere.md.
#pragma once

namespace skylit {

enum class AtmosphereModel {
  full,   // single and multiple scattering, ozone absorption (today's physics)
  paper,  // the paper's §3.1: single scattering only, no ozone
};

enum class AerosolPhase { cornette_shanks, henyey_greenstein };

struct AerosolSettings {
  double aod_550 = 0.1;                   // optical depth at 550 nm of the column above the site
  double angstrom_exponent = 1.3;         // Ångström's law: τ(λ) = τ(550)·(λ/550 nm)^−α
  double single_scattering_albedo = 0.9;  // scattering / extinction
  double asymmetry = 0.75;                // g of the phase function
  AerosolPhase phase = AerosolPhase::cornette_shanks;
  double scale_height_m = 1200.0;  // the paper's §3.1 after Sekine (1987)
};

struct AtmosphereSettings {
  AtmosphereModel model = AtmosphereModel::full;
  AerosolSettings aerosol;
  double ozone_column_du = 300.0;  // total ozone in Dobson units
  double ground_albedo = 0.15;     // Lambertian, grey, for the ground seen through the air and multiple scattering
  double rayleigh_scale_height_m = 7994;  // the paper's Eq. (1)
  double earth_radius_m = 6371e3;
  double top_altitude_m = 100e3;       // above sea level
  double site_elevation_m = 0.0;       // the scene's ground (z = 0) above sea level
  double earth_sun_distance_au = 1.0;  // scales the extraterrestrial spectrum by 1/d²
};

}  // namespace skylit
