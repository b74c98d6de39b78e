// Sunlight and skylight spectra at 1 nm for `skylit spectrum`: the atmosphere model
// evaluated in 1 nm bands, kSpectralBins bands at a time.
#pragma once

#include <vector>

#include "skylit/atmosphere/atmosphere_settings.h"
#include "skylit/core/vec3.h"

namespace skylit {

struct SolarSpectrumSample {
  double wavelength_nm;
  double direct_normal;       // W m⁻² nm⁻¹ on a plane normal to the sun
  double diffuse_horizontal;  // W m⁻² nm⁻¹ from the sky on a horizontal plane
  double zenith_radiance;     // W m⁻² sr⁻¹ nm⁻¹ of the sky at the zenith
};

// At every whole nm from first_nm to last_nm, for an observer `observer_height_m` above
// the ground and the sun seen in `to_sun` (seen_sun.h).
std::vector<SolarSpectrumSample> solar_spectrum(const AtmosphereSettings& settings, const Vec3& to_sun,
                                                double observer_height_m, int first_nm = 380, int last_nm = 780);

}  // namespace skylit
