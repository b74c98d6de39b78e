// The sky until the atmosphere model (issue 3) replaces it: a uniform sky with the
// colour of CIE D65 and a luminance of 5000 cd/m², a typical clear-sky value. It lights
// surfaces as an unobstructed uniform dome would (irradiance π·L·(1 + n_z)/2 on a plane
// with unit normal n, without occlusion by other objects), and pixels that see the sky
// show it. Its diffuse horizontal illuminance is π × 5000 ≈ 15.7 klx.
#pragma once

#include "skylit/spectrum/spectrum.h"

namespace skylit {

inline constexpr double kPlaceholderSkyLuminance = 5000.0;  // cd/m²

// Spectral radiance, W m⁻² sr⁻¹ nm⁻¹.
Spectrum placeholder_sky_radiance();

}  // namespace skylit
