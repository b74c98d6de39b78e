// What a scene sets about the night sky (night_sky.h, docs/night-sky.md).
#pragma once

#include "skylit/spectrum/spectrum.h"

namespace skylit {

// Zenith luminances in cd/m² as seen from the ground at a dark site (extinction at the
// zenith included): together 2.0e-4 cd/m², 21.8 mag/arcsec² in V, inside the range of
// natural zenith brightness Duriscoe (PASP 125, 2013, 1370) measured at dark US parks
// (about 21.6–22.0 mag/arcsec², 1.7e-4 to 2.5e-4 cd/m²). The split follows Leinert et
// al. (A&AS 127, 1998, 1), Table 1 and §9–10, for mid ecliptic and galactic latitudes:
// airglow about half, zodiacal light and starlight the rest.
struct NightSkySettings {
  bool natural = true;
  double airglow_zenith_cd_m2 = 1.0e-4;
  double zodiacal_cd_m2 = 0.6e-4;   // uniform over the sky (no ecliptic dependence)
  double starlight_cd_m2 = 0.4e-4;  // uniform over the sky (no Milky Way)
  double airglow_height_m = 90e3;   // the emitting layer (the 557.7 nm and OH layers, 87–97 km)
  // A city's sky glow at the zenith, cd/m² (0: none); its spectrum per cd/m² (any
  // scale; all zero: equal energy) is set by the scene reader (a 4000 K LED).
  double artificial_zenith_cd_m2 = 0;
  Spectrum artificial_spectrum{0.0f};
};

}  // namespace skylit
