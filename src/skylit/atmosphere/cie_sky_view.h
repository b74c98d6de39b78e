// A CIE standard general sky (cie_sky.h) as a sky-view table, so that everything that
// reads the sky (surfaces' sky light and its band sources, clouds, fog, the camera)
// reads it as it reads the model's own sky.
//
// Its spectrum is CIE D65 at every direction (daylight of 6500 K, the standard's
// illuminant for average daylight; the CIE skies are luminance distributions and give
// none). Below the horizon is the ground, Lambertian with the atmosphere's albedo, lit
// by this sky and by `sun_on_ground` (W m⁻² nm⁻¹ on the horizontal).
#pragma once

#include <memory>

#include "skylit/atmosphere/cie_sky.h"
#include "skylit/atmosphere/optical_properties.h"
#include "skylit/atmosphere/sky_view_table.h"
#include "skylit/spectrum/radiometry.h"

namespace skylit {

// CIE D65 in `bands`, scaled to a luminance of 1 cd/m² (as a radiance; as an irradiance
// it is 1 lx).
Spectrum d65_per_candela(const SpectralBands& bands);

// The zenith luminance (cd/m²) that gives `settings.diffuse_horizontal_lux`.
double cie_zenith_luminance(const CieSkySettings& settings, const Vec3& to_sun);

std::unique_ptr<SkyViewTable> cie_sky_view(const CieSkySettings& settings, const SpectralBands& bands,
                                           const Vec3& to_sun, const Irradiance& sun_on_ground, double ground_albedo,
                                           double observer_radius_m, double ground_radius_m);

}  // namespace skylit
