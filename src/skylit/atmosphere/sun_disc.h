// The sun as a disc of its real angular size with limb darkening.
#pragma once

#include "skylit/atmosphere/optical_properties.h"

namespace skylit {

// Angular radius at 1 AU: IAU 2015 nominal solar radius 6.957e8 m over 1 au
// (1.495978707e11 m), 0.26645°.
inline constexpr double kSunAngularRadiusAt1AuRad = 6.957e8 / 1.495978707e11;

// Hestroffer & Magnan (1998), A&A 333, 338: I(μ)/I(1) = μ^α(λ) with
// α = −0.023 + 0.292/λ[µm], μ the cosine on the solar surface.
double limb_darkening_exponent(double wavelength_nm);

// Radiance (W m⁻² sr⁻¹ nm⁻¹) at angle `angle_from_centre_rad` from the disc's centre,
// outside the atmosphere, for the disc's irradiance `irradiance` and angular radius;
// 0 outside the disc. The disc's radiance integrates to `irradiance`.
Spectrum sun_disc_radiance(const Spectrum& irradiance, const SpectralBands& bands, double angular_radius_rad,
                           double angle_from_centre_rad);

}  // namespace skylit
