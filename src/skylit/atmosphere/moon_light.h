// The moon as the light of a night scene: its spectral irradiance outside the
// atmosphere and its disc as seen, with the phase. The air then treats it as it treats
// the sun (atmosphere.h: the same transmittance, sky and aerial perspective, scaled by
// this irradiance in place of the sun's). docs/night-sky.md.
#pragma once

#include "skylit/atmosphere/moon_settings.h"
#include "skylit/atmosphere/optical_properties.h"

namespace skylit {

// The moon's disc-integrated reflectance relative to its value at 550 nm: a straight
// line rising 0.20 % per nm (clamped to [0.3, 1.6]), which reddens sunlight by the
// difference of the colour indices B−V of the moon (0.92) and the sun (0.65), Allen's
// Astrophysical Quantities (4th ed., 2000), §12.8 and §14.7; the disc reflectance of
// Kieffer & Stone (AJ 129, 2005, 2887, ROLO) rises about so across the visible.
double moon_relative_reflectance(double wavelength_nm);

// W m⁻² nm⁻¹ on a plane facing the moon outside the atmosphere: the extraterrestrial
// solar spectrum × the relative reflectance, scaled so that its illuminance is
// Krisciunas & Schaefer's (moon_illuminance_lx: the phase law, the geometric albedo and
// (R_moon/d_moon)²; sunlight's 1/d_sun² is in the solar spectrum's scale).
Spectrum moon_extraterrestrial_irradiance(const SpectralBands& bands, double earth_sun_distance_au,
                                          const MoonSettings& moon);

// Whether a direction at `angle_from_centre_rad` from the disc's centre, `position_angle`
// about it, meets the sunlit part of the disc. Frame: `toward_sun` is the unit vector
// across the sky toward the sun, perpendicular to the line of sight; the point of the
// moon's visible face at offset (x, y) (in disc radii, x toward the sun) has the normal
// (x, y, √(1−x²−y²)) toward the observer, and the sun from the moon lies at the phase
// angle i from the observer, toward x: lit where x sin i + √(1−x²−y²) cos i > 0.
bool moon_point_lit(double x, double y, double phase_angle_rad);

// The fraction of the disc's area that is lit, (1 + cos i)/2 (Meeus 48.1).
double moon_lit_fraction(double phase_angle_rad);

// Radiance of the moon seen along `direction` (any length): uniform over the lit part,
// so that it integrates to `irradiance`; 0 off the disc or on its dark part (earthshine
// is not drawn). `to_moon` is the disc's centre.
Spectrum moon_disc_radiance(const Spectrum& irradiance, const MoonSettings& moon, const Vec3& to_moon,
                            const Vec3& direction);

}  // namespace skylit
